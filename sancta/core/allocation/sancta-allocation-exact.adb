with Ada.Unchecked_Deallocation;

package body Sancta.Allocation.Exact is

   type Node is record
      Task_Id : Positive;
      Choice  : Positive;
      Loc     : Natural;
      Bit     : Natural;
   end record;
   type Node_Array is array (Positive range <>) of Node;

   type Table is array (Natural range <>, Positive range <>) of Cost;
   type Table_Access is access Table;
   type Link is array (Natural range <>, Positive range <>) of Natural;
   type Link_Access is access Link;
   procedure Free is new Ada.Unchecked_Deallocation (Table, Table_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Link, Link_Access);

   type Set_Costs is array (Natural range <>) of Cost;
   type Set_Access is access Set_Costs;
   procedure Free is new Ada.Unchecked_Deallocation (Set_Costs, Set_Access);

   Unreachable : constant Cost := Cost'Last / 4;

   function Pop_Count (X : Natural) return Natural is
      N : Natural := 0;
      Y : Natural := X;
   begin
      while Y /= 0 loop
         N := N + Y mod 2;
         Y := Y / 2;
      end loop;
      return N;
   end Pop_Count;

   function Has (Set, Bit : Natural) return Boolean is ((Set / 2 ** Bit) mod 2 = 1);

   --  The optimum for the active tasks of one plan selection.
   function Solve_Active
     (P : Problem; C : Criterion; Sel : Location_Array; Feasible : out Boolean)
      return Assignment
   is
      Free_Count : Natural := 0;
      Bit_Of : array (1 .. P.Tasks) of Integer := [others => -1];
      V : Natural := 0;
      Average : constant Boolean := C.Ave_Weight /= 0.0;
   begin
      for T in 1 .. P.Tasks loop
         if not P.Is_Frozen (T) and then Is_Active (P, Sel, T) then
            if Free_Count = Max_Tasks then
               raise Constraint_Error with "exact solver: more than" & Max_Tasks'Image
                 & " free tasks";
            end if;
            Bit_Of (T) := Free_Count;
            Free_Count := Free_Count + 1;
            V := V + P.Alt_Count (T);
         end if;
      end loop;
      declare
         N     : constant Natural := Free_Count;
         Full  : constant Natural := 2 ** N - 1;
         Nodes : Node_Array (1 .. Natural'Max (V, 1));
         --  Per robot: best cost of each subset, and the DP tables to
         --  rebuild its order.
         Robot_Cost : array (1 .. P.Robots) of Set_Access;
         Robot_DP   : array (1 .. P.Robots) of Table_Access;
         Robot_Link : array (1 .. P.Robots) of Link_Access;
         Robot_End  : array (1 .. P.Robots) of Link_Access;  --  best first/last node per set
         K : Natural := 0;
         Result : Assignment := Empty (P);
      begin
         Result.Branch := Sel;
         for T in 1 .. P.Tasks loop
            if Bit_Of (T) >= 0 then
               for Ch in 1 .. P.Alt_Count (T) loop
                  K := K + 1;
                  Nodes (K) := (T, Ch, Location_Of (P, T, Ch), Bit_Of (T));
               end loop;
            end if;
         end loop;

         for R in 1 .. P.Robots loop
            declare
               M  : constant Cost := Cost (P.Multiplier (R));
               S0 : Natural := P.Start (R);
               F0, FC : Cost := 0;
               FN : constant Natural := P.Frozen_Length (R);
               Bad0 : Natural := 0;
               DP : constant Table_Access := new Table (0 .. Full, 1 .. Nodes'Last);
               LK : constant Link_Access := new Link (0 .. Full, 1 .. Nodes'Last);
               EN : constant Link_Access := new Link (0 .. Full, 1 .. 1);
               SC : constant Set_Access := new Set_Costs (0 .. Full);
            begin
               for I in 1 .. FN loop
                  declare
                     T : constant Positive := P.Frozen (R, I);
                     L : constant Natural := Location_Of (P, T);
                  begin
                     F0 := F0 + Robot_Distance (P, R, S0, L);
                     FC := FC + F0;
                     S0 := L;
                     if not P.Can_Do (R, T) then
                        Bad0 := Bad0 + 1;
                     end if;
                  end;
               end loop;
               DP.all := [others => [others => Unreachable]];
               LK.all := [others => [others => 0]];
               --  Without the mean completion time (forward): DP (S, v) = the
               --  shortest path from S0 through S ending at v, LK its
               --  predecessor. With it (backward): DP (S, v) = the least
               --  completion sum of the tasks of S other than v, starting at
               --  v (v in S), LK its successor.
               for X in 1 .. Nodes'Last loop
                  if P.Can_Do (R, Nodes (X).Task_Id) then
                     DP (2 ** Nodes (X).Bit, X) :=
                       (if Average then 0 else Robot_Distance (P, R, S0, Nodes (X).Loc));
                  end if;
               end loop;
               for S in 1 .. Full loop
                  for X in 1 .. Nodes'Last loop
                     if Has (S, Nodes (X).Bit) and then DP (S, X) < Unreachable then
                        for Y in 1 .. Nodes'Last loop
                           if not Has (S, Nodes (Y).Bit) and then P.Can_Do (R, Nodes (Y).Task_Id)
                           then
                              declare
                                 S2 : constant Natural := S + 2 ** Nodes (Y).Bit;
                                 D  : constant Cost :=
                                   (if Average  --  a new first node Y before X
                                    then DP (S, X) + Cost (Pop_Count (S))
                                      * Robot_Distance (P, R, Nodes (Y).Loc, Nodes (X).Loc)
                                    else DP (S, X)
                                      + Robot_Distance (P, R, Nodes (X).Loc, Nodes (Y).Loc));
                              begin
                                 if D < DP (S2, Y) then
                                    DP (S2, Y) := D;
                                    LK (S2, Y) := X;
                                 end if;
                              end;
                           end if;
                        end loop;
                     end if;
                  end loop;
               end loop;
               --  SC (S): the robot's best cost for the set S, EN its
               --  last (forward) or first (backward) node (0: none).
               SC (0) :=
                 (if Average then M * FC else M * (F0 + Robot_Distance (P, R, S0, P.Finish (R))));
               EN (0, 1) := 0;
               for S in 1 .. Full loop
                  SC (S) := Unreachable;
                  EN (S, 1) := 0;
                  for X in 1 .. Nodes'Last loop
                     if Has (S, Nodes (X).Bit) and then DP (S, X) < Unreachable then
                        declare
                           Cnt : constant Cost := Cost (Pop_Count (S));
                           D : constant Cost :=
                             (if Average
                              then M * (FC + Cnt * F0
                                + Cnt * Robot_Distance (P, R, S0, Nodes (X).Loc) + DP (S, X))
                              else M * (F0 + DP (S, X)
                                + Robot_Distance (P, R, Nodes (X).Loc, P.Finish (R))));
                        begin
                           if D < SC (S) then
                              SC (S) := D;
                              EN (S, 1) := X;
                           end if;
                        end;
                     end if;
                  end loop;
               end loop;
               for S in 0 .. Full loop
                  if FN + Pop_Count (S) < P.Min_Tasks or else Bad0 > 0 then
                     SC (S) := Unreachable;
                  end if;
               end loop;
               Robot_Cost (R) := SC;
               Robot_DP (R) := DP;
               Robot_Link (R) := LK;
               Robot_End (R) := EN;
            end;
         end loop;

         --  Split the tasks among robots: G (K, S) over robots 1 .. K.
         declare
            G  : array (0 .. P.Robots) of Set_Access;
            GS : array (1 .. P.Robots) of Link_Access;   --  the subset given to robot K
            Cur : Natural := Full;
         begin
            G (0) := new Set_Costs'(0 .. Full => Unreachable);
            G (0) (0) := 0;
            for R in 1 .. P.Robots loop
               G (R) := new Set_Costs'(0 .. Full => Unreachable);
               GS (R) := new Link (0 .. Full, 1 .. 1);
               for S in 0 .. Full loop
                  --  Enumerate the subsets T of S given to robot R.
                  declare
                     T : Natural := S;
                  begin
                     loop
                        declare
                           A : constant Cost := G (R - 1) (S - T);
                           B : constant Cost := Robot_Cost (R) (T);
                        begin
                           if A < Unreachable and then B < Unreachable then
                              declare
                                 X : constant Cost :=
                                   (if C.Max_Weight /= 0.0 then Cost'Max (A, B) else A + B);
                              begin
                                 if X < G (R) (S) then
                                    G (R) (S) := X;
                                    GS (R) (S, 1) := T;
                                 end if;
                              end;
                           end if;
                        end;
                        exit when T = 0;
                        T := (T - 1) mod 2 ** N;
                        --  next smaller subset of S: (T - 1) and S
                        declare
                           Y : Natural := 0;
                        begin
                           for B in 0 .. N - 1 loop
                              if Has (T, B) and then Has (S, B) then
                                 Y := Y + 2 ** B;
                              end if;
                           end loop;
                           T := Y;
                        end;
                     end loop;
                  end;
               end loop;
            end loop;
            Feasible := G (P.Robots) (Full) < Unreachable;
            if not Feasible then
               Cur := 0;  --  nothing to rebuild
            end if;
            for R in reverse 1 .. P.Robots loop
               exit when not Feasible;
               declare
                  T : constant Natural := GS (R) (Cur, 1);
                  Order : array (1 .. N) of Positive;
                  Cnt : Natural := 0;
                  X : Natural := Robot_End (R) (T, 1);
                  S : Natural := T;
               begin
                  while S /= 0 and then X /= 0 loop
                     Cnt := Cnt + 1;
                     Order (Cnt) := X;
                     declare
                        Next : constant Natural := Robot_Link (R) (S, X);
                     begin
                        S := S - 2 ** Nodes (X).Bit;
                        X := Next;
                     end;
                  end loop;
                  --  Forward tables give the order backwards, backward ones forwards.
                  for I in 1 .. Cnt loop
                     declare
                        Nd : constant Node :=
                          Nodes (if Average then Order (I) else Order (Cnt - I + 1));
                     begin
                        Append (Result, R, Nd.Task_Id);
                        Result.Choice (Nd.Task_Id) := Nd.Choice;
                     end;
                  end loop;
                  Cur := Cur - T;
               end;
            end loop;
            for R in 0 .. P.Robots loop
               Free (G (R));
            end loop;
            for R in 1 .. P.Robots loop
               Free (GS (R));
            end loop;
         end;
         for R in 1 .. P.Robots loop
            Free (Robot_Cost (R));
            Free (Robot_DP (R));
            Free (Robot_Link (R));
            Free (Robot_End (R));
         end loop;
         return Result;
      end;
   end Solve_Active;

   function Solve (P : Problem; C : Criterion) return Assignment is
      Sel    : Location_Array := Default_Selection (P);
      NO     : constant Natural := Or_Count (P);
      Locked : array (1 .. NO) of Boolean;
      Best   : Assignment := Empty (P);
      Best_V : Long_Float := Long_Float'Last;
      Found  : Boolean := False;
      Combos : Natural := 0;
   begin
      if NO = 0 then
         declare
            A : constant Assignment := Solve_Active (P, C, Sel, Found);
         begin
            if not Found then
               raise Constraint_Error with "exact solver: no feasible allocation";
            end if;
            return A;
         end;
      end if;
      for O in 1 .. NO loop
         Locked (O) := Is_Locked (P, O);
      end loop;
      --  Every selection (odometer over the unlocked OR nodes); selections
      --  differing only at unreached OR nodes are the same, only the one
      --  with 1 there is solved.
      loop
         if (for all O in 1 .. NO => Sel (O) = 1 or else Or_Active (P, Sel, O)) then
            Combos := Combos + 1;
            if Combos > Max_Selections then
               raise Constraint_Error with "exact solver: more than" & Max_Selections'Image
                 & " plan selections";
            end if;
            declare
               Feasible : Boolean;
               A : constant Assignment := Solve_Active (P, C, Sel, Feasible);
               V : constant Long_Float :=
                 (if Feasible then Evaluate (P, A, C).Value else Long_Float'Last);
            begin
               if Feasible and then V < Best_V then
                  Best_V := V;
                  Best := A;
                  Found := True;
               end if;
            end;
         end if;
         declare
            O : Natural := 1;
         begin
            while O <= NO and then (Locked (O) or else Sel (O) = Alternatives (P, O)) loop
               if not Locked (O) then
                  Sel (O) := 1;
               end if;
               O := O + 1;
            end loop;
            exit when O > NO;
            Sel (O) := Sel (O) + 1;
         end;
      end loop;
      if not Found then
         raise Constraint_Error with "exact solver: no feasible allocation";
      end if;
      return Best;
   end Solve;

end Sancta.Allocation.Exact;
