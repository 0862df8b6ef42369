--  Occupancy-grid mapping with log-odds: each laser beam lowers the odds
--  of the cells it crosses and raises the odds of the cell it ends in
--  (when it hit something). Cells read like nav_msgs/OccupancyGrid: -1 for
--  never observed, else 0 .. 100 (probability of occupancy in percent);
--  Data gives the row-major array of that message (cell (0, 0) first).
--
--     M.Initialize ((Origin => (0.0, 0.0), Resolution => 0.05,
--                    Width => 400, Height => 300));
--     M.Update (Pose, Scan);
--     if M.Value (I, J) > 50 then ...  --  occupied
with Ada.Finalization;
with Interfaces;
with Sancta.Geometry;       use Sancta.Geometry;
with Sancta.Robot.Grids;
with Sancta.Robot.Sensors;  use Sancta.Robot.Sensors;

package Sancta.Robot.Mappers is

   type Mapper_Config is record
      Hit_Log_Odds  : Real := 0.85;
      --  Added to a cell where a beam ended (about p = 0.7).
      Miss_Log_Odds : Real := -0.4;
      --  Added to a cell a beam crossed.
      Clamp         : Real := 6.0;
      --  Log odds stay in -Clamp .. Clamp.
   end record;

   subtype Cell_Value is Integer range -1 .. 100;

   type Cell_Value_Array is array (Natural range <>) of Interfaces.Integer_8;
   --  nav_msgs/OccupancyGrid data: index I + J * Width.

   type Mapper is new Ada.Finalization.Limited_Controlled with private;

   procedure Initialize
     (This   : in out Mapper;
      Frame  : Grids.Frame;
      Config : Mapper_Config := (others => <>))
     with Pre => Frame.Resolution > 0.0;

   function Frame_Of (This : Mapper) return Grids.Frame;

   procedure Update (This : in out Mapper; Sensor : Pose; Scan : Laser_Scan);
   --  Sensor: the laser's pose in the map frame when the scan was taken.

   function Value (This : Mapper; I, J : Integer) return Cell_Value;
   --  -1 outside the grid or never observed.

   function Data (This : Mapper) return Cell_Value_Array;

private

   type Real_Matrix is array (Integer range <>, Integer range <>) of Real;
   type Real_Access is access Real_Matrix;
   type Flag_Matrix is array (Integer range <>, Integer range <>) of Boolean;
   type Flag_Access is access Flag_Matrix;

   type Mapper is new Ada.Finalization.Limited_Controlled with record
      Frame    : Grids.Frame;
      Config   : Mapper_Config;
      Odds     : Real_Access;
      Observed : Flag_Access;
   end record;

   overriding procedure Finalize (This : in out Mapper);

end Sancta.Robot.Mappers;
