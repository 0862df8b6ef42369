--  Path costs on an occupancy grid: obstacles are inflated by the robot's
--  radius, then A* (4- or 8-connected, octile heuristic, no corner
--  cutting) gives the length of the shortest grid path between two points.
--  Cost is meant as the task planner's cost callback (From, To : Point);
--  Path gives the waypoints (line-of-sight shortened) for a controller.
--
--     P : constant Planner := Create (World_Grid, Robot_Radius => 0.25);
--     C : constant Real := Cost (P, (1.0, 1.0), (8.0, 3.0));
--     if C = Unreachable then ...
with Ada.Containers.Hashed_Maps;
with Ada.Containers.Vectors;
with Ada.Finalization;
with Sancta.Geometry;     use Sancta.Geometry;
with Sancta.Robot.Grids;

package Sancta.Robot.Path_Costs is

   type Connectivity is (Four, Eight);

   Unreachable : constant Real := Real'Last;

   type Planner is new Ada.Finalization.Limited_Controlled with private;
   --  Holds the inflated grid and A*'s scratch space (reused by every
   --  query; not for concurrent use).

   procedure Initialize
     (This         : in out Planner;
      Occupancy    : Grids.Grid;
      Robot_Radius : Real;
      Connect      : Connectivity := Eight)
     with Pre => Robot_Radius >= 0.0 and then Occupancy.Resolution > 0.0;

   function Is_Free (This : Planner; P : Point) return Boolean;
   --  Inside the grid and clear of the inflated obstacles.

   function Cost (This : Planner; From, To : Point) return Real
     with Post => Cost'Result >= 0.0;
   --  Length (m) of the shortest grid path from the cell of From to the
   --  cell of To, or Unreachable. A start inside an inflated obstacle may
   --  leave it (the robot is there already); a goal inside one is
   --  unreachable.

   generic
      Map : in out Planner;
   function Generic_Cost (From, To : Point) return Real;
   --  Cost on Map as a plain function of two points, the shape a task
   --  planner's cost callback takes:
   --     function Office_Cost is new Generic_Cost (Office_Planner);

   function Cached_Costs (This : Planner) return Natural;
   --  Pairs of cells whose cost is remembered: Cost answers a pair it saw
   --  before without searching (the grid never changes after Initialize).

   package Point_Vectors is new Ada.Containers.Vectors (Positive, Point);

   function Path (This : Planner; From, To : Point) return Point_Vectors.Vector;
   --  Waypoints after From, ending with To; empty when unreachable.

   function Path
     (This      : Planner;
      From, To  : Point;
      Obstacles : Point_Vectors.Vector) return Point_Vectors.Vector;
   --  As Path, with each of Obstacles (e.g. laser points on another robot)
   --  also blocked, inflated by the robot radius like the walls, for this
   --  search only: the planner is unchanged afterwards (and Cost's cache
   --  is not touched).

   function Line_Of_Sight (This : Planner; A, B : Point) return Boolean;
   --  The straight segment A-B stays in free (inflated) space.

private

   type Boolean_Matrix is array (Integer range <>, Integer range <>) of Boolean;
   type Boolean_Access is access Boolean_Matrix;
   type Real_Array is array (Natural range <>) of Real;
   type Real_Access is access Real_Array;
   type Index_Array is array (Natural range <>) of Integer;
   type Index_Access is access Index_Array;

   type Scratch is record
      G          : Real_Access;
      Parent     : Index_Access;
      Stamp      : Index_Access;
      --  A cell's G and Parent are valid when Stamp = Generation.
      Closed     : Index_Access;
      Heap       : Index_Access;
      Heap_F     : Real_Access;
      Generation : Integer := 0;
   end record;

   type Scratch_Access is access Scratch;

   type Cell_Pair is record
      From, To : Natural := 0;
   end record;

   use type Ada.Containers.Hash_Type;

   function Hash (P : Cell_Pair) return Ada.Containers.Hash_Type is
     (Ada.Containers.Hash_Type'Mod (P.From) * 16#9E37_79B1#
      xor Ada.Containers.Hash_Type'Mod (P.To));

   package Cost_Maps is new Ada.Containers.Hashed_Maps
     (Cell_Pair, Real, Hash, "=");

   type Cost_Map_Access is access Cost_Maps.Map;

   type Planner is new Ada.Finalization.Limited_Controlled with record
      Frame   : Grids.Frame;
      Blocked : Boolean_Access;
      Connect : Connectivity := Eight;
      Radius  : Real := 0.0;
      Work    : Scratch_Access;
      Cache   : Cost_Map_Access;
   end record;

   overriding procedure Finalize (This : in out Planner);

end Sancta.Robot.Path_Costs;
