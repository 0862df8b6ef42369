--  The allocation problem: locations with an exact (possibly asymmetric)
--  distance matrix, tasks placed at one location or at one of several
--  alternative locations (a one-level OR: the planner chooses), a plan tree
--  of AND / OR nodes over the tasks (an OR alternative may be a subtree of
--  several tasks: a compound task; the choice at every OR node fixes the
--  active task set), robots with a start location, closed or open tours, a
--  cost multiplier and optionally a cost function of their own (an explicit
--  matrix, a callback or a factor over the shared matrix: heterogeneous
--  teams), infeasible robot/task pairs, frozen tour prefixes (tasks already
--  done or under way, for online re-planning), and the minimum number of
--  tasks per robot (1 in the classic mTSP).
--
--     P : constant Problem_Access := Create (Locations => 3, Tasks => 2, Robots => 1);
--     Set_Distance (P.all, 1, 2, 10); ...
--     Set_Task (P.all, 1, Location => 2);
--     Set_Robot (P.all, 1, Start => 1, Closed => True);
--     Add_Node (P.all, Or_Node, Parent => 0, Node => O);   --  plan: 1 or 2
--     Add_Plan_Task (P.all, O, 1);  Add_Plan_Task (P.all, O, 2);
--
--  Tasks outside the plan tree are always active (the root is an implicit
--  AND). Problems are built once and read-only afterwards.
--
--  Distances: read them with Distance (P, From, To) (Robot_Distance for a
--  robot's own costs). They come from an n x n matrix (8 bytes per pair:
--  1000 locations 8 MB, 5000 locations 200 MB) or, for Euclidean problems
--  (Set_Euclidean, TSPLIB EUC_2D / CEIL_2D) of more than Matrix_Limit
--  locations, are computed from the coordinates with the same rounding
--  (memory O(n)). Set_Distance on a computed problem turns it into a matrix.
--
--  Known limits: compound tasks with distinct entry and exit points are
--  modelled as their entry location plus an inner length folded into the
--  matrix by the caller; every task must be feasible for some robot even
--  when it sits in an alternative never chosen; at most Tasks OR nodes.
with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Numerics.Long_Elementary_Functions;
with Sancta.Geometry;

