with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Giant_Tours;
with Sancta.Allocation.Random;

package body Sancta.Allocation.Annealers.Memetic is

   use type Ada.Real_Time.Time;
   use type Interfaces.Unsigned_64;

   function Applies (P : Problem; Opts : Options) return Boolean is
     (Opts.Population >= 2 and then not Opts.Initial
      and then (Opts.Iterations > 0 or else Opts.Time_Limit > 0.0)
      and then Opts.Criterion.Max_Weight > 0.0 and then Opts.Criterion.Sum_Weight = 0.0
      and then Opts.Criterion.Ave_Weight = 0.0
      and then P.Robots >= 2 and then Giant_Tours.Applies (P));

   type Assignment_Access is access Assignment;
   procedure Free is new Ada.Unchecked_Deallocation (Assignment, Assignment_Access);

   type Member is record
      Max, Sum : Cost := Cost'Last;
   end record;

   function "<" (A, B : Member) return Boolean is
     (A.Max < B.Max or else (A.Max = B.Max and then A.Sum < B.Sum));

   procedure Search
     (P     : Problem;
      Opts  : Options;
      Best  : in out Assignment;
      Stats : out Progress)
   is
      N : constant Positive := Opts.Population;
      Started : constant Ada.Real_Time.Time := Budget_Clocks.Clock (Opts.Budget_Clock);
      G : Random.Generator := Random.Seeded (Opts.Seed * 16#9E37_79B9_7F4A_7C15# + 16#3A7#);
      Pop : array (1 .. N) of Assignment_Access :=
        [others => new Assignment (P.Robots, P.Tasks)];
      --  On the heap: N plans of Robots x Tasks may not fit on the stack.
      Score : array (1 .. N) of Member;
      Count : Natural := 0;
      Top : Positive := 1;
      Used : Long_Long_Integer := 0;
      Init_Moves : constant Long_Long_Integer :=
        Long_Long_Integer (Long_Float (Opts.Iterations) * Opts.Population_Share);
      Init_Time : constant Duration :=
        Duration (Long_Float (Opts.Time_Limit) * Opts.Population_Share);

      function Elapsed return Duration is
        (Ada.Real_Time.To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started));

      function Score_Of (A : Assignment) return Member is
         E : constant Evaluation := Evaluate (P, A, Opts.Criterion);
      begin
         return (E.Max, E.Sum);
      end Score_Of;

      function Next_Seed return Interfaces.Unsigned_64 is
         S : Interfaces.Unsigned_64;
      begin
         Random.Next (G, S);
         return S;
      end Next_Seed;

      --  Solve under O from A, counting its moves; Stats.Current becomes A's
      --  value (the reports give each member's and child's value there).
      procedure Run (O : Options; A : in out Assignment) is
         S : Progress;
      begin
         Solve (P, O, A, S);
         Used := Used + Long_Long_Integer'Max (1, S.Moves);
         Stats.Accepted := Stats.Accepted + S.Accepted;
         Stats.Current := Evaluate (P, A, Opts.Criterion).Value;
      end Run;

      --  Member K is the new best when Better.
      procedure Note_Best (K : Positive; Better : Boolean) is
      begin
         if Better then
            Top := K;
            Stats.Best := Evaluate (P, Pop (K).all, Opts.Criterion).Value;
            Stats.Time_To_Best := Elapsed;
            if Opts.Box /= null then
               Opts.Box.Post (Pop (K).all, Stats.Best);
            end if;
         end if;
      end Note_Best;

      procedure Report is
      begin
         if Opts.Report /= null then
            Stats.Moves := Used;
            Stats.Elapsed := Elapsed;
            Stats.Moves_Per_Second :=
              (if Stats.Elapsed > 0.0 then Long_Float (Used) / Long_Float (Stats.Elapsed)
               else 0.0);
            Opts.Report (Stats);
         end if;
      end Report;

      Base : Options := Opts;
   begin
      if Opts.Population_Share not in 0.0 .. 1.0 then
         raise Constraint_Error with "annealer: Population_Share"
           & Opts.Population_Share'Image & " is not in 0 .. 1";
      end if;
      Stats := (others => <>);
      Base.Population := 0;
      Base.Report := null;
      Base.Box := null;
      Base.Target := 0.0;
      --  The first members: independent anneals sharing Init_Moves / Init_Time.
      for K in 1 .. N loop
         declare
            O : Options := Base;
         begin
            O.Seed := Next_Seed;
            if Opts.Iterations > 0 then
               O.Iterations := Long_Long_Integer'Max (1, (Init_Moves - Used) / Long_Long_Integer
                                                         (N - K + 1));
            end if;
            if Opts.Time_Limit > 0.0 then
               O.Time_Limit := Duration'Max
                 (0.001, (Init_Time - Elapsed) / (N - K + 1));
            end if;
            Run (O, Pop (K).all);
            Score (K) := Score_Of (Pop (K).all);
            Note_Best (K, K = 1 or else Score (K) < Score (Top));
            Count := K;
            Report;
         end;
         exit when Opts.Target > 0.0 and then Stats.Best <= Opts.Target;
      end loop;
      --  Children until the budget is spent.
      loop
         exit when Count < N;
         exit when Opts.Target > 0.0 and then Stats.Best <= Opts.Target;
         exit when Opts.Iterations > 0 and then Used >= Opts.Iterations;
         exit when Opts.Time_Limit > 0.0 and then Opts.Time_Limit - Elapsed < 0.001;
         declare
            function Tournament return Positive is
               X : constant Positive := 1 + Random.Below (G, N);
               Y : constant Positive := 1 + Random.Below (G, N);
            begin
               return (if Score (Y) < Score (X) then Y else X);
            end Tournament;
            First : constant Positive := Tournament;
            Second : Positive := Tournament;
            A : constant Count_Array := Giant_Tours.Giant_Tour (Pop (First).all);
            B : Count_Array (1 .. P.Tasks);
            Order : Count_Array (1 .. P.Tasks) := [others => 0];
            Taken : Boolean_Array (1 .. P.Tasks) := [others => False];
            Child : Assignment (P.Robots, P.Tasks);
            Max, Sum : Cost;
            Lo : Positive := 1 + Random.Below (G, P.Tasks);
            Hi : Positive := 1 + Random.Below (G, P.Tasks);
            Worst : Positive := 1;
            O : Options := Base;
            C : Member;
         begin
            if Second = First then
               Second := (if First = N then 1 else First + 1);
            end if;
            B := Giant_Tours.Giant_Tour (Pop (Second).all);
            if Lo > Hi then
               declare
                  X : constant Positive := Lo;
               begin
                  Lo := Hi;
                  Hi := X;
               end;
            end if;
            for I in Lo .. Hi loop
               Order (I) := A (I);
               Taken (A (I)) := True;
            end loop;
            declare
               To : Natural := Hi;
            begin
               for I in 1 .. P.Tasks loop
                  declare
                     T : constant Positive := B (1 + (Hi + I - 1) mod P.Tasks);
                  begin
                     if not Taken (T) then
                        To := (if To = P.Tasks then 1 else To + 1);
                        Order (To) := T;
                     end if;
                  end;
               end loop;
            end;
            Giant_Tours.Split (P, Order, Child, Max, Sum);
            O.Seed := Next_Seed;
            O.Initial := True;
            O.Convergence := 0;
            if Opts.Child_Start_Factor > 0.0 then
               O.Start_Factor := Opts.Child_Start_Factor;
            end if;
            O.Iterations := Long_Long_Integer'Max
              (1, Long_Long_Integer (Opts.Child_Moves * Long_Float (P.Tasks)));
            if Opts.Iterations > 0 then
               O.Iterations := Long_Long_Integer'Min (O.Iterations, Opts.Iterations - Used);
            end if;
            if Opts.Time_Limit > 0.0 then
               O.Time_Limit := Duration'Max (0.001, Opts.Time_Limit - Elapsed);
            end if;
            Run (O, Child);
            C := Score_Of (Child);
            for K in 1 .. N loop
               if Score (Worst) < Score (K) then
                  Worst := K;
               end if;
            end loop;
            if C < Score (Worst)
              and then (for all K in 1 .. N => Score (K) /= C)
            then
               declare
                  Better : constant Boolean := C < Score (Top);
               begin
                  Pop (Worst).all := Child;
                  Score (Worst) := C;
                  Note_Best (Worst, Better);
               end;
            end if;
            Report;
         end;
      end loop;
      Best := Pop (Top).all;
      for X of Pop loop
         Free (X);
      end loop;
      Stats.Current := Stats.Best;
      Stats.Moves := Used;
      Stats.Elapsed := Elapsed;
      Stats.Moves_Per_Second :=
        (if Stats.Elapsed > 0.0 then Long_Float (Used) / Long_Float (Stats.Elapsed) else 0.0);
   end Search;

end Sancta.Allocation.Annealers.Memetic;
