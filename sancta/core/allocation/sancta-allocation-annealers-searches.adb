with Ada.Numerics.Long_Elementary_Functions;
with Sancta.Allocation.Local_Search;
with Sancta.Allocation.Annealers.Construction; use Sancta.Allocation.Annealers.Construction;
with Sancta.Allocation.Annealers.Neighbourhoods;
use Sancta.Allocation.Annealers.Neighbourhoods;

package body Sancta.Allocation.Annealers.Searches is

   use Ada.Numerics.Long_Elementary_Functions;
   use type Chains.Workspace_Access;
   use Ada.Real_Time;

   --  The budget's clock (wall or CPU time, Options.Budget_Clock).
   function Now (This : Search) return Time is (Budget_Clocks.Clock (This.Opts.Budget_Clock));

   Reheat_Phase_Moves : constant := 5.0E6;
   --  The automatic schedule's hybrid needs this many moves after its
   --  geometric share: a few cycles of the reheat schedule, whose steps are
   --  counted in moves (20 000 without improvement, 1 M without a new best).
   --  Shorter budgets (about 1 s of CPU at 100-200 tasks) anneal
   --  geometrically: halving the cooling costs more there than the reheats
   --  gain (measured at 1 s: kroA200 x 5 +2.05% geometric, +4.96% hybrid).

   Initial_Weights : constant Kind_Reals :=
     [Or_Opt_Near => 3.0, Two_Opt_Near => 3.0, Or3_Near => 2.0, Cross_Near => 1.5,
      Random_Move => 0.5, Move_Owner => 0.5, Guided_Move => 0.5,
      Log_Auction => 0.5, Swap_Any => 0.5, Switch_Or => 0.5,
      Segment_Move => 0.5, Random_Reverse => 0.5,
      Switch_Subtree => 0.5, Ruin_Recreate => 0.0, Route_Search => 0.0,
      Ejection_Chain => 0.0];
   --  Ruin_Recreate and Ejection_Chain are not drawn: they run on their
   --  shares of evaluations; Route_Search every Route_Search_Interval x
   --  tasks moves.

   overriding procedure Finalize (This : in out Search) is
   begin
      if This.Tours /= null then
         Free (This.Tours.Compact);
      end if;
      Free (This.Tours);
      Free (This.Switch);
      Chains.Free (This.Chain_Space);
   end Finalize;

   ---------------------------------------------------------------------------
   --  Small helpers.

   function True_Value (This : Search) return Long_Float is
     (Value (This.Opts.Criterion, Current_Max (This.Tours.all), This.Tours.Total_Cost,
             This.Tours.Total_Completion, This.Tours.Active_Tasks));
   --  The criterion itself (no tie-break).

   procedure Save_Best (This : in out Search) is
   begin
      Store (This.Tours.all, This.Best);
      This.Best_Saved := True;
   end Save_Best;

   function Sum_Of (W : Kind_Reals) return Long_Float is
      Total : Long_Float := 0.0;
   begin
      for M in Move_Kind loop
         Total := Total + W (M);
      end loop;
      return Total;
   end Sum_Of;
   --  In Move_Kind order (Search.Weight_Total).

   procedure Check (This : Search; P : Problem; Mv : Move := No_Move;
                    Predicted : Boolean := False) is
   begin
      if This.Opts.Check then
         Verify (P, This.Tours.all, Mv, Predicted);
         if This.Weight_Total /= Sum_Of (This.Weight) then
            raise Program_Error with "annealer check failed: move weight total";
         end if;
      end if;
   end Check;

   procedure Restart_From_Current (This : in out Search; P : Problem) is
   begin
      This.Current := Current_Value (P, This.Tours.all, This.Guide);
   end Restart_From_Current;

   --  The squared-excess term (Options.Excess_Weight) for a new best
   --  makespan: its floor Excess_Band below it, its weight such that the
   --  longest tour's excess weighs Excess_Weight per unit of cost.
   procedure Set_Excess_Floor (This : in out Search; Makespan : Cost) is
      Band : constant Cost :=
        Cost'Max (1, Cost (This.Opts.Excess_Band * Long_Float (Makespan)));
   begin
      This.Excess_Makespan := Makespan;
      Set_Square_Floor (This.Tours.all, Makespan - Band);
      This.Guide.Square := This.Opts.Excess_Weight / (2.0 * Long_Float (Band));
   end Set_Excess_Floor;

   procedure Note_New_Best (This : in out Search; Kind : Move_Kind; Value : Long_Float) is
   begin
      if This.Excess_Floor and then Current_Max (This.Tours.all) < This.Excess_Makespan then
         --  The search objective changes: the current value and the
         --  schedule's reference move with it.
         declare
            Before : constant Long_Float := This.Guide.Square * This.Tours.Total_Square;
            Change : Long_Float;
         begin
            Set_Excess_Floor (This, Current_Max (This.Tours.all));
            Change := This.Guide.Square * This.Tours.Total_Square - Before;
            This.Current := This.Current + Change;
            This.Cycle_Best := This.Cycle_Best + Change;
         end;
      end if;
      This.Best_Value := Value;
      This.Best_Saved := False;
      This.Last_Best_Move := This.Moves;
      This.Best_Time := To_Duration (Now (This) - This.Started);
      This.Kinds (Kind).New_Best := This.Kinds (Kind).New_Best + 1;
      if This.Opts.Target > 0.0 and then True_Value (This) <= This.Opts.Target then
         This.Stop := True;
      end if;
   end Note_New_Best;

   function Accepts (This : in out Search; Delta_Value : Long_Float) return Boolean is
     (Delta_Value <= 0.0
      or else (Delta_Value < 30.0 * This.Temperature
               and then Random.Uniform (This.Generator)
                        < Exp (-Delta_Value / This.Temperature)));
   --  The Metropolis rule (never uphill by more than 30 temperatures).

   function Statistics (This : Search) return Progress is
     (Best => This.Best_Value, Current => This.Current, Temperature => This.Temperature,
      Moves => This.Moves, Accepted => This.Accepted, Elapsed => This.Elapsed,
      Moves_Per_Second => (if This.Elapsed > 0.0
                           then Long_Float (This.Moves) / Long_Float (This.Elapsed)
                           else 0.0),
      Time_To_Best => This.Best_Time, Kinds => This.Kinds,
      Polish_Gain => This.Polish_Gain, Switches => This.Switches);

   procedure Send_Report (This : in out Search) is
   begin
      if This.Opts.Box /= null then
         if not This.Best_Saved then
            Save_Best (This);
         end if;
         This.Opts.Box.Post (This.Best, This.Best_Value);
      end if;
      if This.Opts.Report /= null then
         This.Opts.Report (Statistics (This));
      end if;
   end Send_Report;

   ---------------------------------------------------------------------------
   --  Drawing and proposing moves.

   function Pick_Kind (This : in out Search) return Move_Kind is
      X : Long_Float := Random.Uniform (This.Generator) * This.Weight_Total;
   begin
      for M in Move_Kind loop
         X := X - This.Weight (M);
         if X < 0.0 then
            return M;
         end if;
      end loop;
      return Or_Opt_Near;
   end Pick_Kind;

   function Worst_Robot (S : State) return Positive is
      Worst : Positive := 1;
   begin
      for R in 2 .. S.Robots loop
         if S.Robot_Cost (R) > S.Robot_Cost (Worst) then
            Worst := R;
         end if;
      end loop;
      return Worst;
   end Worst_Robot;
   --  The robot with the largest cost (the first of equals).

   --  Guided move (from the worst robot to another) and log auction (task
   --  T anywhere): the best of Log_Tries random re-insertions.
   procedure Propose_Best_Insert
     (This : in out Search; P : Problem; T : Positive; Guided : Boolean;
      Mv : in out Move; Ok : out Boolean)
   is
      S : State renames This.Tours.all;
      Source : Natural := T;
      Slots : array (Boolean) of Move;
      Best : Boolean := False;
      --  The best candidate so far in Slots (Best), the next one drawn in
      --  the other slot (no copy of a move per improvement).
      Found, Legal : Boolean := False;
   begin
      Ok := False;
      if Guided then
         --  A random movable task of the robot with the worst cost.
         declare
            Worst : constant Positive := Worst_Robot (S);
            Free_Length : constant Natural := S.Length (Worst) - P.Frozen_Length (Worst);
         begin
            if Free_Length = 0 then
               return;
            end if;
            Source := S.Task_At
              (Worst, P.Frozen_Length (Worst) + 1 + Random.Below (This.Generator, Free_Length));
         end;
      end if;
      for Try in 1 .. This.Log_Tries loop
         declare
            Candidate : Move renames Slots (not Best);
         begin
            Random_Insert (P, S, This.Generator, Source, Guided, Candidate, Legal);
            if Legal then
               Evaluate_Move (P, S, This.Guide, Candidate, Legal);
               if Legal and then (not Found or else Candidate.Value < Slots (Best).Value) then
                  Best := not Best;
                  Found := True;
               end if;
            end if;
         end;
      end loop;
      if Found then
         Mv := Slots (Best);
         Ok := True;
      end if;
   end Propose_Best_Insert;

   --  The neighbour moves from T drawn at random: T's candidate neighbour
   --  first, then the move's own numbers, one declaration each (the order
   --  in which a call's arguments are evaluated is the compiler's choice,
   --  RM 6.4(10)); nothing (Ok False) when the neighbour is not in a tour.

   function Draw_Neighbour (This : in out Search; T : Positive) return Natural is
     (Placed_Neighbour (This.Tours.all, T, 1 + Random.Below (This.Generator, This.Neighbours)));

   procedure Propose_Or_Opt
     (This : in out Search; P : Problem; T : Positive; Mv : in out Move; Ok : out Boolean)
   is
      U       : constant Natural := Draw_Neighbour (This, T);
      Length  : constant Positive := 1 + Random.Below (This.Generator, 3);
      Variant : constant Natural := Random.Below (This.Generator, 4);
   begin
      Ok := False;
      if U /= 0 then
         Or_Opt (P, This.Tours.all, T, U, Length, Variant, Mv, Ok);
      end if;
   end Propose_Or_Opt;

   procedure Propose_Two_Opt
     (This : in out Search; P : Problem; T : Positive; Mv : in out Move; Ok : out Boolean)
   is
      U       : constant Natural := Draw_Neighbour (This, T);
      Variant : constant Natural := Random.Below (This.Generator, 4);
   begin
      Ok := False;
      if U /= 0 then
         Two_Opt (P, This.Tours.all, T, U, Variant, Mv, Ok);
      end if;
   end Propose_Two_Opt;

   procedure Propose_Or_3opt
     (This : in out Search; P : Problem; T : Positive; Mv : in out Move; Ok : out Boolean)
   is
      U       : constant Natural := Draw_Neighbour (This, T);
      V_Index : constant Positive := 1 + Random.Below (This.Generator, This.Neighbours);
      Variant : constant Natural := Random.Below (This.Generator, 2);
   begin
      Ok := False;
      if U /= 0 then
         Or_3opt (P, This.Tours.all, T, U, V_Index, Variant, Mv, Ok);
      end if;
   end Propose_Or_3opt;

   procedure Propose_Cross_Exchange
     (This : in out Search; P : Problem; T : Positive; Mv : in out Move; Ok : out Boolean)
   is
      U  : constant Natural := Draw_Neighbour (This, T);
      L1 : constant Positive := 1 + Random.Below (This.Generator, 3);
      L2 : constant Natural := Random.Below (This.Generator, 4);
   begin
      Ok := False;
      if U /= 0 then
         Cross_Exchange (P, This.Tours.all, T, U, L1, L2, Mv, Ok);
      end if;
   end Propose_Cross_Exchange;

   --  Makespan criteria: a task of the longest tour (the tour that sets the
   --  makespan) moved next to one of its candidate neighbours (Or-opt of 1
   --  to 3 tasks) or joined to it by 2-opt / 2-opt*: the neighbour moves,
   --  aimed where the makespan can fall (uniform draws hit the longest of
   --  10 tours one time in 10).
   procedure Propose_Worst_Near
     (This : in out Search; P : Problem; Mv : in out Move; Ok : out Boolean)
   is
      S : State renames This.Tours.all;
      G : Random.Generator renames This.Generator;
      Worst : constant Positive := Worst_Robot (S);
      Free_Length : constant Natural := S.Length (Worst) - P.Frozen_Length (Worst);
      T : Positive;
   begin
      Ok := False;
      if Free_Length = 0 then
         return;
      end if;
      T := S.Task_At (Worst, P.Frozen_Length (Worst) + 1 + Random.Below (G, Free_Length));
      if Random.Below (G, 2) = 0 then
         Propose_Or_Opt (This, P, T, Mv, Ok);
      else
         Propose_Two_Opt (This, P, T, Mv, Ok);
      end if;
   end Propose_Worst_Near;

   --  Another alternative of an OR task T, at the best of a few random
   --  places (its own place among them).
   procedure Propose_Switch_Or
     (This : in out Search; P : Problem; T : Positive; Mv : in out Move; Ok : out Boolean)
   is
      S : State renames This.Tours.all;
      G : Random.Generator renames This.Generator;
      C : Positive := 1 + Random.Below (G, P.Alt_Count (T) - 1);
      R : constant Positive := S.Owner (T);
      I : constant Positive := S.Position (T);
      Candidate, Best_Mv : Move;
      Legal : Boolean;
   begin
      if C >= S.Choice (T) then
         C := C + 1;
      end if;
      Relocate (S, Best_Mv, R, I, I, R, I, False, Legal,
                New_Location => Location_Of (P, T, C));
      Evaluate_Move (P, S, This.Guide, Best_Mv, Legal);
      for Try in 1 .. This.Log_Tries loop
         declare
            R2 : constant Positive := 1 + Random.Below (G, S.Robots);
            Q  : constant Natural := Random_Robot_Position (P, S, G, R2);
         begin
            if R2 /= R or else (Q /= I and then Q + 1 /= I) then
               Relocate (S, Candidate, R, I, I, R2, Q, False, Legal,
                         New_Location => Location_Of (P, T, C));
               if Legal then
                  Evaluate_Move (P, S, This.Guide, Candidate, Legal);
                  if Legal and then Candidate.Value < Best_Mv.Value then
                     Best_Mv := Candidate;
                  end if;
               end if;
            end if;
         end;
      end loop;
      Mv := Best_Mv;
      Mv.Switch_Task := T;
      Mv.Switch_To := C;
      Ok := True;
   end Propose_Switch_Or;

   procedure Propose
     (This : in out Search; P : Problem; Kind : Move_Kind; Mv : in out Move; Ok : out Boolean)
   is
      S : State renames This.Tours.all;
      G : Random.Generator renames This.Generator;
      T : constant Natural := Random_Task (P, S, G);
   begin
      Ok := False;
      Mv.Switch_Task := 0;
      Mv.Or_Node := 0;
      if T = 0 then
         return;
      end if;
      case Kind is
         when Switch_Subtree =>
            Propose_Switch (P, S, G, This.Guide, This.Locked, This.Switch.all, Mv, Ok);
         when Or_Opt_Near =>
            Propose_Or_Opt (This, P, T, Mv, Ok);
         when Two_Opt_Near =>
            Propose_Two_Opt (This, P, T, Mv, Ok);
         when Or3_Near =>
            Propose_Or_3opt (This, P, T, Mv, Ok);
         when Cross_Near =>
            Propose_Cross_Exchange (This, P, T, Mv, Ok);
         when Random_Move =>
            declare
               R : constant Positive := S.Owner (T);
               Q : constant Natural := Random_Robot_Position (P, S, G, R);
            begin
               if Q /= S.Position (T) and then Q + 1 /= S.Position (T) then
                  Relocate (S, Mv, R, S.Position (T), S.Position (T), R, Q, False, Ok);
               end if;
            end;
         when Move_Owner =>
            Random_Insert (P, S, G, T, True, Mv, Ok);
         when Guided_Move =>
            if This.Guide.C.Max_Weight > 0.0 and then Random.Below (G, 3) > 0 then
               Propose_Worst_Near (This, P, Mv, Ok);
            else
               Propose_Best_Insert (This, P, T, True, Mv, Ok);
            end if;
         when Log_Auction =>
            Propose_Best_Insert (This, P, T, False, Mv, Ok);
         when Segment_Move =>
            --  A random segment (any length) of T's tour, moved to a
            --  random place of a random robot, maybe reversed.
            declare
               R1 : constant Positive := S.Owner (T);
               I  : constant Positive := S.Position (T);
               J  : constant Positive := I + Random.Below (G, S.Length (R1) - I + 1);
               R2 : constant Positive := 1 + Random.Below (G, S.Robots);
               Q  : constant Natural := Random_Robot_Position (P, S, G, R2);
            begin
               if R2 /= R1 or else Q + 1 < I or else Q > J then
                  Relocate (S, Mv, R1, I, J, R2, Q, Random.Below (G, 2) = 0, Ok);
               end if;
            end;
         when Random_Reverse =>
            declare
               R1 : constant Positive := S.Owner (T);
               I  : constant Positive := S.Position (T);
               J  : constant Positive := I + Random.Below (G, S.Length (R1) - I + 1);
            begin
               if J > I then
                  Clear (Mv);
                  Mv.A.Robot := R1;
                  Add (Mv.A, R1, 1, I - 1);
                  Add (Mv.A, R1, I, J, True);
                  Add (Mv.A, R1, J + 1, S.Length (R1));
                  Ok := True;
               end if;
            end;
         when Swap_Any =>
            declare
               U : constant Natural := Random_Task (P, S, G);
            begin
               if U /= 0 then
                  Swap (S, T, U, Mv, Ok);
               end if;
            end;
         when Ruin_Recreate | Route_Search | Ejection_Chain =>
            null;  --  Not single moves: see Ruin_And_Recreate, Search_Routes, Run_Chain.
         when Switch_Or =>
            if P.Alt_Count (T) > 1 then
               Propose_Switch_Or (This, P, T, Mv, Ok);
            end if;
      end case;
   end Propose;

   procedure Apply_Move (This : in out Search; P : Problem; Mv : Move) is
   begin
      if Mv.Or_Node /= 0 then
         Apply_Switch (P, This.Tours.all, This.Switch.all);
      else
         Apply (P, This.Tours.all, Mv);
      end if;
      Check (This, P, Mv, Predicted => True);
   end Apply_Move;

   ---------------------------------------------------------------------------
   --  One step: a drawn move, or ruin and recreate.

   function Ruin_Due (This : Search) return Boolean is
     (This.Only_Ruin
      or else (This.Opts.Ruin_Share > 0.0 and then This.Opts.Enabled (Ruin_Recreate)
               and then Long_Float (This.Ruin_Evaluations)
                        < This.Opts.Ruin_Share * Long_Float (This.Moves)));

   function Ruin_Seed (This : in out Search; P : Problem) return Natural is
      --  Makespan criteria: half the time a task of the longest tour.
      S : State renames This.Tours.all;
   begin
      if This.Guide.C.Max_Weight > 0.0 and then P.Robots > 1
        and then Random.Below (This.Generator, 2) = 0
      then
         declare
            Worst : constant Positive := Worst_Robot (S);
            N : constant Natural := S.Length (Worst) - P.Frozen_Length (Worst);
         begin
            if N > 0 then
               return S.Task_At
                 (Worst, P.Frozen_Length (Worst) + 1 + Random.Below (This.Generator, N));
            end if;
         end;
      end if;
      return Random_Task (P, S, This.Generator);
   end Ruin_Seed;

   --  Ruin and recreate (a large neighbourhood move): a random task and up
   --  to Neighbours of its candidate neighbours leave their tours and are
   --  put back one by one, in random order, at their best places for the
   --  search objective (any robot); the result is accepted or undone like
   --  any move.
   procedure Ruin_And_Recreate (This : in out Search; P : Problem) is
      S      : State renames This.Tours.all;
      Seed_T : constant Natural := Ruin_Seed (This, P);
      List   : Count_Array (1 .. This.Neighbours + 1);
      N      : Natural := 0;
      Want   : Positive;
      Old_Length : constant Count_Array (1 .. P.Robots) := S.Length;
      Ok     : Boolean := True;
      V, Delta_Value : Long_Float;
      X : Kind_Stats renames This.Kinds (Ruin_Recreate);
   begin
      X.Tries := X.Tries + 1;
      if Seed_T = 0 then
         This.Ruin_Evaluations := This.Ruin_Evaluations + 1;
         return;
      end if;
      Want := 2 + Random.Below (This.Generator, This.Neighbours);
      N := 1;
      List (1) := Seed_T;
      for I in 1 .. S.Near_Count (Seed_T) loop
         exit when N >= Want;
         if Movable (P, S, S.Near (Seed_T, I)) then
            N := N + 1;
            List (N) := S.Near (Seed_T, I);
         end if;
      end loop;
      Shuffle (This.Generator, List, N);
      if not This.Best_Saved then
         Save_Best (This);
      end if;
      Store (S, This.Backup);
      Remove_Tasks (P, S, List (1 .. N));
      for I in 1 .. N loop
         Best_Insert (P, S, This.Guide, List (I));
      end loop;
      This.Ruin_Evaluations :=
        This.Ruin_Evaluations + Long_Long_Integer (N * (S.Active_Tasks + P.Robots));
      for R in 1 .. P.Robots loop
         if S.Length (R) < P.Min_Tasks and then S.Length (R) < Old_Length (R) then
            Ok := False;
         end if;
      end loop;
      V := Current_Value (P, S, This.Guide);
      Delta_Value := V - This.Current;
      if Ok and then Accepts (This, Delta_Value) then
         X.Legal := X.Legal + 1;
         X.Accepted := X.Accepted + 1;
         This.Accepted := This.Accepted + 1;
         This.Current := V;
         if Delta_Value < 0.0 then
            X.Improving := X.Improving + 1;
         end if;
         declare
            Goal_Value : constant Long_Float := Current_Value (P, S, This.Goal);
         begin
            if Goal_Value < This.Best_Value - 1.0E-9 then
               Note_New_Best (This, Ruin_Recreate, Goal_Value);
            end if;
         end;
      else
         if Ok then
            X.Legal := X.Legal + 1;
         end if;
         Load (P, S, This.Backup);
      end if;
      Check (This, P);
   end Ruin_And_Recreate;

   function Chain_Due (This : Search) return Boolean is
     (This.Chain_Space /= null and then This.Opts.Chain_Share > 0.0
      and then Long_Float (This.Chain_Evaluations)
               < This.Opts.Chain_Share * Long_Float (This.Moves));

   --  One ejection chain from the current solution (Chains), kept if it
   --  lowers the search objective.
   procedure Run_Chain (This : in out Search; P : Problem) is
      S : State renames This.Tours.all;
      X : Kind_Stats renames This.Kinds (Ejection_Chain);
      Improved : Boolean;
   begin
      X.Tries := X.Tries + 1;
      This.Chain_Evaluations := This.Chain_Evaluations + 1;
      if not This.Best_Saved then
         Save_Best (This);
      end if;
      Chains.Ejection_Chain (P, S, This.Guide, This.Chain_Space.all, This.Opts.Check,
                             Improved, This.Chain_Evaluations);
      if not Improved then
         return;
      end if;
      X.Legal := X.Legal + 1;
      X.Accepted := X.Accepted + 1;
      X.Improving := X.Improving + 1;
      This.Accepted := This.Accepted + 1;
      Restart_From_Current (This, P);
      if This.Current < This.Cycle_Best then
         This.Cycle_Best := This.Current;
         This.Since_Improve := 0;
      end if;
      declare
         Goal_Value : constant Long_Float := Current_Value (P, S, This.Goal);
      begin
         if Goal_Value < This.Best_Value - 1.0E-9 then
            Note_New_Best (This, Ejection_Chain, Goal_Value);
         end if;
      end;
   end Run_Chain;

   --  The current routes shortened by a descent of the route search
   --  (Local_Search.Polish_Routes: 2-opt, Or-opt, LK chains, no kicks):
   --  route lengths never grow, so neither does the search objective (no
   --  mean completion time here); a new best is noted.
   procedure Search_Routes (This : in out Search; P : Problem) is
      S : State renames This.Tours.all;
      X : Kind_Stats renames This.Kinds (Route_Search);
      Found : Local_Search.Statistics;
      function Compact_Distance (R : Positive; From, To : Natural) return Cost is
        (Arc (P, S, R, From, To));
      --  Robot_Distance (P, R, From, To) from S's compact copy, if any.
      Time_Left : constant Duration :=
        (if This.Opts.Time_Limit > 0.0
         then Duration'Max (0.001, This.Opts.Time_Limit - To_Duration (Now (This) - This.Started))
         else 0.0);
      --  Descents stopped at the end of the budget (unbounded under a move
      --  budget alone: deterministic).
   begin
      X.Tries := X.Tries + 1;
      Store (S, This.Backup);
      Local_Search.Polish_Routes
        (P, This.Backup,
         (Time_Limit => Time_Left, Budget_Clock => This.Opts.Budget_Clock,
          Seed => This.Opts.Seed, Kicks => False, Check => This.Opts.Check, others => <>),
         Found, Compact_Distance'Access);
      if Found.After >= Found.Before then
         return;
      end if;
      X.Legal := X.Legal + 1;
      X.Accepted := X.Accepted + 1;
      X.Improving := X.Improving + 1;
      Load (P, S, This.Backup);
      Check (This, P);
      Restart_From_Current (This, P);
      declare
         Goal_Value : constant Long_Float := Current_Value (P, S, This.Goal);
      begin
         if Goal_Value < This.Best_Value - 1.0E-9 then
            Note_New_Best (This, Route_Search, Goal_Value);
         end if;
      end;
   end Search_Routes;

   --  A drawn move: proposed, evaluated, accepted by the Metropolis rule
   --  (the best is saved before leaving a better solution).
   procedure Try_Move (This : in out Search; P : Problem) is
      Kind : constant Move_Kind := Pick_Kind (This);
      Mv   : Move;
      Ok   : Boolean;
      Delta_Value, Goal_Value : Long_Float;
      X    : Kind_Stats renames This.Kinds (Kind);
   begin
      Propose (This, P, Kind, Mv, Ok);
      This.Tries (Kind) := This.Tries (Kind) + 1.0;
      X.Tries := X.Tries + 1;
      if Ok then
         Evaluate_Move (P, This.Tours.all, This.Guide, Mv, Ok);
      end if;
      if not Ok then
         return;
      end if;
      X.Legal := X.Legal + 1;
      Delta_Value := Mv.Value - This.Current;
      if not Accepts (This, Delta_Value) then
         This.Since_Improve := This.Since_Improve + 1;
         return;
      end if;
      Goal_Value := Objective (This.Goal, Mv.New_Max, Mv.New_Sum, Mv.New_Completion,
                               Mv.New_Active);
      if not This.Best_Saved and then Goal_Value > This.Best_Value then
         Save_Best (This);
      end if;
      Apply_Move (This, P, Mv);
      This.Accepted := This.Accepted + 1;
      if Mv.Or_Node /= 0 then
         This.Switches := This.Switches + 1;
      end if;
      X.Accepted := X.Accepted + 1;
      This.Current := Mv.Value;
      if Delta_Value < 0.0 then
         This.Score (Kind) := This.Score (Kind) + 1.0;
         X.Improving := X.Improving + 1;
      end if;
      if This.Current < This.Cycle_Best then
         This.Cycle_Best := This.Current;
         This.Since_Improve := 0;
      else
         This.Since_Improve := This.Since_Improve + 1;
      end if;
      if Goal_Value < This.Best_Value - 1.0E-9 then
         This.Score (Kind) := This.Score (Kind) + 2.0;
         Note_New_Best (This, Kind, Goal_Value);
      end if;
   end Try_Move;

   ---------------------------------------------------------------------------
   --  Set-up.

   procedure Choose_Move_Kinds (This : in out Search; P : Problem) is
      W : Kind_Reals renames This.Weight;
   begin
      W := Initial_Weights;
      if not (for some T in 1 .. P.Tasks => P.Alt_Count (T) > 1) then
         W (Switch_Or) := 0.0;
      end if;
      if not (for some O in 1 .. Or_Count (P) =>
                not This.Locked (O) and then Alternatives (P, O) > 1)
      then
         W (Switch_Subtree) := 0.0;
      end if;
      if P.Robots = 1 then
         W (Move_Owner) := 0.0;
         W (Guided_Move) := 0.0;
         W (Cross_Near) := 0.0;
      end if;
      for M in Move_Kind loop
         if not This.Opts.Enabled (M) then
            W (M) := 0.0;
         end if;
      end loop;
      if (for all M in Move_Kind => W (M) = 0.0) then
         if not This.Opts.Enabled (Ruin_Recreate) then
            raise Constraint_Error with "annealer: no move kind enabled";
         end if;
         This.Only_Ruin := True;
      end if;
      This.Weight_Total := Sum_Of (W);
   end Choose_Move_Kinds;

   --  Temperatures from the mean uphill delta of 300 sampled moves.
   procedure Sample_Temperatures (This : in out Search; P : Problem) is
      Sum_Up : Long_Float := 0.0;
      N_Up   : Natural := 0;
      Mv     : Move;
      Ok     : Boolean;
      T0, T1 : Long_Float;
   begin
      for I in 1 .. 300 loop
         Propose (This, P, Pick_Kind (This), Mv, Ok);
         if Ok then
            Evaluate_Move (P, This.Tours.all, This.Guide, Mv, Ok);
            if Ok and then Mv.Value > This.Current
              and then Mv.Value - This.Current < 0.5 * Long_Float (Infinity)
            then
               Sum_Up := Sum_Up + (Mv.Value - This.Current);
               N_Up := N_Up + 1;
            end if;
         end if;
      end loop;
      T0 := (if N_Up > 0 then This.Opts.Start_Factor * Sum_Up / Long_Float (N_Up) else 1.0);
      if This.Opts.Start_Temperature > 0.0 then
         T0 := This.Opts.Start_Temperature;
      end if;
      T1 := (if This.Opts.End_Temperature > 0.0 then This.Opts.End_Temperature
             else T0 / This.Opts.End_Ratio);
      This.Start_Temperature := T0;
      This.End_Temperature := Long_Float'Min (T1, T0);
      This.Temperature := T0;
      This.Reheat_Temperature := T0;
   end Sample_Temperatures;

   procedure Start
     (This   : in out Search;
      P      : Problem;
      Opts   : Options;
      Best   : Assignment) is
   begin
      if Opts.Time_Limit <= 0.0 and then Opts.Iterations <= 0 and then Opts.Convergence <= 0 then
         raise Constraint_Error with "annealer: no budget (time, iterations or convergence)";
      end if;
      if Opts.Geometric_Share not in 0.0 .. 1.0 then
         raise Constraint_Error with "annealer: Geometric_Share" & Opts.Geometric_Share'Image
           & " is not in 0 .. 1";
      end if;
      if Opts.Excess_Weight < 0.0 then
         raise Constraint_Error with "annealer: Excess_Weight" & Opts.Excess_Weight'Image
           & " is negative";
      elsif Opts.Excess_Band not in 0.0 .. 1.0 then
         raise Constraint_Error with "annealer: Excess_Band" & Opts.Excess_Band'Image
           & " is not in 0 .. 1";
      end if;
      This.Opts := Opts;
      This.Automatic_Hybrid := False;
      if Opts.Schedule = Automatic then
         This.Automatic_Hybrid := Opts.Criterion.Sum_Weight = 0.0
           and then Opts.Criterion.Ave_Weight = 0.0 and then P.Robots > 1;
         This.Opts.Schedule := (if This.Automatic_Hybrid then Hybrid else Geometric);
      end if;
      This.Neighbours := Positive'Min (Opts.Neighbours, Positive'Max (1, P.Tasks - 1));
      This.Tours := New_State (P, This.Neighbours);
      This.Tours.Compact := Compact_Matrix (P);
      This.Generator := Random.Seeded (Opts.Seed);
      This.Started := Now (This);
      This.Next_Report := This.Started + To_Time_Span (Opts.Report_Every);
      This.Runs := (if Opts.Runs > 0 then Opts.Runs else 1);
      This.Runs_Decided := Opts.Runs > 0 or else This.Opts.Schedule not in Geometric | Hybrid
        or else (Opts.Time_Limit <= 0.0 and then Opts.Iterations <= 0);
      This.Switch := New_Switch (P);
      This.Log_Tries := Natural (Long_Float'Floor (Log (Long_Float (P.Tasks)))) + 1;
      Compute_Neighbours (P, This.Tours.all);
      for O in 1 .. Or_Count (P) loop
         This.Locked (O) := Is_Locked (P, O);
      end loop;
      Choose_Move_Kinds (This, P);
      This.Route_Searches := Opts.Polish and then Opts.Criterion.Ave_Weight = 0.0
        and then Opts.Enabled (Route_Search);
      if Opts.Criterion.Max_Weight > 0.0 and then P.Robots > 1
        and then Opts.Enabled (Ejection_Chain)
      then
         This.Chain_Space := Chains.New_Workspace (P);
      end if;
      This.Next_Route_Search := Route_Search_Interval * Long_Long_Integer (P.Tasks);
      if Opts.Initial then
         declare
            V : constant String := Validate (P, Best);
         begin
            if V /= "" and then (V'Length < 6 or else V (V'First .. V'First + 5) /= "robot ") then
               raise Constraint_Error with "annealer: bad initial assignment: " & V;
            end if;
         end;
         Load (P, This.Tours.all, Best);
      else
         Construct (P, This.Tours.all, Opts.Criterion, This.Generator);
      end if;
      This.Goal := Make_Weights (P, Opts.Criterion, This.Tours.Total_Cost);
      This.Guide := This.Goal;
      if This.Goal.Tie > 0.0 then
         This.Initial_Balance :=
           (if Opts.Balance >= 0.0 then Opts.Balance else 1.0 / Long_Float (P.Robots));
         This.Guide.Tie := Long_Float'Max (This.Goal.Tie, This.Initial_Balance);
         if Opts.Square_Balance > 0.0 and then P.All_Feasible then
            --  d/dc (W c^2) = Square_Balance at the mean tour cost.
            This.Guide.Square := Opts.Square_Balance
              / (2.0 * Long_Float'Max (1.0, Long_Float (This.Tours.Total_Cost)
                                          / Long_Float (P.Robots)));
         elsif This.Opts.Excess_Weight > 0.0 and then This.Opts.Excess_Band > 0.0
           and then P.All_Feasible
         then
            This.Excess_Floor := True;
            Set_Excess_Floor (This, Current_Max (This.Tours.all));
         end if;
      end if;
      Check (This, P);
      Restart_From_Current (This, P);
      This.Best_Value := Current_Value (P, This.Tours.all, This.Goal);
      Save_Best (This);
      Sample_Temperatures (This, P);
      This.Cycle_Best := This.Current;
   end Start;

   ---------------------------------------------------------------------------
   --  Budget and schedule (every 128 moves).

   --  The share of the budget used (0 .. 1; may exceed 1), setting Stop
   --  when it is spent.
   function Budget_Used (This : in out Search; Reading : Time) return Long_Float is
      O : Options renames This.Opts;
      X : Long_Float := 0.0;
   begin
      This.Elapsed := To_Duration (Reading - This.Started);
      if O.Time_Limit > 0.0 then
         X := Long_Float (This.Elapsed) / Long_Float (O.Time_Limit);
         This.Stop := This.Stop
           or else This.Elapsed >= O.Time_Limit * (if O.Polish then 0.97 else 1.0);
      end if;
      if O.Iterations > 0 then
         X := Long_Float'Max (X, Long_Float (This.Moves) / Long_Float (O.Iterations));
         This.Stop := This.Stop or else This.Moves >= O.Iterations;
      end if;
      if O.Convergence > 0 then
         This.Stop := This.Stop or else
           (This.Moves - This.Last_Best_Move >= O.Convergence
            and then (O.Time_Limit > 0.0 or else O.Iterations > 0
                      or else This.Moves >= 10 * O.Convergence));
         --  Alone, it applies once the schedule is half way down.
         if O.Time_Limit <= 0.0 and then O.Iterations <= 0 then
            --  Convergence only: cool over 20 stagnation windows.
            X := Long_Float (This.Moves) / (20.0 * Long_Float (O.Convergence));
         end if;
      end if;
      return X;
   end Budget_Used;

   --  Geometric: T0 -> T1 over each of Runs independent runs sharing the
   --  budget (their number decided after 2% of it when automatic).
   procedure Geometric_Step (This : in out Search; P : Problem; X : Long_Float) is
      T0 : constant Long_Float := This.Start_Temperature;
      T1 : constant Long_Float := This.End_Temperature;
      Run_Share : Long_Float;
   begin
      if not This.Runs_Decided and then X >= 0.02 then
         --  As many runs (at most Max_Runs) as the budget gives
         --  Opts.Run_Moves x tasks ** 2 moves each.
         This.Runs_Decided := True;
         This.Runs := Positive (Long_Float'Max (1.0, Long_Float'Min
           (Long_Float (Max_Runs), Long_Float'Floor
              (Long_Float (This.Moves) / X
               / (This.Opts.Run_Moves * Long_Float (P.Tasks) ** 2)))));
      end if;
      Run_Share := X * Long_Float (This.Runs) - Long_Float (This.Run);
      if Run_Share >= 1.0 and then This.Run + 1 < This.Runs then
         if not This.Best_Saved then
            Save_Best (This);
         end if;
         This.Run := Natural'Min (This.Runs - 1, Natural (Long_Float'Floor
                                                            (X * Long_Float (This.Runs))));
         Construct (P, This.Tours.all, This.Opts.Criterion, This.Generator);
         Check (This, P);
         Restart_From_Current (This, P);
         Run_Share := X * Long_Float (This.Runs) - Long_Float (This.Run);
      end if;
      This.Temperature := T0 * (T1 / T0) ** Long_Float'Min (1.0, Run_Share);
   end Geometric_Step;

   --  Cyclic: cycles of geometric cooling; each new cycle restarts from the
   --  best so far, at a start temperature divided by Cycle_Drop per cycle.
   procedure Cyclic_Step (This : in out Search; P : Problem; X : Long_Float) is
      T0 : constant Long_Float := This.Start_Temperature;
      T1 : constant Long_Float := This.End_Temperature;
      C : constant Long_Float := X * Long_Float (This.Opts.Cycles);
      K : constant Natural :=
        Natural (Long_Float'Min (Long_Float (This.Opts.Cycles - 1), Long_Float'Floor (C)));
      F : constant Long_Float := Long_Float'Min (1.0, C - Long_Float (K));
      Cycle_Start : constant Long_Float := Long_Float'Max (T1, T0 / This.Opts.Cycle_Drop ** K);
   begin
      if K /= This.Cycle then
         This.Cycle := K;
         if not This.Best_Saved then
            Save_Best (This);
         end if;
         Load (P, This.Tours.all, This.Best);
         Restart_From_Current (This, P);
      end if;
      This.Temperature := Cycle_Start * (T1 / Cycle_Start) ** F;
   end Cyclic_Step;

   --  Reheat: divide the temperature by 1.85 after a stretch without
   --  improvement, back to T0 after a long stretch without a new best.
   procedure Reheat_Step (This : in out Search) is
   begin
      if This.Since_Improve > 20_000 then
         This.Reheat_Temperature :=
           Long_Float'Max (This.End_Temperature, This.Reheat_Temperature / 1.85);
         This.Since_Improve := 0;
         This.Cycle_Best := This.Current;
      end if;
      if This.Moves - This.Last_Best_Move > 1_000_000
        and then This.Reheat_Temperature <= This.End_Temperature
      then
         This.Reheat_Temperature := This.Start_Temperature;
         This.Last_Best_Move := This.Moves;
      end if;
      This.Temperature := This.Reheat_Temperature;
   end Reheat_Step;

   --  Hybrid: Geometric over the first Geometric_Share of the budget, then
   --  Reheat from the best so far, starting at T1 (back to T0 only after
   --  the reheat schedule's long stretch without a new best), without the
   --  excess term unless Opts.Excess_In_Reheats.
   procedure Hybrid_Step (This : in out Search; P : Problem; X : Long_Float) is
      Share : constant Long_Float := This.Opts.Geometric_Share;
   begin
      if This.Automatic_Hybrid then
         --  Chosen by Automatic: kept only if the budget leaves the reheats
         --  Reheat_Phase_Moves (estimated from the moves so far), else the
         --  geometric schedule over the whole budget, which also runs until
         --  that is decided (so a short budget anneals exactly as Geometric).
         if X >= 0.02 * Share and then X > 0.0 then
            This.Automatic_Hybrid := False;
            if Long_Float (This.Moves) / X * (1.0 - Share) < Reheat_Phase_Moves then
               This.Opts.Schedule := Geometric;
            end if;
         end if;
         if This.Automatic_Hybrid or else This.Opts.Schedule = Geometric then
            Geometric_Step (This, P, X);
            return;
         end if;
      end if;
      if X < Share then
         Geometric_Step (This, P, X / Share);
         return;
      end if;
      if not This.Reheating then
         This.Reheating := True;
         if This.Excess_Floor and then not This.Opts.Excess_In_Reheats then
            --  The reheats anneal on the makespan itself (Current is
            --  recomputed below).
            This.Excess_Floor := False;
            This.Guide.Square := 0.0;
         end if;
         if not This.Best_Saved then
            Save_Best (This);
         end if;
         Load (P, This.Tours.all, This.Best);
         Check (This, P);
         Restart_From_Current (This, P);
         This.Reheat_Temperature := This.End_Temperature;
         This.Cycle_Best := This.Current;
         This.Since_Improve := 0;
         This.Last_Best_Move := This.Moves;
      end if;
      Reheat_Step (This);
   end Hybrid_Step;

   procedure Adapt_Weights (This : in out Search) is
   begin
      for M in Move_Kind loop
         if This.Tries (M) > 0.0 and then This.Weight (M) > 0.0 then
            This.Weight (M) := 0.8 * This.Weight (M) + 0.2 * Long_Float'Max
              (0.05, 20.0 * This.Score (M) / This.Tries (M));
         end if;
         This.Score (M) := 0.0;
         This.Tries (M) := 0.0;
      end loop;
      This.Weight_Total := Sum_Of (This.Weight);
   end Adapt_Weights;

   --  Everything done every 128 moves: budget, balance decay, temperature,
   --  reports, move weights.
   procedure Checkpoint (This : in out Search; P : Problem) is
      Reading : constant Time := Now (This);
      X   : Long_Float := Budget_Used (This, Reading);
   begin
      if This.Stop then
         return;
      end if;
      X := Long_Float'Min (1.0, X);
      if This.Initial_Balance > This.Goal.Tie and then This.Opts.Balance_Decay then
         This.Guide.Tie := Long_Float'Max
           (This.Goal.Tie, This.Initial_Balance * (This.Goal.Tie / This.Initial_Balance) ** X);
         Restart_From_Current (This, P);
      end if;
      case This.Opts.Schedule is
         when Geometric => Geometric_Step (This, P, X);
         when Cyclic    => Cyclic_Step (This, P, X);
         when Reheat    => Reheat_Step (This);
         when Hybrid    => Hybrid_Step (This, P, X);
         when Automatic => raise Program_Error with "schedule not resolved";
      end case;
      if Reading >= This.Next_Report then
         This.Next_Report := Reading + To_Time_Span (This.Opts.Report_Every);
         Send_Report (This);
      end if;
      if This.Opts.Adaptive and then This.Moves mod 8192 = 0 and then This.Moves > 0 then
         Adapt_Weights (This);
      end if;
   end Checkpoint;

   procedure Anneal (This : in out Search; P : Problem) is
   begin
      loop
         if This.Moves mod 128 = 0 then
            Checkpoint (This, P);
            exit when This.Stop;
         end if;
         This.Moves := This.Moves + 1;
         if This.Route_Searches and then This.Moves >= This.Next_Route_Search then
            This.Next_Route_Search :=
              This.Moves + Route_Search_Interval * Long_Long_Integer (P.Tasks);
            Search_Routes (This, P);
         elsif Ruin_Due (This) then
            Ruin_And_Recreate (This, P);
            --  A target reached here stops at the next checkpoint.
         elsif Chain_Due (This) then
            Run_Chain (This, P);
         else
            Try_Move (This, P);
            exit when This.Stop;
         end if;
      end loop;
   end Anneal;

   ---------------------------------------------------------------------------
   --  The end.

   --  Local descent with the neighbour moves until no improvement (or time).
   procedure Polish (This : in out Search; P : Problem) is
      S : State renames This.Tours.all;
      K : constant Positive := This.Neighbours;
      Improved : Boolean := True;
      Mv : Move;
      Ok : Boolean;
      Rounds : Natural := 0;
   begin
      while Improved and then Rounds < 50 loop
         Improved := False;
         Rounds := Rounds + 1;
         for T in 1 .. P.Tasks loop
            if This.Opts.Time_Limit > 0.0 and then T mod 16 = 0
              and then To_Duration (Now (This) - This.Started) > This.Opts.Time_Limit * 1.02
            then
               return;
            end if;
            if Movable (P, S, T) then
               for U_Index in 1 .. K loop
                  declare
                     U : constant Natural := Placed_Neighbour (S, T, U_Index);
                  begin
                     for V in 0 .. 13 + 2 * K loop
                        exit when U = 0 or else not Movable (P, S, T);
                        if V < 8 then
                           Or_Opt (P, S, T, U, 1 + V / 4 * 2, V mod 4, Mv, Ok);
                        elsif V < 12 then
                           Two_Opt (P, S, T, U, V mod 4, Mv, Ok);
                        elsif V < 14 then
                           Cross_Exchange (P, S, T, U, 1, (V mod 2), Mv, Ok);
                        else
                           Or_3opt (P, S, T, U, 1 + (V - 14) / 2, V mod 2, Mv, Ok);
                        end if;
                        Mv.Switch_Task := 0;
                        if Ok then
                           Evaluate_Move (P, S, This.Guide, Mv, Ok);
                           if Ok and then Mv.Value < This.Current - 1.0E-9 then
                              Apply_Move (This, P, Mv);
                              Restart_From_Current (This, P);
                              Improved := True;
                           end if;
                        end if;
                     end loop;
                  end;
               end loop;
            end if;
         end loop;
      end loop;
   end Polish;

   --  Makespan criteria: ejection chains until none lowers the objective
   --  (or the time is up), then the neighbour moves' descent again.
   procedure Chain_Descent (This : in out Search; P : Problem) is
      Improved : Boolean := True;
      Any : Boolean := False;
      Unused : Long_Long_Integer := 0;
   begin
      while Improved loop
         exit when This.Opts.Time_Limit > 0.0
           and then To_Duration (Now (This) - This.Started) > This.Opts.Time_Limit * 1.02;
         Chains.Ejection_Chain (P, This.Tours.all, This.Guide, This.Chain_Space.all,
                                This.Opts.Check, Improved, Unused);
         Any := Any or else Improved;
      end loop;
      if Any then
         Restart_From_Current (This, P);
         Polish (This, P);
      end if;
   end Chain_Descent;

   procedure Finish
     (This : in out Search; P : Problem; Best : in out Assignment; Stats : out Progress) is
   begin
      if not This.Best_Saved then
         Save_Best (This);
      end if;
      This.Guide := This.Goal;
      if This.Opts.Polish then
         Load (P, This.Tours.all, This.Best);
         Restart_From_Current (This, P);
         Polish (This, P);
         if This.Chain_Space /= null then
            Chain_Descent (This, P);
         end if;
         This.Polish_Gain := Long_Float'Max (0.0, This.Best_Value - This.Current);
         if This.Current < This.Best_Value then
            This.Best_Value := This.Current;
            This.Best_Time := To_Duration (Now (This) - This.Started);
            Store (This.Tours.all, This.Best);
         end if;
      end if;
      Load (P, This.Tours.all, This.Best);
      This.Elapsed := To_Duration (Now (This) - This.Started);
      This.Best_Value := True_Value (This);
      This.Current := This.Best_Value;
      Send_Report (This);
      Best := This.Best;
      Stats := Statistics (This);
   end Finish;

end Sancta.Allocation.Annealers.Searches;
