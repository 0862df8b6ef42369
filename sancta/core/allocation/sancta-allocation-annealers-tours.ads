--  The annealer's current solution: one tour per robot held in arrays with
--  prefix sums of forward and reverse arc costs and of arrival times, the
--  robots' costs, their total and (in a max segment tree) their maximum,
--  the position of every task, and the candidate neighbours of every task.
--
--     S : State_Access := new State (P.Robots, P.Tasks, K, P.Tasks + 1, 2 * P.Robots);
--     Compute_Neighbours (P, S.all);
--     Load (P, S.all, A);        --  from an allocation; Store writes one back
--     S.Task_At (R, I) := T;  Rebuild (P, S.all, R, From => I);
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Random;

private package Sancta.Allocation.Annealers.Tours is

   subtype Generator is Sancta.Allocation.Random.Generator;

   type Position_Grid is array (Positive range <>, Natural range <>) of Natural;
   type Cost_Grid is array (Positive range <>, Natural range <>) of Cost;
   type Neighbour_Grid is array (Positive range <>, Positive range <>) of Natural;

   type Narrow_Cost is range 0 .. 2 ** 16 - 1 with Size => 16;
   type Wide_Cost is range 0 .. 2 ** 31 - 1 with Size => 32;
   type Narrow_Matrix is array (Natural range <>) of Narrow_Cost;
   type Wide_Matrix is array (Natural range <>) of Wide_Cost;
   type Index_Table is array (Natural range <>) of Natural;
   type Narrow_Access is access Narrow_Matrix;
   type Wide_Access is access Wide_Matrix;
   type Index_Access is access Index_Table;

   type Compact_Distances is record
      Narrow : Narrow_Access;
      Wide   : Wide_Access;
      --  At most one of them: the distances in 16 bits when they all fit,
      --  else in 32 bits when they fit (null, null: read the problem).
      Row, Column : Index_Access;
      --  The distance From -> To is at Row (From) + Column (To).
   end record;
   --  A compact copy of a problem's shared distance matrix for the hot loops
   --  of the annealer (Evaluate_Tour, Rebuild): the same integers in a
   --  quarter or half of the bytes. Locations are ranked along a Hilbert
   --  curve of their coordinates (when they have some) and the matrix is
   --  stored in 16 x 16 tiles, so that near locations' rows and columns
   --  share cache lines and pages. Measured (release build, 10 robots,
   --  1-2 M moves, two runs beside the 64-bit reads; plans identical):
   --  CPU -17% at 300 tasks, -26% at 500, -30% at 1000, with the route
   --  search's own matrix (Local_Search); of which 32 bits in location
   --  order alone gave -10% / -12% at 300 / 1000, 16 bits -8% more, the
   --  Hilbert order -12% more at 1000 (about 0 at 300-500).

   Compact_Limit : constant := Matrix_Limit;
   --  Problems of at most this many locations get a compact copy (2 MB in
   --  16 bits at 1000 locations, beside the problem's 8 MB); larger ones
   --  have no matrix (computed Euclidean distances: memory O (n) kept) or
   --  one of their own too big to copy.

   function Compact_Matrix (P : Problem) return Compact_Distances;
   --  The compact copy of P's distances when no robot has costs of its own,
   --  P has a matrix of at most Compact_Limit locations and every distance
   --  fits in 32 bits (location 0 included); all null otherwise.

   procedure Free (C : in out Compact_Distances);

   type State (Robots, Tasks, Neighbours, Positions, Tree_Size : Positive) is record
      --  Positions = Tasks + 1, Tree_Size = 2 Robots (discriminants must
      --  appear alone in component constraints).
      Compact         : Compact_Distances;
      --  Compact_Matrix (P) or nothing, shared with its owner (Searches),
      --  which frees it; first in the record for a fixed offset.
      Task_At         : Position_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      --  The task at each position 1 .. Length of each robot's tour.
      Location_At     : Position_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      --  Location at each position; 0 = start, Length + 1 = finish.
      Forward_Cost    : Cost_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      --  Base cost from the start to each position, forward.
      Backward_Cost   : Cost_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      --  Backward_Cost (I) = sum over K < I of D (Location_At (K + 1),
      --  Location_At (K)): the same arcs travelled in reverse.
      Forward_Sum     : Cost_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      Backward_Sum    : Cost_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      --  Prefix sums of Forward_Cost and Backward_Cost over positions 1 .. I.
      Length          : Count_Array (1 .. Robots) := [others => 0];
      Infeasible      : Count_Array (1 .. Robots) := [others => 0];
      --  Tasks in the tour that the robot cannot do.
      Owner           : Count_Array (1 .. Tasks) := [others => 0];
      Position        : Count_Array (1 .. Tasks) := [others => 0];
      Choice          : Location_Array (1 .. Tasks) := [others => 1];
      --  Where each task is (Owner 0: not in a tour) and which of its
      --  alternative locations it uses.
      Robot_Cost      : Cost_Array (1 .. Robots) := [others => 0];
      Robot_Completion : Cost_Array (1 .. Robots) := [others => 0];
      --  Tour cost and sum of completion times (times the multiplier,
      --  Infinity per infeasible task).
      Total_Cost, Total_Completion : Cost := 0;
      Square_Floor    : Cost := 0;
      Total_Square    : Long_Float := 0.0;
      --  The sum over robots of Square_Of (S, robot cost): squared excess
      --  over Square_Floor (the makespan search's balance term,
      --  Moves.Weights.Square; Set_Square_Floor changes the floor).
      Max_Tree        : Cost_Array (1 .. Tree_Size) := [others => 0];
      --  Robot costs in a max segment tree: leaves Robots .. 2 Robots - 1.
      Top             : Count_Array (1 .. 3) := [1, 2, 3];
      --  With 3 .. Top_Robots robots: the robots of the three largest
      --  costs, largest first (Max_Except reads them instead of the tree).
      Near            : Neighbour_Grid (1 .. Tasks, 1 .. Neighbours) :=
        [others => [others => 0]];
      Near_Count      : Count_Array (1 .. Tasks) := [others => 0];
      --  The candidate neighbours of each task, nearest first.
      Selection       : Location_Array (1 .. Tasks) := [others => 1];
      --  Plan trees: the alternative chosen at each OR ordinal ...
      Active          : Boolean_Array (1 .. Tasks) := [others => True];
      --  ... the tasks it makes active (only they are in tours; Owner = 0
      --  for the others) ...
      Active_Tasks    : Natural := Tasks;
      --  ... and their number.
   end record;

   type State_Access is access State;
   procedure Free is new Ada.Unchecked_Deallocation (State, State_Access);

   function New_State (P : Problem; Neighbours : Positive) return State_Access
   is (new State (P.Robots, P.Tasks, Neighbours, P.Tasks + 1, 2 * P.Robots));

   function Arc (P : Problem; S : State; R : Positive; From, To : Natural) return Cost
   is (if S.Compact.Narrow /= null
       then Cost (S.Compact.Narrow (S.Compact.Row (From) + S.Compact.Column (To)))
       elsif S.Compact.Wide /= null
       then Cost (S.Compact.Wide (S.Compact.Row (From) + S.Compact.Column (To)))
       else Robot_Distance (P, R, From, To))
     with Inline;
   --  Robot_Distance (P, R, From, To), from S.Compact when there is one
   --  (then no robot has costs of its own).

   function Square_Of (S : State; C : Cost) return Long_Float is
     (if Is_Infinite (C) or else C <= S.Square_Floor then 0.0
      else Long_Float (C - S.Square_Floor) ** 2) with Inline;
   --  The square of a robot cost's excess over S.Square_Floor (the cost
   --  squared with the floor 0); 0 for an infeasible tour (its 2 ** 80
   --  would swallow the other robots' terms in a running sum).
   --  Example: floor 900, costs 1000 and 800: 100 ** 2 + 0 = 10_000.

   procedure Set_Square_Floor (S : in out State; Floor : Cost)
     with Post => S.Square_Floor = Floor;
   --  A new floor; Total_Square recomputed (O (robots)).

   Top_Robots : constant := 32;
   --  Up to this many robots, every tree update also rescans the three
   --  largest costs (O (robots)), and Max_Except takes the first of them
   --  that is not A or B: three comparisons instead of three walks of the
   --  tree (which took 8% of a 10-robot, 300-task makespan anneal).

   function Max_Except (S : State; A, B : Natural) return Cost with Inline;
   --  The largest robot cost but those of robots A and B (0: none).

   function Current_Max (S : State) return Cost is (S.Max_Tree (1));
   --  The makespan (with one robot the single leaf is Max_Tree (1) itself).

   procedure Rebuild
     (P : Problem; S : in out State; R : Positive; From : Positive;
      Same_From : Positive := Positive'Last; Shift : Integer := 0)
     with Pre => Same_From = Positive'Last
                 or else (Same_From > From and then Same_From <= S.Length (R) + 1
                          and then Same_From - 1 + Shift >= 1);
   --  Recomputes the caches of robot R from position From on (its tasks in
   --  Task_At (R, 1 .. Length (R))), its costs, the totals and the tree.
   --  When the new tour ends with a piece of the old one (Moves.Apply):
   --  the tasks at positions Same_From - 1 .. Length (R) were at the old
   --  positions Same_From - 1 + Shift .. Length (R) + Shift, in the same
   --  order, and the caches still hold the old tour there. The arcs into
   --  Same_From .. Length (R) + 1 (the finish) are then the old ones: their
   --  prefix sums are moved and offset instead of read again from the
   --  distances (each position's own task and location lookups and two
   --  matrix reads saved; Moves.Verify checks every cache under Check).

   procedure Cost_From_Scratch
     (P : Problem; R : Positive; Task_At : Position_Grid; Length : Natural;
      Choice : Location_Array; Tour_Cost, Completion : out Cost);
   --  The cost and the sum of completion times (times the multiplier,
   --  Infinity per task R cannot do) of robot R's tour Task_At (R, 1 ..
   --  Length), each task at its Choice, arc by arc without prefix sums: what
   --  Rebuild's caches and the moves' predictions must agree with.

   procedure Compute_Neighbours (P : Problem; S : in out State);
   --  The Neighbours nearest tasks of each task (by the shorter direction).

   procedure Load (P : Problem; S : in out State; A : Assignment);
   procedure Store (S : State; A : in out Assignment);
   --  From / to an allocation.

   function Movable (P : Problem; S : State; T : Positive) return Boolean is
     (S.Owner (T) /= 0 and then S.Position (T) > P.Frozen_Length (S.Owner (T)));
   --  Active (in a tour) and not frozen.

   procedure Shuffle (G : in out Generator; Items : in out Count_Array; Last : Natural)
     with Pre => Items'First = 1 and then Last <= Items'Last;
   --  Fisher-Yates shuffle of Items (1 .. Last).

end Sancta.Allocation.Annealers.Tours;
