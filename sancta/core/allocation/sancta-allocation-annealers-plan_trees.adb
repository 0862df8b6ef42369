with Sancta.Allocation.Random;

package body Sancta.Allocation.Annealers.Plan_Trees is

   --  Visit (T, X) for every task T and every OR ordinal X above it.
   generic
      with procedure Visit (T, X : Positive);
   procedure For_Each_Or_Above (P : Problem);

   procedure For_Each_Or_Above (P : Problem) is
   begin
      for T in 1 .. P.Tasks loop
         declare
            X : Natural := P.Task_Or (T);
         begin
            while X /= 0 loop
               Visit (T, X);
               X := Or_Parent (P, X);
            end loop;
         end;
      end loop;
   end For_Each_Or_Above;

   function Under_Size (P : Problem) return Positive is
      N : Natural := 0;

      procedure Count (T, X : Positive) is
         pragma Unreferenced (T, X);
      begin
         N := N + 1;
      end Count;

      procedure Count_All is new For_Each_Or_Above (Count);
   begin
      Count_All (P);
      return Positive'Max (1, N);
   end Under_Size;

   procedure Set_Under (P : Problem; D : in out Subtree_Switch) is
      Count : Count_Array (1 .. D.Tasks + 1) := [others => 0];

      procedure Count_Under (T, X : Positive) is
         pragma Unreferenced (T);
      begin
         Count (X) := Count (X) + 1;
      end Count_Under;

      procedure Place_Under (T, X : Positive) is
      begin
         D.Under (D.Under_First (X) + Count (X)) := T;
         Count (X) := Count (X) + 1;
      end Place_Under;

      procedure Count_All is new For_Each_Or_Above (Count_Under);
      procedure Place_All is new For_Each_Or_Above (Place_Under);
   begin
      Count_All (P);
      D.Under_First (1) := 1;
      for O in 1 .. D.Tasks loop
         D.Under_First (O + 1) := D.Under_First (O) + Count (O);
      end loop;
      Count := [others => 0];
      Place_All (P);
   end Set_Under;

   function New_Switch (P : Problem) return Switch_Access is
      D : constant Switch_Access :=
        new Subtree_Switch (P.Robots, P.Tasks + 1, P.Tasks, Under_Size (P));
   begin
      Set_Under (P, D.all);
      return D;
   end New_Switch;

   function Pending_Location (P : Problem; D : Subtree_Switch; R : Positive; Q : Natural)
     return Natural
   is (if Q = 0 then P.Start (R) elsif Q > D.Length (R) then P.Finish (R)
       else D.Location_At (R, Q));

   procedure Pending_Costs (P : Problem; S : State; D : in out Subtree_Switch; R : Positive) is
   begin
      Cost_From_Scratch (P, R, D.Task_At, D.Length (R), S.Choice,
                         D.Robot_Cost (R), D.Robot_Completion (R));
   end Pending_Costs;

   --  The OR ordinal to switch (a few tries), or 0.
   function Pick_Or_Node
     (P : Problem; S : State; G : in out Generator; Locked : Boolean_Array) return Natural is
   begin
      for Try in 1 .. 4 loop
         declare
            X : constant Positive := 1 + Random.Below (G, Or_Count (P));
         begin
            if not Locked (X) and then Alternatives (P, X) >= 2
              and then Or_Active (P, S.Selection, X)
            then
               return X;
            end if;
         end;
      end loop;
      return 0;
   end Pick_Or_Node;

   --  Inserts task T into the pending tours: at the cheapest place (pure
   --  makespan: the place giving the least robot cost, ties: least added
   --  cost; else the least added cost) or at a random place. Ok False when
   --  no robot can take it.
   procedure Insert_Pending
     (P : Problem; S : State; G : in out Generator; W : Weights; Cheapest : Boolean;
      D : in out Subtree_Switch; T : Positive; Ok : out Boolean)
   is
      L : constant Natural := Location_Of (P, T, S.Choice (T));
      Best_R : Natural := 0;
      Best_Q : Natural := 0;
      Best_D : Cost := Cost'Last;
      Best_K : Cost := Cost'Last;
      Makespan : constant Boolean :=
        W.C.Max_Weight > 0.0 and then W.C.Sum_Weight = 0.0 and then W.C.Ave_Weight = 0.0;
   begin
      if Cheapest then
         for R in 1 .. S.Robots loop
            if P.Can_Do (R, T) then
               for Q in P.Frozen_Length (R) .. D.Length (R) loop
                  declare
                     A  : constant Natural := Pending_Location (P, D, R, Q);
                     B  : constant Natural := Pending_Location (P, D, R, Q + 1);
                     DC : constant Cost := Cost (P.Multiplier (R))
                       * (Robot_Distance (P, R, A, L) + Robot_Distance (P, R, L, B)
                          - Robot_Distance (P, R, A, B));
                     Key : constant Cost := (if Makespan then D.Robot_Cost (R) + DC else DC);
                  begin
                     if Key < Best_K or else (Key = Best_K and then DC < Best_D) then
                        Best_K := Key;
                        Best_D := DC;
                        Best_R := R;
                        Best_Q := Q;
                     end if;
                  end;
               end loop;
            end if;
         end loop;
      else
         for Try in 1 .. 2 * S.Robots loop
            declare
               R : constant Positive := 1 + Random.Below (G, S.Robots);
            begin
               if P.Can_Do (R, T) then
                  Best_R := R;
                  Best_Q := P.Frozen_Length (R)
                    + Random.Below (G, D.Length (R) - P.Frozen_Length (R) + 1);
                  exit;
               end if;
            end;
         end loop;
      end if;
      Ok := Best_R /= 0;
      if not Ok then
         return;
      end if;
      declare
         A : constant Natural := Pending_Location (P, D, Best_R, Best_Q);
         B : constant Natural := Pending_Location (P, D, Best_R, Best_Q + 1);
      begin
         D.Robot_Cost (Best_R) := D.Robot_Cost (Best_R) + Cost (P.Multiplier (Best_R))
           * (Robot_Distance (P, Best_R, A, L) + Robot_Distance (P, Best_R, L, B)
              - Robot_Distance (P, Best_R, A, B));
      end;
      for I in reverse Best_Q + 1 .. D.Length (Best_R) loop
         D.Task_At (Best_R, I + 1) := D.Task_At (Best_R, I);
         D.Location_At (Best_R, I + 1) := D.Location_At (Best_R, I);
      end loop;
      D.Task_At (Best_R, Best_Q + 1) := T;
      D.Location_At (Best_R, Best_Q + 1) := L;
      D.Length (Best_R) := D.Length (Best_R) + 1;
      D.Changed (Best_R) := True;
   end Insert_Pending;

   procedure Propose_Switch
     (P : Problem; S : State; G : in out Generator; W : Weights; Locked : Boolean_Array;
      D : in out Subtree_Switch; Mv : in out Move; Ok : out Boolean)
   is
      O  : constant Natural := Pick_Or_Node (P, S, G, Locked);
      Coming : Natural := 0;
      Active_After : Natural := S.Active_Tasks;
   begin
      Ok := False;
      Mv := No_Move;
      if O = 0 then
         return;
      end if;
      D.Selection := S.Selection;
      D.Selection (O) := 1 + Random.Below (G, Alternatives (P, O) - 1);
      if D.Selection (O) >= S.Selection (O) then
         D.Selection (O) := D.Selection (O) + 1;
      end if;
      --  Which tasks leave and which come (only tasks below O can).
      for K in D.Under_First (O) .. D.Under_First (O + 1) - 1 loop
         declare
            T : constant Positive := D.Under (K);
            After : constant Boolean := Is_Active (P, D.Selection, T);
         begin
            D.Gone (T) := S.Active (T) and then not After;
            if After and then not S.Active (T) then
               Coming := Coming + 1;
               D.Added (Coming) := T;
               Active_After := Active_After + 1;
            elsif D.Gone (T) then
               Active_After := Active_After - 1;
            end if;
         end;
      end loop;
      --  The current tours without the leaving tasks, and their costs.
      for R in 1 .. S.Robots loop
         D.Length (R) := 0;
         D.Changed (R) := False;
         for I in 1 .. S.Length (R) loop
            if D.Gone (S.Task_At (R, I)) then
               D.Changed (R) := True;
            else
               D.Length (R) := D.Length (R) + 1;
               D.Task_At (R, D.Length (R)) := S.Task_At (R, I);
               D.Location_At (R, D.Length (R)) := S.Location_At (R, I);
            end if;
         end loop;
         if D.Changed (R) then
            Pending_Costs (P, S, D, R);
         else
            D.Robot_Cost (R) := S.Robot_Cost (R);
         end if;
      end loop;
      for K in D.Under_First (O) .. D.Under_First (O + 1) - 1 loop
         D.Gone (D.Under (K)) := False;
      end loop;
      --  Insert the coming tasks in random order.
      Shuffle (G, D.Added, Coming);
      declare
         Cheapest : constant Boolean := Random.Below (G, 4) /= 0;
         Inserted : Boolean;
      begin
         for K in 1 .. Coming loop
            Insert_Pending (P, S, G, W, Cheapest, D, D.Added (K), Inserted);
            if not Inserted then
               return;
            end if;
         end loop;
      end;
      --  Exact costs of the touched robots.
      declare
         Sum  : Cost := S.Total_Cost;
         Completion : Cost := S.Total_Completion;
         Max  : Cost := 0;
         Square : Long_Float := S.Total_Square;
      begin
         for R in 1 .. S.Robots loop
            if D.Changed (R) then
               if D.Length (R) < P.Min_Tasks and then D.Length (R) < S.Length (R) then
                  return;
               end if;
               Pending_Costs (P, S, D, R);
               Sum := Sum - S.Robot_Cost (R) + D.Robot_Cost (R);
               Completion := Completion - S.Robot_Completion (R) + D.Robot_Completion (R);
               Max := Cost'Max (Max, D.Robot_Cost (R));
               Square := Square - Square_Of (S, S.Robot_Cost (R))
                 + Square_Of (S, D.Robot_Cost (R));
            else
               Max := Cost'Max (Max, S.Robot_Cost (R));
            end if;
         end loop;
         Mv.Or_Node := O;
         D.Or_Node := O;
         D.New_Active := Active_After;
         Mv.New_Sum := Sum;
         Mv.New_Completion := Completion;
         Mv.New_Max := Max;
         Mv.New_Active := Active_After;
         Mv.New_Square := Square;
         Mv.Value := Objective (W, Max, Sum, Completion, Active_After, Square);
         Ok := True;
      end;
   end Propose_Switch;

   procedure Apply_Switch (P : Problem; S : in out State; D : Subtree_Switch) is
   begin
      S.Selection := D.Selection;
      for K in D.Under_First (D.Or_Node) .. D.Under_First (D.Or_Node + 1) - 1 loop
         declare
            T : constant Positive := D.Under (K);
         begin
            S.Active (T) := Is_Active (P, S.Selection, T);
            if not S.Active (T) then
               S.Owner (T) := 0;
               S.Position (T) := 0;
            end if;
         end;
      end loop;
      S.Active_Tasks := D.New_Active;
      for R in 1 .. S.Robots loop
         if D.Changed (R) then
            S.Length (R) := D.Length (R);
            for I in 1 .. D.Length (R) loop
               S.Task_At (R, I) := D.Task_At (R, I);
            end loop;
            Rebuild (P, S, R, 1);
         end if;
      end loop;
   end Apply_Switch;

end Sancta.Allocation.Annealers.Plan_Trees;
