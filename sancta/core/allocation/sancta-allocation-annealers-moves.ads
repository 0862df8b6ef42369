--  Moves as segment lists: a move is described as at most two new tours,
--  each a short list of segments of the current tours (forward or
--  reversed) and single tasks, so its exact cost change (length,
--  completion times, infeasibility) is computed in O(segments) from the
--  prefix sums of Tours.State without applying it.
--
--     Clear (Mv);  Mv.A.Robot := R;
--     Add (Mv.A, R, 1, I - 1);  Add (Mv.A, R, I, J, Reversed => True);
--     Add (Mv.A, R, J + 1, S.Length (R));       --  2-opt on robot R
--     Evaluate_Move (P, S, W, Mv, Ok);          --  Mv.Value: the objective after it
--     if Ok and then Mv.Value < Current_Value (P, S, W) then Apply (P, S, Mv); end if;
with Sancta.Allocation.Annealers.Tours; use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Moves is

   type Segment_Kind is (Span, Single);
   type Segment is record
      Kind     : Segment_Kind;
      Robot    : Positive;
      First    : Natural;
      Last     : Natural;
      Reversed : Boolean;
      --  Span: positions First .. Last of Robot's current tour.
      Task_Id  : Natural;   --  Single: this task ...
      Location : Natural;   --  ... at this location
   end record;
   --  No default values: a tour plan only reads its first Count segments,
   --  and moves are built millions of times a second.

   Max_Segments : constant := 6;
   type Segment_List is array (1 .. Max_Segments) of Segment;

   type Tour_Plan is record
      Robot    : Natural := 0;      --  0 = unused
      Segments : Segment_List;
      Count    : Natural := 0;
   end record;
   --  A robot's new tour.

   type Move is record
      A, B        : Tour_Plan;
      Switch_Task : Natural := 0;   --  OR switch: task and its new choice
      Switch_To   : Natural := 0;
      Or_Node     : Natural := 0;
      --  Switch subtree: the OR ordinal switched (the move's new tours are
      --  in a Plan_Trees.Pending record, its costs already evaluated).
      New_Active  : Natural := 0;
      New_A_Cost, New_B_Cost : Cost := 0;
      New_A_Completion, New_B_Completion : Cost := 0;
      Completion_Known : Boolean := True;
      --  False: Evaluate_Move left the sums of completion times (New_A_,
      --  New_B_Completion, New_Completion) at 0, its criterion having no
      --  mean (Value does not read them); Verify then does not compare them.
      --  Two prefix-sum loads per span saved: CPU at a fixed move budget
      --  (release, MinMax, min of 3 runs, plans identical) -2.1 / -2.7 /
      --  -5.4% at 300 / 500 / 1000 tasks x 10 robots, -2.6 / -2.4 / -2.3%
      --  x 5.
      New_A_Length, New_B_Length : Natural := 0;
      New_Max, New_Sum, New_Completion : Cost := 0;
      New_Square  : Long_Float := 0.0;
      --  The sum of squared robot costs (only when the weights use it).
      Value       : Long_Float := 0.0;
      --  The search objective after the move.
   end record;

   procedure Clear (Mv : in out Move) with Inline;
   --  No tour, no subtree switch.

   function No_Move return Move;
   --  A move of no tour (for Verify without a prediction).

   procedure Add (T : in out Tour_Plan; Robot : Positive; First, Last : Natural;
                  Reversed : Boolean := False) with Inline;
   --  Appends Robot's positions First .. Last (nothing when empty).

   procedure Add_Single (T : in out Tour_Plan; Task_Id, Location : Positive) with Inline;

   type Weights is record
      C   : Criterion;
      Tie : Long_Float := 0.0;  --  weight of the total cost added to break MinMax ties
      Square : Long_Float := 0.0;
      --  Weight of the sum of squared robot costs: a makespan search's
      --  balance term (each robot's cost counts by its size, so every long
      --  tour, not only the longest, is pushed down).
   end record;
   --  A search objective: the criterion and its tie-break / balance terms.

   function Objective (W : Weights; Max, Sum, Completion : Cost; Tasks : Natural;
                       Square : Long_Float := 0.0)
     return Long_Float
   is (Value (W.C, Max, Sum, Completion, Tasks) + W.Tie * Long_Float (Sum)
       + W.Square * Square);

   function Current_Value (P : Problem; S : State; W : Weights) return Long_Float is
     (Objective (W, Current_Max (S), S.Total_Cost, S.Total_Completion,
                 Natural'Min (S.Active_Tasks, P.Tasks), S.Total_Square));

   function Make_Weights (P : Problem; C : Criterion; Scale_Sum : Cost) return Weights;
   --  C, and for a pure makespan with several robots a tie-break so small
   --  (against Scale_Sum) that it never trades a unit of makespan.

   procedure Evaluate_Move
     (P : Problem; S : State; W : Weights; Mv : in out Move; Valid : out Boolean);
   --  The new costs and Value of Mv; Valid False when a robot would fall
   --  below the minimum task count. The sums of completion times only when
   --  W.C has a mean (Ave_Weight /= 0.0): Mv.Completion_Known.

   procedure Apply (P : Problem; S : in out State; Mv : Move);
   --  Installs the new tours of Mv (not a subtree switch).

   procedure Verify (P : Problem; S : State; Mv : Move; Predicted : Boolean);
   --  The expensive check: all costs recomputed from scratch and compared
   --  with the incremental ones (and with Mv's prediction if Predicted);
   --  Program_Error on any difference.

end Sancta.Allocation.Annealers.Moves;
