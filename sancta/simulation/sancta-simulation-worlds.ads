--  A simulated world: a static occupancy grid plus a clearance field (the
--  Chebyshev distance, in cells, from each cell to the nearest occupied
--  cell) that lets rays jump across open space. Ray casting and disk
--  collision are exact with respect to the grid: a ray stops at the
--  boundary of the first occupied cell it enters.
--
--     G : Grids.Grid (799, 599);  Grids.Draw (G, ((0.0, 0.0), (40.0, 0.0), 0.1));
--     W : constant World := Create (G);
--     D : constant Real := Cast (W, (1.0, 1.0), Angle => 0.0, Max_Range => 8.0);
with Ada.Finalization;
with Sancta.Geometry;     use Sancta.Geometry;
with Sancta.Robot.Grids;

package Sancta.Simulation.Worlds is

   type World is new Ada.Finalization.Controlled with private;
   --  Copies are deep; the empty world (default) has no cells: every cast
   --  returns 0 and every disk collides.

   function Create (Occupancy : Robot.Grids.Grid) return World
     with Pre => Occupancy.Resolution > 0.0;

   function Frame_Of (This : World) return Robot.Grids.Frame;

   function Occupancy (This : World) return Robot.Grids.Grid;
   --  A copy of the occupancy grid (for planners and renderers).

   function Is_Occupied (This : World; I, J : Integer) return Boolean;
   --  Outside the grid is occupied.

   function Cast
     (This      : World;
      From      : Point;
      Angle     : Real;
      Max_Range : Real) return Real
     with Post => Cast'Result in 0.0 .. Real'Max (0.0, Max_Range);
   --  Distance from From along Angle (world frame) to the first occupied
   --  cell, or Max_Range when there is none closer.

   function Cast_Along
     (This      : World;
      From      : Point;
      DX, DY    : Real;
      Max_Range : Real) return Real
     with Pre  => abs (DX * DX + DY * DY - 1.0) < 1.0E-6,
          Post => Cast_Along'Result in 0.0 .. Real'Max (0.0, Max_Range);
   --  The same along the unit direction (DX, DY): no trigonometry, for
   --  lasers that rotate their beam direction incrementally.

   function Disk_Collides
     (This : World; Center : Point; Radius : Real) return Boolean;
   --  The disk overlaps an occupied cell (or leaves the grid).

private

   type Grid_Access is access Robot.Grids.Grid;

   type Clearance is range 0 .. 255 with Size => 8;
   --  0: occupied; else the Chebyshev distance in cells to the nearest
   --  occupied cell (or the grid's edge), capped at 255.

   type Clearance_Matrix is array (Integer range <>, Integer range <>) of Clearance
     with Component_Size => 8;
   --  One byte per cell: the ray caster reads only this (cache friendly).
   type Clearance_Access is access Clearance_Matrix;

   type World is new Ada.Finalization.Controlled with record
      Cells     : Grid_Access;
      Clear     : Clearance_Access;
   end record;

   overriding procedure Adjust (This : in out World);
   overriding procedure Finalize (This : in out World);

end Sancta.Simulation.Worlds;
