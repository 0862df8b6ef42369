--  Team plans: the allocation problem of one re-planning round (a snapshot
--  of the robots' positions and the tasks still to do), the plans proposed
--  for it, their costs and their text in the team database.
--
--  Costs are path lengths in metres along straight lines (the planner's
--  model; the executed distance is measured by the simulator): a robot's
--  tour cost is the sum of the legs from its position to each task's entry
--  point plus the length travelled inside each task. A plan's Value is its
--  makespan (longest tour) + total / 1000, so lower is better.
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;
with Interfaces;
with Sancta.Geometry;
with Sancta.Team.Missions;

package Sancta.Team.Plans is

   use Ada.Strings.Unbounded;

   Format_Error : exception renames Missions.Format_Error;

   type Robot_Position is record
      Id     : Unbounded_String;
      Where  : Sancta.Geometry.Point;
   end record;
   package Robot_Vectors is new Ada.Containers.Vectors (Positive, Robot_Position);

   type Snapshot is record
      Generation : Natural := 0;
      Robots     : Robot_Vectors.Vector;
      Tasks      : Missions.Task_Vectors.Vector;
   end record;
   --  One re-planning round.

   function Encode (S : Snapshot) return String;
   --  "generation|r1@x,y;r2@x,y|t1,t2,..." (tasks by id).
   procedure Decode
     (Text     : String;
      S        : out Snapshot;
      Task_Ids : out Missions.Task_Vectors.Vector);
   --  Task_Ids: tasks with only their Id set (the caller looks them up).

   type Step is record
      Task_Id : Unbounded_String;
      Choice  : Positive := 1;
   end record;
   package Step_Vectors is new Ada.Containers.Vectors (Positive, Step);
   package Tour_Vectors is new Ada.Containers.Vectors
     (Positive, Step_Vectors.Vector, Step_Vectors."=");

   type Plan is record
      Generation : Natural := 0;
      Value      : Long_Float := Long_Float'Last;
      Proposer   : Unbounded_String;
      Tours      : Tour_Vectors.Vector;
      --  One per snapshot robot, in the snapshot's order.
   end record;

   function Encode (P : Plan; S : Snapshot) return String;
   --  "generation|value|proposer|r1=t1.1,t5.2;r2=;..."
   function Decode (Text : String; S : Snapshot) return Plan;
   --  Raises Format_Error when Text does not fit S.

   function Has_Task (S : Snapshot; Id : String) return Boolean is
     (for some T of S.Tasks => T.Id = Id);
   function Task_Of (S : Snapshot; Id : String) return Missions.Mission_Task
     with Pre => Has_Task (S, Id) or else raise Format_Error with "task " & Id & " not in round";

   function Tour_Cost
     (S     : Snapshot;
      Start : Sancta.Geometry.Point;
      Tour  : Step_Vectors.Vector;
      Leg   : access function (From, To : Sancta.Geometry.Point) return Long_Float := null)
      return Long_Float;
   --  Leg: the cost of going from one point to another (e.g. an A* path
   --  length on the world's grid); null: the straight line (the planners'
   --  model). The length inside a task (an explore segment) is always
   --  straight.
   function Evaluate
     (S   : Snapshot;
      P   : in out Plan;
      Leg : access function (From, To : Sancta.Geometry.Point) return Long_Float := null)
      return Long_Float;
   --  Sets P.Value and returns it (legs as for Tour_Cost).
   function Makespan
     (S   : Snapshot;
      P   : Plan;
      Leg : access function (From, To : Sancta.Geometry.Point) return Long_Float := null)
      return Long_Float;
   function Total
     (S   : Snapshot;
      P   : Plan;
      Leg : access function (From, To : Sancta.Geometry.Point) return Long_Float := null)
      return Long_Float;
   --  The longest tour and the sum of the tours, legs as for Tour_Cost.

   procedure Best_Insertion
     (S         : Snapshot;
      Start     : Sancta.Geometry.Point;
      Tour      : Step_Vectors.Vector;
      Task_Id   : String;
      New_Cost  : out Long_Float;
      Position  : out Positive;
      Choice    : out Positive;
      Leg       : access function (From, To : Sancta.Geometry.Point) return Long_Float := null);
   --  Where inserting Task_Id into Tour (before Position, with Choice) gives
   --  the cheapest tour, and that tour's cost (an auction bid).

   function Anneal
     (S          : Snapshot;
      Seed       : Interfaces.Unsigned_64;
      Budget     : Duration;
      Start_From : Plan;
      Proposer   : String;
      Iterations : Long_Long_Integer := 0;
      Leg        : access function (From, To : Sancta.Geometry.Point) return Long_Float := null)
      return Plan
     with Pre => not S.Robots.Is_Empty and then (Budget > 0.0 or else Iterations > 0);
   --  The project's annealer (Sancta.Allocation.Annealers) on this round
   --  for Budget of wall-clock time (or Iterations moves, whichever ends
   --  first; 0 = no limit); starts from Start_From when it has tours for S,
   --  else from its own greedy start. Leg: the cost of the legs between
   --  points (null: straight lines), computed once per pair of points.

   function Carried_Over
     (Previous_Round : Snapshot;
      Previous       : Plan;
      S              : Snapshot;
      Proposer       : String;
      Leg            : access function (From, To : Sancta.Geometry.Point) return Long_Float
        := null)
      return Plan;
   --  The anytime start of a re-plan: Previous (the plan adopted for
   --  Previous_Round) brought to round S. Each robot of S keeps, in order,
   --  the tasks of its previous tour that S still holds (done ones are gone
   --  from S); each other task of S (a lost robot's, a new one) goes, in
   --  S's order, where the tour it joins costs least afterwards (best
   --  insertion, legs as for Tour_Cost). Value set. A plan without tours
   --  (Anneal then starts from its own greedy start) when Previous is not
   --  Previous_Round's adopted plan.
   --
   --     Start : constant Plan := Carried_Over (Old.Round, Old.Adopted, S, "r1");
   --     Mine  : constant Plan := Anneal (S, Seed, 0.25, Start, "r1");

   function Greedy (S : Snapshot; Proposer : String) return Plan
     with Pre => not S.Robots.Is_Empty;
   --  Best-insertion greedy (the min-makespan baseline): tasks in mission
   --  order, each to the robot whose tour stays the shortest.

   function Auction (S : Snapshot; Proposer : String) return Plan
     with Pre => not S.Robots.Is_Empty;
   --  The outcome of the team's sequential single-item auctions computed in
   --  one place (same bids and winner rule as Sancta.Team.Agents' auctions:
   --  each step, every robot bids its cheapest task at the tour cost after
   --  its best insertion; the lowest bid wins, ties to the first robot).
   --  For benchmarks.

end Sancta.Team.Plans;
