--  Leg costs for team plans from A* path lengths on a world's grid (the
--  robots drive A* paths, Sancta.Robot.Path_Costs), so that the allocation
--  plans with the distances the robots will travel rather than with
--  straight lines through walls.
--
--     Costs : constant Grid_Costs.Cost_Access :=
--       Grid_Costs.Create (Sim_Tool.World_File ("office"), Robot_Radius => 0.2);
--     Agent_Config'(..., Costs => Costs);
--
--  The world's occupancy is coarsened (a coarse cell is occupied when any
--  of its cells is) to Cell metres before inflation, which makes a query
--  about (Cell / resolution)^2 times cheaper than on the full grid: a leg
--  is an estimate within about a cell per end of the robots' A* length.
--  Unreachable legs (a point inside an inflated obstacle of the coarse
--  grid) cost their straight line. Pairs are cached (by the planner, per
--  pair of cells). Safe for concurrent use (a protected planner).
with Sancta.Geometry;
with Sancta.Robot.Grids;
private with Sancta.Robot.Path_Costs;

package Sancta.Team.Grid_Costs is

   use Sancta.Geometry;

   type Grid_Cost_Model is tagged limited private;
   type Cost_Access is access all Grid_Cost_Model'Class;

   function Create
     (World_File   : String;
      Robot_Radius : Real := 0.2;
      Cell         : Real := 0.2) return Cost_Access
     with Pre => Robot_Radius >= 0.0 and then Cell > 0.0;
   --  Loads World_File (Sancta.Simulation.Map_Files: its errors propagate).

   function Create
     (Occupancy    : Sancta.Robot.Grids.Grid;
      Robot_Radius : Real := 0.2;
      Cell         : Real := 0.2) return Cost_Access
     with Pre => Robot_Radius >= 0.0 and then Cell > 0.0;

   function Leg (This : Grid_Cost_Model; From, To : Point) return Long_Float;
   --  The A* length from From to To on the coarse grid (metres), or the
   --  straight line when there is no path.

   function Cached_Legs (This : Grid_Cost_Model) return Natural;
   --  Pairs of coarse cells whose leg Leg answers from its cache.

   function Coarsen (G : Sancta.Robot.Grids.Grid; Factor : Positive)
     return Sancta.Robot.Grids.Grid;
   --  Cells of Factor x Factor cells of G (the same origin), occupied when
   --  any of them is (G's cells past its last full block included).

private

   protected type Guarded is
      procedure Initialize (Occupancy : Sancta.Robot.Grids.Grid; Robot_Radius : Real);
      procedure Cost (From, To : Point; Result : out Long_Float);
      function Cached return Natural;
   private
      Map : Sancta.Robot.Path_Costs.Planner;
   end Guarded;

   type Guarded_Access is access Guarded;

   type Grid_Cost_Model is tagged limited record
      Guard : Guarded_Access := new Guarded;
   end record;

end Sancta.Team.Grid_Costs;
