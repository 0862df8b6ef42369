--  Pictures of a world with robot trajectories, robots and points of
--  interest, as SVG (vector) or as an image saved to PNG (labels in a
--  5 x 7 pixel font, Sancta.Simulation.Glyphs). Trajectories can be read from and written to CSV
--  ("robot,x,y" per line, robots numbered from 1). A world can also be
--  written as a ROS map-server pair (PGM + YAML).
--
--     S.Trajectories := Read_Trajectories ("run.csv");
--     S.Markers.Append ((Where => (3.0, 4.0), Label => To_Unbounded_String ("dock")));
--     Write_SVG (World, S, "run.svg");
--     Images.Save_PNG (Render (World, S, Scale => 20.0), "run.png");
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;
with Sancta.Geometry;             use Sancta.Geometry;
with Sancta.Simulation.Images;
with Sancta.Simulation.Worlds;

package Sancta.Simulation.Rendering is

   package Point_Vectors is new Ada.Containers.Vectors (Positive, Point);
   package Path_Vectors is new Ada.Containers.Vectors
     (Positive, Point_Vectors.Vector, Point_Vectors."=");
   package Pose_Vectors is new Ada.Containers.Vectors (Positive, Pose);

   type Marker is record
      Where : Point;
      Label : Ada.Strings.Unbounded.Unbounded_String;
   end record;

   package Marker_Vectors is new Ada.Containers.Vectors (Positive, Marker);

   type Scene is record
      Trajectories : Path_Vectors.Vector;
      --  One path per robot, in robot order.
      Robots       : Pose_Vectors.Vector;
      --  Robots drawn as disks with a heading tick.
      Robot_Radius : Real := 0.2;
      Markers      : Marker_Vectors.Vector;
   end record;

   function Color_Of (Robot : Positive) return Images.Color;
   --  A distinct colour per robot (cycling over ten).

   function Render
     (World : Worlds.World; S : Scene; Scale : Real := 20.0) return Images.Image
     with Pre => Scale > 0.0;
   --  Scale: pixels per metre.

   procedure Write_SVG
     (World     : Worlds.World;
      S         : Scene;
      File_Name : String;
      Scale     : Real := 20.0)
     with Pre => Scale > 0.0;

   function Read_Trajectories (File_Name : String) return Path_Vectors.Vector;
   --  Format_Error "file:line: reason" on a bad line.

   procedure Write_Trajectories (Paths : Path_Vectors.Vector; File_Name : String);

   procedure Write_Map (World : Worlds.World; Base_Name : String);
   --  Base_Name.pgm (occupied 0, free 254) and Base_Name.yaml.

end Sancta.Simulation.Rendering;
