--  The allocation problem: locations with an exact (possibly asymmetric)
--  distance matrix, tasks placed at one location or at one of several
--  alternative locations (an OR node: the planner chooses), robots with a
--  start location, closed or open tours and a cost multiplier (heterogeneous
--  teams), infeasible robot/task pairs, frozen tour prefixes (tasks already
--  done or under way, for online re-planning), and the minimum number of
--  tasks per robot (1 in the classic mTSP).
--
--     P : constant Problem_Access := Create (Locations => 3, Tasks => 2, Robots => 1);
--     Set_Distance (P.all, 1, 2, 10); ...
--     Set_Task (P.all, 1, Location => 2);
--     Set_Robot (P.all, 1, Start => 1, Closed => True);
--
--  Problems are built once and read-only afterwards; they live on the heap
--  because their matrix can be large (1000 locations: 8 MB).
--
--  Partial (known limits): heterogeneous robots differ by an integer cost
--  multiplier (speed), by what they can do (Forbid) and by their start and
--  end depots (Set_Robot, Set_Robot_End), not by whole cost functions
--  of their own (the annealer's O(1) segment costs rely on one matrix);
--  plans are one level deep: a task is an OR node over alternative single
--  locations (the mission reader normalises nested <and>/<or> trees to this
--  form when they have no compound alternative); OR nodes over sets of
--  tasks and compound tasks with distinct entry and exit points are not
--  modelled yet.
with Sancta.Geometry;

package Sancta.Allocation.Problems is

   type Cost_Matrix is array (Natural range <>, Natural range <>) of Cost;
   type Location_Array is array (Positive range <>) of Natural;
   type Count_Array is array (Positive range <>) of Natural;
   type Boolean_Matrix is array (Positive range <>, Positive range <>) of Boolean;
   type Boolean_Array is array (Positive range <>) of Boolean;
   type Point_Array is array (Positive range <>) of Sancta.Geometry.Point;
   type Task_Matrix is array (Positive range <>, Positive range <>) of Natural;

   type Problem
     (Locations    : Positive;
      Tasks        : Positive;
      Robots       : Positive;
      Alternatives : Positive)
   is limited record
      Distance       : Cost_Matrix (0 .. Locations, 0 .. Locations) :=
        [others => [others => 0]];
      --  Base distance; location 0 is "nowhere", at distance 0 from
      --  everything: the end of an open tour.
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
   end record;

   type Problem_Access is access Problem;

   function Create
     (Locations, Tasks, Robots : Positive; Alternatives : Natural := 0)
      return Problem_Access;
   --  A problem with all distances 0, task T at location T, room for
   --  Alternatives extra OR alternatives, robots starting at location 1 on
   --  closed tours.

   Nowhere : constant := 0;

   procedure Set_Distance (This : in out Problem; From, To : Positive; D : Cost)
     with Pre => From <= This.Locations and then To <= This.Locations
                 and then D >= 0 and then D < Infinity;

   procedure Update_Symmetry (This : in out Problem);
   --  Sets This.Symmetric from the matrix (call after Set_Distance).

   procedure Set_Symmetric_Distance (This : in out Problem; A, B : Positive; D : Cost);

   procedure Set_Euclidean
     (This : in out Problem; Points : Point_Array; Scale : Long_Float := 1.0;
      Round : Boolean := True);
   --  Coordinates and distances from them: nint (Scale * distance).

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

   function Check (This : Problem) return String;
   --  "" when consistent; else what is wrong.

end Sancta.Allocation.Problems;
