with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Random;

package body Sancta.Allocation.Annealers.Subsets is

   use type Ada.Real_Time.Time;
   use type Interfaces.Unsigned_64;

   Near_Count : constant := 8;
   --  Nearest tasks of other tours looked at per task of the longest tour.

   function Applies (P : Problem; Opts : Options) return Boolean is
     (Opts.Subset_Share > 0.0 and then Opts.Subset_Robots >= 2
      and then Opts.Criterion.Max_Weight > 0.0 and then Opts.Criterion.Sum_Weight = 0.0
      and then Opts.Criterion.Ave_Weight = 0.0
      and then P.Robots >= 3 and then not Has_Plan (P)
      and then (for all T in 1 .. P.Tasks =>
                  P.Alt_Count (T) = 1 and then not P.Is_Frozen (T))
      and then (for all R in 1 .. P.Robots =>
                  P.Frozen_Length (R) = 0 and then not Has_Own_Costs (P, R)));

   procedure Free is new Ada.Unchecked_Deallocation (Cost_Matrix, Cost_Matrix_Access);

   --  The tasks of Robots (their tours in Best) re-annealed as a problem of
   --  their own; Best takes the new tours when Improved. Used: the moves.
   procedure Solve_Subset
     (P        : Problem;
      Opts     : Options;
      Robots   : Count_Array;
      Rest_Max   : Cost;
      Seed     : Interfaces.Unsigned_64;
      Moves    : Long_Long_Integer;
      Time     : Duration;
      Best     : in out Assignment;
      Improved : out Boolean;
      Used     : out Long_Long_Integer)
   is
      N : constant Positive := Robots'Length;
      K : Natural := 0;
   begin
      Improved := False;
      Used := 0;
      for R of Robots loop
         K := K + Best.Length (R);
      end loop;
      if K = 0 then
         return;
      end if;
      declare
         Map  : Location_Array (1 .. K + 2 * N) := [others => 1];
         --  Sub-problem location -> location of P: the tasks', then the
         --  robots' starts and ends.
         Orig : Location_Array (1 .. K);
         --  Sub-problem task -> task of P.
         L    : Natural := K;
         A    : Assignment (N, K);
         Old_Max, Old_Sum : Cost := 0;
         Next : Natural := 0;

         function Robot_Location (Loc : Natural) return Natural is
         begin
            if Loc = Nowhere then
               return Nowhere;
            end if;
            for I in K + 1 .. L loop
               if Map (I) = Loc then
                  return I;
               end if;
            end loop;
            L := L + 1;
            Map (L) := Loc;
            return L;
         end Robot_Location;

         Starts, Ends : Location_Array (1 .. N);
      begin
         for I in 1 .. N loop
            declare
               R : constant Positive := Robots (Robots'First + I - 1);
               C : constant Cost := Tour_Cost (P, Best, R);
            begin
               Old_Max := Cost'Max (Old_Max, C);
               Old_Sum := Old_Sum + C;
               for J in 1 .. Best.Length (R) loop
                  Next := Next + 1;
                  Orig (Next) := Best.Tour (R, J);
                  Map (Next) := Location_Of (P, Best.Tour (R, J));
                  A.Tour (I, J) := Next;
               end loop;
               A.Length (I) := Best.Length (R);
            end;
         end loop;
         for I in 1 .. N loop
            Starts (I) := Robot_Location (P.Start (Robots (Robots'First + I - 1)));
            Ends (I) := Robot_Location (P.Finish (Robots (Robots'First + I - 1)));
         end loop;
         declare
            Sub : Problem (Locations => L, Tasks => K, Robots => N, Alternatives => K);
            O : Options := Opts;
            S : Progress;
            New_Max, New_Sum : Cost := 0;
         begin
            for T in 1 .. K loop
               Sub.Alt_First (T) := T;
               Sub.Alt_Location (T) := T;
            end loop;
            Sub.Next_Alt := K + 1;
            Sub.Matrix := new Cost_Matrix (0 .. L, 0 .. L);
            for X in 0 .. L loop
               for Y in 0 .. L loop
                  Sub.Matrix (X, Y) :=
                    Distance (P, (if X = 0 then Nowhere else Map (X)),
                              (if Y = 0 then Nowhere else Map (Y)));
               end loop;
            end loop;
            Sub.Symmetric := P.Symmetric;
            Sub.Scale := P.Scale;
            if P.Has_Coordinates then
               Sub.Has_Coordinates := True;
               for X in 1 .. L loop
                  Sub.Coordinates (X) := P.Coordinates (Map (X));
               end loop;
            end if;
            for I in 1 .. N loop
               declare
                  R : constant Positive := Robots (Robots'First + I - 1);
               begin
                  Sub.Start (I) := Starts (I);
                  Sub.Finish (I) := Ends (I);
                  Sub.Multiplier (I) := P.Multiplier (R);
                  for T in 1 .. K loop
                     Sub.Can_Do (I, T) := P.Can_Do (R, Orig (T));
                     Sub.All_Feasible := Sub.All_Feasible and then Sub.Can_Do (I, T);
                  end loop;
               end;
            end loop;
            Sub.Min_Tasks := P.Min_Tasks;
            O.Seed := Seed;
            O.Iterations := Moves;
            O.Time_Limit := Time;
            O.Convergence := 0;
            O.Initial := not Opts.Subset_Fresh;
            O.Report := null;
            O.Box := null;
            O.Target := 0.0;
            O.Subset_Share := 0.0;
            if Opts.Subset_Total_Weight > 0.0 then
               O.Criterion := (Max_Weight => 1.0, Sum_Weight => Opts.Subset_Total_Weight,
                               Ave_Weight => 0.0);
            end if;
            if Opts.Subset_Start_Factor > 0.0 then
               O.Start_Factor := Opts.Subset_Start_Factor;
            end if;
            Solve (Sub, O, A, S);
            Used := S.Moves;
            for I in 1 .. N loop
               declare
                  C : constant Cost := Tour_Cost (Sub, A, I);
               begin
                  New_Max := Cost'Max (New_Max, C);
                  New_Sum := New_Sum + C;
               end;
            end loop;
            if Validate (Sub, A) = ""
              and then (Cost'Max (Rest_Max, New_Max) < Cost'Max (Rest_Max, Old_Max)
                        or else (Cost'Max (Rest_Max, New_Max) = Cost'Max (Rest_Max, Old_Max)
                                 and then New_Sum < Old_Sum))
            then
               Improved := True;
               for I in 1 .. N loop
                  declare
                     R : constant Positive := Robots (Robots'First + I - 1);
                  begin
                     for J in 1 .. Best.Tasks loop
                        Best.Tour (R, J) := (if J <= A.Length (I) then Orig (A.Tour (I, J))
                                             else 0);
                     end loop;
                     Best.Length (R) := A.Length (I);
                  end;
               end loop;
            end if;
            Free (Sub.Matrix);
         end;
      end;
   end Solve_Subset;

   procedure Reoptimise
     (P     : Problem;
      Opts  : Options;
      Moves : Long_Long_Integer;
      Time  : Duration;
      Best  : in out Assignment;
      Stats : in out Progress)
   is
      G : Random.Generator := Random.Seeded (Opts.Seed * 16#9E37_79B9_7F4A_7C15# + 16#5EB5#);
      Started : constant Ada.Real_Time.Time := Budget_Clocks.Clock (Opts.Budget_Clock);
      Before : constant Duration := Stats.Elapsed;
      N : constant Positive := Positive'Min (Opts.Subset_Robots, P.Robots - 1);
      Owner : Count_Array (1 .. P.Tasks) := [others => 0];
      Used : Long_Long_Integer := 0;

      function Elapsed return Duration is
        (Ada.Real_Time.To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started));
   begin
      loop
         exit when Moves > 0 and then Used >= Moves;
         exit when Time > 0.0 and then Elapsed >= Time;
         declare
            Longest : Positive := 1;
            Longest_Cost : Cost := -1;
            Score : Count_Array (1 .. P.Robots) := [others => 0];
            Chosen : Count_Array (1 .. N);
            Taken : Boolean_Array (1 .. P.Robots) := [others => False];
            K : Natural := 0;
            Sub_Moves : Long_Long_Integer;
            Improved : Boolean;
            Sub_Used : Long_Long_Integer;
            Rest_Max : Cost := 0;
         begin
            for R in 1 .. P.Robots loop
               declare
                  C : constant Cost := Tour_Cost (P, Best, R);
               begin
                  if C > Longest_Cost then
                     Longest := R;
                     Longest_Cost := C;
                  end if;
               end;
               for J in 1 .. Best.Length (R) loop
                  Owner (Best.Tour (R, J)) := R;
               end loop;
            end loop;
            if Opts.Subset_Total_Weight > 0.0 and then Random.Below (G, 2) = 0 then
               Longest := 1 + Random.Below (G, P.Robots);
            end if;
            --  Affinity: owners of the nearest tasks of other tours.
            for J in 1 .. Best.Length (Longest) loop
               declare
                  From : constant Positive := Location_Of (P, Best.Tour (Longest, J));
                  Near : Count_Array (1 .. Near_Count) := [others => 0];
                  Near_D : Cost_Array (1 .. Near_Count) := [others => Cost'Last];
               begin
                  for U in 1 .. P.Tasks loop
                     if Owner (U) /= Longest and then Owner (U) /= 0 then
                        declare
                           D : constant Cost := Distance (P, From, Location_Of (P, U));
                           I : Natural := Near_Count;
                        begin
                           if D < Near_D (Near_Count) then
                              while I > 1 and then Near_D (I - 1) > D loop
                                 Near_D (I) := Near_D (I - 1);
                                 Near (I) := Near (I - 1);
                                 I := I - 1;
                              end loop;
                              Near_D (I) := D;
                              Near (I) := U;
                           end if;
                        end;
                     end if;
                  end loop;
                  for U of Near loop
                     if U /= 0 then
                        Score (Owner (U)) := Score (Owner (U)) + 1;
                     end if;
                  end loop;
               end;
            end loop;
            Chosen (1) := Longest;
            Taken (Longest) := True;
            for I in 2 .. N loop
               declare
                  Total : Natural := 0;
                  X : Natural;
                  Pick : Natural := 0;
               begin
                  for R in 1 .. P.Robots loop
                     if not Taken (R) then
                        Total := Total + Score (R);
                     end if;
                  end loop;
                  if Total = 0 then
                     X := Random.Below (G, P.Robots - (I - 1));
                     for R in 1 .. P.Robots loop
                        if not Taken (R) then
                           if X = 0 then
                              Pick := R;
                              exit;
                           end if;
                           X := X - 1;
                        end if;
                     end loop;
                  else
                     X := Random.Below (G, Total);
                     for R in 1 .. P.Robots loop
                        if not Taken (R) then
                           if X < Score (R) then
                              Pick := R;
                              exit;
                           end if;
                           X := X - Score (R);
                        end if;
                     end loop;
                  end if;
                  Chosen (I) := Pick;
                  Taken (Pick) := True;
               end;
            end loop;
            for R of Chosen loop
               K := K + Best.Length (R);
            end loop;
            for R in 1 .. P.Robots loop
               if not Taken (R) then
                  Rest_Max := Cost'Max (Rest_Max, Tour_Cost (P, Best, R));
               end if;
            end loop;
            Sub_Moves := Long_Long_Integer'Max
              (1, Long_Long_Integer (Opts.Subset_Moves * Long_Float (K)));
            if Moves > 0 then
               Sub_Moves := Long_Long_Integer'Min (Sub_Moves, Moves - Used);
            end if;
            exit when Time > 0.0 and then Time - Elapsed < 0.001;
            declare
               Seed : Interfaces.Unsigned_64;
            begin
               Random.Next (G, Seed);
               Solve_Subset
                 (P, Opts, Chosen, Rest_Max, Seed, Sub_Moves,
                  (if Time > 0.0 then Time - Elapsed else 0.0),
                  Best, Improved, Sub_Used);
            end;
            Used := Used + Long_Long_Integer'Max (1, Sub_Used);
            if Improved then
               Stats.Best := Evaluate (P, Best, Opts.Criterion).Value;
               Stats.Current := Stats.Best;
               Stats.Time_To_Best := Before + Elapsed;
               if Opts.Box /= null then
                  Opts.Box.Post (Best, Stats.Best);
               end if;
            end if;
         end;
      end loop;
      Stats.Moves := Stats.Moves + Used;
      Stats.Elapsed := Before + Elapsed;
   end Reoptimise;

end Sancta.Allocation.Annealers.Subsets;
