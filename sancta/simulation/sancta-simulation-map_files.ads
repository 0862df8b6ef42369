--  Worlds from files:
--  * a ROS map-server pair: a YAML file (image, resolution, origin, negate,
--    occupied_thresh, free_thresh, mode) naming a PGM or PNG image, read
--    with map_server's rule: p = (255 - gray) / 255 (gray / 255 when
--    negate), occupied when p > occupied_thresh, free when p <
--    free_thresh, unknown otherwise (unknown is solid for the simulator);
--  * a wall world, a text file of straight walls:
--       # comment
--       resolution 0.05                  cell size (default 0.05 m)
--       thickness 0.1                    default wall thickness (0.1 m)
--       bounds X0 Y0 X1 Y1               area (default: walls + 0.5 m)
--       wall X1 Y1 X2 Y2 [THICKNESS]
--       box X0 Y0 X1 Y1 [THICKNESS]      the four walls of a rectangle
--  Errors: Format_Error "file:line: what was expected, what was found".
--
--     W : constant Worlds.World := Load_World ("share/worlds/office.yaml");
with Ada.Strings.Unbounded;
with Sancta.Geometry;             use Sancta.Geometry;
with Sancta.Robot.Grids;
with Sancta.Simulation.Raster_Images;
with Sancta.Simulation.Worlds;

package Sancta.Simulation.Map_Files is

   type Map_Info is record
      Image           : Ada.Strings.Unbounded.Unbounded_String;
      --  As written in the YAML file.
      Image_Path      : Ada.Strings.Unbounded.Unbounded_String;
      --  Resolved against the YAML file's directory.
      Resolution      : Real := 0.05;
      Origin          : Pose;
      Negate          : Boolean := False;
      Occupied_Thresh : Real := 0.65;
      Free_Thresh     : Real := 0.196;
   end record;

   function Read_YAML (File_Name : String) return Map_Info;

   function Load_Map (File_Name : String) return Worlds.World;
   --  A map-server YAML file and its image.

   function Load_Walls (File_Name : String) return Worlds.World;
   --  A wall world.

   function Read_Walls
     (File_Name  : String;
      Resolution : out Real;
      Low, High  : out Point) return Robot.Grids.Segment_Array;
   --  The walls of a wall world and its area.

   function Load_World (File_Name : String) return Worlds.World;
   --  Load_Map for *.yaml / *.yml, Load_Walls otherwise.

   function To_World
     (Img : Raster_Images.Image; Info : Map_Info) return Worlds.World;
   --  The map-server rule applied to an image.

   function World_File (Name : String) return String;
   --  Name when it names a file; else the bundled world of that name
   --  (Installation.Share_File ("worlds/NAME.yaml"), then .walls); ""
   --  when none.

   function Bundled_Worlds return String;
   --  The names World_File takes for bundled worlds, sorted, for help and
   --  error texts: "arena, campus, office" (the .yaml and .walls files in
   --  Installation.Share_File ("worlds/")); "none" when there are none.

end Sancta.Simulation.Map_Files;
