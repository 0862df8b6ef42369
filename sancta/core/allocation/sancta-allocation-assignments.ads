--  An allocation: each robot's ordered tour of tasks, for each task the
--  alternative location chosen for it, and for each OR node of the plan
--  tree the alternative chosen there (which fixes the active tasks); and
--  its evaluation from scratch (the reference
--  the annealer's incremental costs are checked against).
--
--     A : Assignment := Empty (P.all);  --  frozen prefixes only
--     Append (A, Robot => 1, T => 3);
--     E : constant Evaluation := Evaluate (P.all, A, Min_Max);
with Sancta.Allocation.Problems; use Sancta.Allocation.Problems;

package Sancta.Allocation.Assignments is

   type Tour_Matrix is array (Positive range <>, Positive range <>) of Natural;
   type Cost_Array is array (Positive range <>) of Cost;

   type Assignment (Robots : Positive; Tasks : Positive) is record
      Tour   : Tour_Matrix (1 .. Robots, 1 .. Tasks) := [others => [others => 0]];
      Length : Count_Array (1 .. Robots) := [others => 0];
      Choice : Location_Array (1 .. Tasks) := [others => 1];
      Branch : Location_Array (1 .. Tasks) := [others => 1];
      --  The alternative chosen at each OR ordinal of the plan tree.
   end record;

   function Empty (P : Problem) return Assignment;
   --  Every robot with its frozen prefix only; every choice the first,
   --  every OR node at its first alternative (or the one holding a frozen
   --  task).

   procedure Append (This : in out Assignment; Robot, T : Positive)
     with Pre => This.Length (Robot) < This.Tasks;

   procedure Insert (This : in out Assignment; Robot, T : Positive; After : Natural)
     with Pre => After <= This.Length (Robot) and then This.Length (Robot) < This.Tasks;

   function Assigned (This : Assignment) return Natural;
   --  Number of task slots used.

   type Evaluation (Robots : Positive) is record
      Robot_Cost       : Cost_Array (1 .. Robots);
      --  Tour cost of each robot (Infinity per infeasible task).
      Robot_Completion : Cost_Array (1 .. Robots);
      --  Sum of the task completion times of each robot.
      Max, Sum, Completion_Sum : Cost := 0;
      Active           : Natural := 0;
      --  Number of active tasks (the mean completion time is over them).
      Value            : Long_Float := 0.0;
   end record;

   function Evaluate
     (P : Problem; This : Assignment; C : Criterion) return Evaluation;
   --  Costs recomputed from scratch.

   function Tour_Cost
     (P : Problem; This : Assignment; Robot : Positive) return Cost;

   function Insertion_Cost
     (P : Problem; This : Assignment; Robot : Positive; Location : Natural; After : Natural)
     return Cost
     with Pre => After <= This.Length (Robot);
   --  What a stop at Location after position After (0: first) of Robot's
   --  tour adds to its cost: the detour times the robot's multiplier.

   function Validate (P : Problem; This : Assignment) return String;
   --  "" when complete (each active task exactly once, no inactive one), frozen prefixes kept,
   --  choices valid, every robot has P.Min_Tasks tasks and all costs are
   --  finite; else the first problem found.

end Sancta.Allocation.Assignments;
