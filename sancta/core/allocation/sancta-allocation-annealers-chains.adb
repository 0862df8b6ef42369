with Sancta.Allocation.Annealers.Neighbourhoods;
use Sancta.Allocation.Annealers.Neighbourhoods;

package body Sancta.Allocation.Annealers.Chains is

   Breadth : constant array (1 .. Max_Depth) of Positive := [3, 2, others => 1];
   --  Steps tried at each level of the depth-first search, best first (a
   --  wider one, 6 / 3 / 2, found no better chain on 10 test instances).

   type Candidate is record
      Mv     : Move;
      Closes : Boolean := False;
      --  The receiving tour stays below the makespan: the chain can end.
      Rank   : Long_Float := 0.0;
      --  Closing steps by the objective after them, the others by the
      --  receiving tour's new cost.
   end record;
   --  Closing steps first, then by Rank.

   type Candidate_List is array (1 .. 3) of Candidate;

   function Before (X, Y : Candidate) return Boolean is
     ((X.Closes and then not Y.Closes) or else (X.Closes = Y.Closes and then X.Rank < Y.Rank));

   --  Tour R as it is, kept in row K of the undo record.
   procedure Save_Tour (S : State; Space : in out Workspace; K, R : Positive) is
   begin
      Space.Saved_Robot (K) := R;
      Space.Saved_Length (K) := S.Length (R);
      for I in 1 .. S.Length (R) loop
         Space.Saved_Tasks (K, I) := S.Task_At (R, I);
      end loop;
   end Save_Tour;

   --  The last applied step undone: its two tours as they were.
   procedure Undo_Step (P : Problem; S : in out State; Space : in out Workspace) is
   begin
      for K in 2 * Space.Applied - 1 .. 2 * Space.Applied loop
         declare
            R : constant Positive := Space.Saved_Robot (K);
         begin
            S.Length (R) := Space.Saved_Length (K);
            for I in 1 .. S.Length (R) loop
               S.Task_At (R, I) := Space.Saved_Tasks (K, I);
            end loop;
         end;
      end loop;
      for K in 2 * Space.Applied - 1 .. 2 * Space.Applied loop
         Rebuild (P, S, Space.Saved_Robot (K), 1);
      end loop;
      Space.Applied := Space.Applied - 1;
   end Undo_Step;

   function New_Workspace (P : Problem) return Workspace_Access is
     (new Workspace (P.Robots, P.Tasks + 1, 2 * Max_Depth * Max_Rounds));

   procedure Ejection_Chain
     (P           : Problem;
      S           : in out State;
      W           : Weights;
      Space       : in out Workspace;
      Check       : Boolean;
      Improved    : out Boolean;
      Evaluations : in out Long_Long_Integer)
   is
      Limit       : constant Cost := Current_Max (S) - 1;
      Start_Value : constant Long_Float := Current_Value (P, S, W);

      --  A closing step ends the chain if other tours are still at the
      --  makespan (the next round takes them on) or the objective fell.
      function Ends_Chain return Boolean is
        (Current_Max (S) > Limit or else Current_Value (P, S, W) < Start_Value);

      procedure Apply_Step (Mv : Move) is
      begin
         Save_Tour (S, Space, 2 * Space.Applied + 1, Mv.A.Robot);
         Save_Tour (S, Space, 2 * Space.Applied + 2, Mv.B.Robot);
         Space.Applied := Space.Applied + 1;
         Apply (P, S, Mv);
         if Check then
            Verify (P, S, Mv, Predicted => True);
         end if;
      end Apply_Step;

      procedure Undo is
      begin
         Undo_Step (P, S, Space);
         if Check then
            Verify (P, S, No_Move, Predicted => False);
         end if;
      end Undo;

      --  The Donor tour is above Limit: a step from it to a tour not in the
      --  chain that brings it to Limit or below; then the chain ends or
      --  goes on from the receiving tour.
      procedure Extend (Donor : Positive; Depth : Positive; Found : out Boolean) is
         Width : constant Positive := Breadth (Depth);
         Best  : Candidate_List;
         Count : Natural := 0;

         procedure Consider (Mv : in out Move) is
            Valid : Boolean;
            C : Candidate;
            K : Natural;
         begin
            Evaluate_Move (P, S, W, Mv, Valid);
            Evaluations := Evaluations + 1;
            if not Valid or else Mv.New_A_Cost > Limit then
               return;
            end if;
            C.Closes := Mv.New_B_Cost <= Limit;
            if Depth = Max_Depth and then not C.Closes then
               return;  --  The chain could not go on.
            end if;
            C.Rank := (if C.Closes then Mv.Value else Long_Float (Mv.New_B_Cost));
            if Count = Width and then not Before (C, Best (Count)) then
               return;
            end if;
            C.Mv := Mv;
            K := Natural'Min (Count + 1, Width);
            Count := K;
            while K > 1 and then Before (C, Best (K - 1)) loop
               Best (K) := Best (K - 1);
               K := K - 1;
            end loop;
            Best (K) := C;
         end Consider;

         Mv : Move;
         Ok : Boolean;
      begin
         Found := False;
         for I in P.Frozen_Length (Donor) + 1 .. S.Length (Donor) loop
            declare
               T : constant Positive := S.Task_At (Donor, I);
            begin
               for U_Index in 1 .. S.Near_Count (T) loop
                  declare
                     U : constant Positive := S.Near (T, U_Index);
                     Q : constant Natural := S.Owner (U);
                  begin
                     if Q /= 0 and then Q /= Donor and then not Space.Visited (Q) then
                        for Length in 1 .. Natural'Min (3, S.Length (Donor) - I + 1) loop
                           for Variant in 0 .. 3 loop
                              Or_Opt (P, S, T, U, Length, Variant, Mv, Ok);
                              if Ok then
                                 Consider (Mv);
                              end if;
                           end loop;
                        end loop;
                        for Variant in 0 .. 3 loop
                           Two_Opt (P, S, T, U, Variant, Mv, Ok);
                           if Ok then
                              Consider (Mv);
                           end if;
                        end loop;
                     end if;
                  end;
               end loop;
            end;
         end loop;
         for K in 1 .. Count loop
            declare
               C : Candidate renames Best (K);
               Q : constant Positive := C.Mv.B.Robot;
            begin
               Apply_Step (C.Mv);
               if C.Closes then
                  Found := Ends_Chain;
               elsif Depth < Max_Depth then
                  Space.Visited (Q) := True;
                  Extend (Q, Depth + 1, Found);
                  Space.Visited (Q) := False;
               end if;
               if Found then
                  return;
               end if;
               Undo;
            end;
         end loop;
      end Extend;

      Rounds : Natural := 0;
      Found  : Boolean := True;
   begin
      Improved := False;
      if W.C.Max_Weight = 0.0 or else S.Robots < 2 then
         return;
      end if;
      Space.Applied := 0;
      while Current_Max (S) > Limit loop
         if Rounds = Max_Rounds then
            Found := False;
            exit;
         end if;
         Rounds := Rounds + 1;
         declare
            Donor : Positive := 1;
         begin
            for R in 2 .. S.Robots loop
               if S.Robot_Cost (R) > S.Robot_Cost (Donor) then
                  Donor := R;
               end if;
            end loop;
            Space.Visited := [others => False];
            Space.Visited (Donor) := True;
            Extend (Donor, 1, Found);
         end;
         exit when not Found;
      end loop;
      if Found and then Current_Value (P, S, W) < Start_Value then
         Improved := True;
         return;
      end if;
      while Space.Applied > 0 loop
         Undo;
      end loop;
   end Ejection_Chain;

end Sancta.Allocation.Annealers.Chains;