package Sancta.Allocation.Problems is

   type Cost_Matrix is array (Natural range <>, Natural range <>) of Cost;
   type Location_Array is array (Positive range <>) of Natural;
   type Count_Array is array (Positive range <>) of Natural;
   type Boolean_Matrix is array (Positive range <>, Positive range <>) of Boolean;
   type Boolean_Array is array (Positive range <>) of Boolean;
   type Point_Array is array (Positive range <>) of Sancta.Geometry.Point;
   type Task_Matrix is array (Positive range <>, Positive range <>) of Natural;
   type Cost_Matrix_Access is access Cost_Matrix;
   type Robot_Matrices is array (Positive range <>) of Cost_Matrix_Access;
   type Factor_Array is array (Positive range <>) of Long_Float;

   type Distance_Rule is (From_Matrix, Euclidean_Nearest, Euclidean_Floor, Euclidean_Ceiling);
   --  Where distances come from: the matrix, or Scale x the Euclidean
   --  distance of the coordinates rounded to the nearest integer (TSPLIB
   --  nint), down or up (TSPLIB CEIL_2D).

   Matrix_Limit : constant := 1000;
   --  Euclidean problems of more locations have no matrix (computed
   --  distances; a matrix of 1000 locations is 8 MB and is read from memory
   --  at about the cost of a square root).

   type Node_Kind is (Task_Node, And_Node, Or_Node);
   type Plan_Node is record
      Kind        : Node_Kind := And_Node;
      Task_Id     : Natural := 0;    --  Task_Node: its task
      Parent      : Natural := 0;    --  0: the implicit root AND
      First_Child : Natural := 0;
      Last_Child  : Natural := 0;
      Next        : Natural := 0;    --  next sibling
      Children    : Natural := 0;
      Or_Anc      : Natural := 0;
      --  Ordinal of the nearest OR ancestor (0: none) ...
      Branch      : Natural := 0;
      --  ... and the alternative of it this node lies in (1 .. its Children).
      Or_Index    : Natural := 0;    --  Or_Node: its ordinal
   end record;
   --  One node of the plan tree (nodes are numbered from 1 in creation order).

   package Node_Vectors is new Ada.Containers.Vectors (Positive, Plan_Node);
   package Natural_Vectors is new Ada.Containers.Vectors (Positive, Natural);
   package Name_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   type Problem
     (Locations    : Positive;
      Tasks        : Positive;
      Robots       : Positive;
      Alternatives : Positive)
   is limited record
      Rule           : Distance_Rule := From_Matrix;
      Matrix         : Cost_Matrix_Access;
      --  From_Matrix: the base distances, (0 .. Locations, 0 .. Locations)
      --  (null: all 0); location 0 is "nowhere", at distance 0 from
      --  everything: the end of an open tour. Read through Distance.
      Symmetric      : Boolean := True;
      Coordinates    : Point_Array (1 .. Locations) := [others => (0.0, 0.0)];
      Has_Coordinates : Boolean := False;
      Scale          : Long_Float := 1.0;
      --  Costs are real values times Scale (fixed point); 1.0 for integers.
      Alt_First      : Location_Array (1 .. Tasks) := [others => 1];
      Alt_Count      : Location_Array (1 .. Tasks) := [others => 1];
      Alt_Location   : Location_Array (1 .. Alternatives) := [others => 1];
      Next_Alt       : Positive := 1;
      Start          : Location_Array (1 .. Robots) := [others => 1];
      Finish         : Location_Array (1 .. Robots) := [others => 1];
      --  Where the tour ends: the start for a closed tour, "nowhere" else.
      Multiplier     : Count_Array (1 .. Robots) := [others => 1];
      Can_Do         : Boolean_Matrix (1 .. Robots, 1 .. Tasks) :=
        [others => [others => True]];
      All_Feasible   : Boolean := True;
      Frozen         : Task_Matrix (1 .. Robots, 1 .. Tasks) :=
        [others => [others => 0]];
      Frozen_Length  : Count_Array (1 .. Robots) := [others => 0];
      Is_Frozen      : Boolean_Array (1 .. Tasks) := [others => False];
      Min_Tasks      : Natural := 0;
      --  Every robot must do at least this many tasks (mTSP: 1).
      Name           : String (1 .. 32) := [others => ' '];
      Own            : Robot_Matrices (1 .. Robots) := [others => null];
      --  A robot's own base distances (null: the shared ones, times
      --  Own_Factor when that is > 0).
      Own_Factor     : Factor_Array (1 .. Robots) := [others => 0.0];
      Plan           : Node_Vectors.Vector;
      Or_Nodes       : Natural_Vectors.Vector;
      --  The node of each OR ordinal.
      Task_Or        : Location_Array (1 .. Tasks) := [others => 0];
      Task_Branch    : Location_Array (1 .. Tasks) := [others => 0];
      --  Nearest OR ancestor of each task and the alternative it lies in.
      In_Plan        : Boolean_Array (1 .. Tasks) := [others => False];
      Task_Names     : Name_Vectors.Vector;
      Or_Names       : Name_Vectors.Vector;
      --  Optional labels of the tasks and OR ordinals (mission files).
   end record;

   type Problem_Access is access Problem;

   function Create
     (Locations, Tasks, Robots : Positive; Alternatives : Natural := 0)
      return Problem_Access;
   --  A problem with all distances 0, task T at location T, room for
   --  Alternatives extra OR alternatives, robots starting at location 1 on
   --  closed tours.

   Nowhere : constant := 0;

   function Euclidean_Length (A, B : Sancta.Geometry.Point) return Long_Float
   is (Ada.Numerics.Long_Elementary_Functions.Sqrt
         ((Long_Float (A.X) - Long_Float (B.X)) * (Long_Float (A.X) - Long_Float (B.X))
          + (Long_Float (A.Y) - Long_Float (B.Y)) * (Long_Float (A.Y) - Long_Float (B.Y))));
   --  Example: Euclidean_Length ((0.0, 0.0), (3.0, 4.0)) = 5.0.

   function Floor_Cost (X : Long_Float) return Cost
   is (Cost (X) - (if Long_Float (Cost (X)) > X then 1 else 0))
     with Inline;
   --  Cost (Long_Float'Floor (X)) without the attribute's library call (the
   --  conversion rounds to the nearest, then one down if that was above).
   --  Example: Floor_Cost (2.5) = 2, Floor_Cost (-0.5) = -1.

   function Ceiling_Cost (X : Long_Float) return Cost
   is (Cost (X) + (if Long_Float (Cost (X)) < X then 1 else 0))
     with Inline;
   --  Cost (Long_Float'Ceiling (X)). Example: Ceiling_Cost (2.1) = 3.

   function Rounded (Rule : Distance_Rule; D : Long_Float) return Cost
   is (case Rule is
          when Euclidean_Floor   => Floor_Cost (D),
          when Euclidean_Ceiling => Ceiling_Cost (D),
          when others            => Floor_Cost (D + 0.5))
     with Inline;
   --  D rounded as Rule says (nearest for From_Matrix).

   function Computed_Distance (This : Problem; From, To : Natural) return Cost
   is (if From = Nowhere or else To = Nowhere then 0
       else Rounded (This.Rule, This.Scale * Euclidean_Length
                       (This.Coordinates (From), This.Coordinates (To))))
     with Inline;
   --  The distance a Euclidean rule gives (0 to and from Nowhere).

   function Distance (This : Problem; From, To : Natural) return Cost
   is (if This.Rule /= From_Matrix then Computed_Distance (This, From, To)
       elsif This.Matrix = null then 0
       else This.Matrix (From, To))
     with Inline, Pre => From <= This.Locations and then To <= This.Locations;
   --  Base distance from From to To (shared by the robots without costs of
   --  their own; before a robot's multiplier).
   --  Example: Distance (P.all, 1, 2) = 10 after Set_Distance (P.all, 1, 2, 10).

   function Has_Matrix (This : Problem) return Boolean
   is (This.Rule = From_Matrix and then This.Matrix /= null);
   --  The distances are held in an n x n matrix (False when computed).

   procedure Set_Distance (This : in out Problem; From, To : Positive; D : Cost)
     with Pre => From <= This.Locations and then To <= This.Locations
                 and then D >= 0 and then D < Infinity,
          Post => This.Rule = From_Matrix;
   --  Allocates the matrix on first use (from the computed distances when
   --  there are some).

   procedure Update_Symmetry (This : in out Problem);
   --  Sets This.Symmetric from the matrix (call after Set_Distance).

   procedure Set_Symmetric_Distance (This : in out Problem; A, B : Positive; D : Cost);

   procedure Set_Euclidean
     (This : in out Problem; Points : Point_Array; Scale : Long_Float := 1.0;
      Round : Boolean := True; Rule : Distance_Rule := Euclidean_Nearest;
      Keep_Matrix_Up_To : Natural := Matrix_Limit)
     with Pre => Rule /= From_Matrix and then Points'Length = This.Locations;
   --  Coordinates and distances from them: nint (Scale * distance) (Rule,
   --  or floor when not Round). A matrix of them is kept when there are at
   --  most Keep_Matrix_Up_To locations, else they are computed on each read.

   procedure Copy_Distances (From : Problem; To : in out Problem)
     with Pre => From.Locations = To.Locations;
   --  To gets From's distances, coordinates, scale and symmetry (a matrix
   --  is copied).

   type Cost_Function is access function (From, To : Positive) return Cost;
   procedure Set_From (This : in out Problem; F : not null Cost_Function);
   --  Distances from a callback (e.g. path length on a grid map).

   procedure Set_Task (This : in out Problem; T : Positive; Location : Positive);
   procedure Set_Task_Alternatives
     (This : in out Problem; T : Positive; Locations : Location_Array)
     with Pre => Locations'Length >= 1;
   --  Task T is an OR node: it is done at exactly one of Locations.

   procedure Set_Robot
     (This : in out Problem; R : Positive; Start : Positive; Closed : Boolean;
      Multiplier : Positive := 1);

   procedure Set_Robot_End (This : in out Problem; R : Positive; Finish : Natural)
     with Pre => Finish <= This.Locations;
   --  Robot R's tour ends at Finish, a depot of its own that may differ from
   --  its start (heterogeneous teams: e.g. a robot that must end at its
   --  charger); Nowhere makes its tour open. Call after Set_Robot.

   procedure Forbid (This : in out Problem; R, T : Positive);
   --  Robot R cannot do task T (infinite cost).

   procedure Freeze (This : in out Problem; R : Positive; Tasks : Location_Array);
   --  Robot R's tour starts with Tasks, in this order, never changed.

   function Location_Of (This : Problem; T : Positive; Choice : Positive := 1)
     return Positive
   is (This.Alt_Location (This.Alt_First (T) + Choice - 1));

   function Is_Closed (This : Problem; R : Positive) return Boolean
   is (This.Finish (R) /= Nowhere);

   ---------------------------------------------------------------------------
   --  Per-robot cost functions. Infeasible arcs may cost Infinity (a tour
   --  using one is infeasible); costs are base units, the multiplier still
   --  applies on top.

   procedure Set_Robot_Distance
     (This : in out Problem; R : Positive; From, To : Positive; D : Cost)
     with Pre => From <= This.Locations and then To <= This.Locations
                 and then D in 0 .. Infinity;
   --  Robot R's own distance; the first call gives R a copy of the shared
   --  matrix (set the shared distances first).

   type Robot_Cost_Function is access function (R, From, To : Positive) return Cost;
   procedure Set_Robot_Costs
     (This : in out Problem; R : Positive; F : not null Robot_Cost_Function);
   --  Robot R's own distances from a callback (From /= To; e.g. path length
   --  of that robot on a grid map; Infinity or more: unreachable).

   procedure Set_Robot_Factor (This : in out Problem; R : Positive; Factor : Long_Float)
     with Pre => Factor > 0.0;
   --  Robot R's own distances: nint (Factor * shared distance) (e.g. a slow
   --  robot on the whole map, unlike Multiplier which is an integer).

   function Has_Own_Costs (This : Problem; R : Positive) return Boolean
   is (This.Own (R) /= null or else This.Own_Factor (R) > 0.0);

   function Robot_Distance (This : Problem; R : Positive; From, To : Natural) return Cost
   is (if This.Own (R) /= null then This.Own (R) (From, To)
       elsif This.Own_Factor (R) > 0.0
       then Cost'Min (Infinity, Floor_Cost
                        (This.Own_Factor (R) * Long_Float (Distance (This, From, To)) + 0.5))
       else Distance (This, From, To))
     with Inline;
   --  Base distance for robot R (before its multiplier).

   ---------------------------------------------------------------------------
   --  Plan trees.

   subtype Inner_Kind is Node_Kind range And_Node .. Or_Node;

   procedure Add_Node
     (This : in out Problem; Kind : Inner_Kind; Parent : Natural; Node : out Positive)
     with Pre => Parent <= Natural (This.Plan.Length)
                 and then (Parent = 0 or else This.Plan (Parent).Kind /= Task_Node);
   --  A new AND or OR node under Parent (0: the root). Constraint_Error when
   --  there would be more OR nodes than tasks.

   procedure Add_Plan_Task (This : in out Problem; Parent : Positive; T : Positive)
     with Pre => T <= This.Tasks and then Parent <= Natural (This.Plan.Length)
                 and then This.Plan (Parent).Kind /= Task_Node;
   --  Task T as a child of Parent; Constraint_Error when T is already placed.

   function Or_Count (This : Problem) return Natural is (Natural (This.Or_Nodes.Length));
   function Has_Plan (This : Problem) return Boolean is (Or_Count (This) > 0);

   function Alternatives (This : Problem; O : Positive) return Natural
   is (This.Plan (This.Or_Nodes (O)).Children);
   --  Number of alternatives of OR ordinal O.

   function Or_Parent (This : Problem; O : Positive) return Natural
   is (This.Plan (This.Or_Nodes (O)).Or_Anc);
   function Or_Branch (This : Problem; O : Positive) return Natural
   is (This.Plan (This.Or_Nodes (O)).Branch);

   function Or_Active (This : Problem; Sel : Location_Array; O : Natural) return Boolean;
   --  OR ordinal O (0: the root) is reached under the selection Sel (one
   --  alternative per OR ordinal).

   function Is_Active (This : Problem; Sel : Location_Array; T : Positive) return Boolean
   is (This.Task_Or (T) = 0
       or else (Sel (This.Task_Or (T)) = This.Task_Branch (T)
                and then Or_Active (This, Sel, This.Task_Or (T))));
   --  Task T is to be done under Sel.

   function Active_Count (This : Problem; Sel : Location_Array) return Natural;

   function Default_Selection (This : Problem) return Location_Array;
   --  (1 .. Tasks): the first alternative everywhere, except that OR nodes
   --  above a frozen task select the alternative holding it.

   function Is_Locked (This : Problem; O : Positive) return Boolean;
   --  OR ordinal O lies above a frozen task: its choice cannot change.

   function Cheapest_Selection (This : Problem) return Location_Array;
   --  (1 .. Tasks): at each OR node (bottom-up) the alternative of least
   --  estimated cost, a task being estimated at its cheapest robot's
   --  start -> task -> end trip (times its multiplier); locked nodes keep
   --  their frozen alternative. Used by the baselines and the annealer's
   --  construction.

   function Task_Name (This : Problem; T : Positive) return String;
   function Or_Name (This : Problem; O : Positive) return String;
   --  The label given (Task_Names, Or_Names) or the number.

   function Check (This : Problem) return String;
   --  "" when consistent; else what is wrong.

end Sancta.Allocation.Problems;
