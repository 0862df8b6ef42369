--  Pictures of a world with robot trajectories, robots and points of
--  interest, as SVG (vector) or as an image saved to PNG (labels in a
--  5 x 7 pixel font with lower case, Sancta.Simulation.Glyphs). Robots get
--  colours a colour-blind reader tells apart (the first five); red marks
--  where a robot was lost. Trajectories can be read from and written to
--  CSV ("robot,x,y" per line, robots numbered from 1). A world can also be
--  written as a ROS map-server pair (PGM + YAML).
--
--     S.Trajectories := Read_Trajectories ("run.csv");
--     S.Markers.Append ((Where => (3.0, 4.0), Label => To_Unbounded_String ("dock")));
--     Write_SVG (World, S, "run.svg");
--     Raster_Images.Save_PNG (Render (World, S, Scale => 20.0), "run.png");
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;
with Sancta.Geometry;             use Sancta.Geometry;
with Sancta.Simulation.Raster_Images;
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

   type Legend_Entry is record
      Color : Raster_Images.Color;
      Text  : Ada.Strings.Unbounded.Unbounded_String;
   end record;
   package Legend_Vectors is new Ada.Containers.Vectors (Positive, Legend_Entry);

   type Scene is record
      Trajectories : Path_Vectors.Vector;
      --  One path per robot, in robot order.
      Robots       : Pose_Vectors.Vector;
      --  Robots drawn as disks with a heading tick.
      Robot_Radius : Real := 0.2;
      Lost         : Point_Vectors.Vector;
      --  Where robots were lost: a red cross, larger and thicker than a
      --  marker's (red is for losses only: no robot has it).
      Markers      : Marker_Vectors.Vector;
      Title        : Ada.Strings.Unbounded.Unbounded_String;
      --  A band above the world when set.
      Legend       : Legend_Vectors.Vector;
      Scale_Bar    : Boolean := False;
      --  A band below the world with the legend (a colour swatch and its
      --  text per entry, wrapped) and a scale bar (1, 2, 5, 10... m).
   end record;
   --  Marker labels are placed where they stay inside the picture, overlap
   --  no other label nor marker, and cover the fewest drawn pixels (walls,
   --  paths, crosses): right of the marker, else left, above, below, the
   --  corners, else farther away with a leader line (Place_Labels).

   type Pixel_Array is array (Positive range <>) of Integer;

   type Label_Box is record
      X, Y          : Integer;  --  Top left corner, pixels.
      Width, Height : Natural;
      Leader        : Boolean;  --  Away from its marker: draw a line.
   end record;
   type Label_Boxes is array (Positive range <>) of Label_Box;

   function Place_Labels
     (Anchors_X, Anchors_Y : Pixel_Array;
      Widths               : Pixel_Array;
      Height               : Natural;
      Left, Top, Right, Bottom : Integer;
      Marker_Radius        : Natural := 4;
      Ink                  : access function (X, Y : Integer) return Boolean := null)
      return Label_Boxes
     with Pre => Anchors_X'First = 1 and then Anchors_Y'First = 1 and then Widths'First = 1
                 and then Anchors_X'Length = Anchors_Y'Length
                 and then Anchors_X'Length = Widths'Length,
          Post => Place_Labels'Result'Length = Anchors_X'Length;
   --  Boxes for labels of the given widths at the anchors (pixels), inside
   --  Left .. Right x Top .. Bottom and not overlapping each other whenever
   --  a place is found within 120 pixels (else clamped inside). A label
   --  starts Marker_Radius + 3 pixels from its anchor (the marker's
   --  symbol reaches Marker_Radius) and keeps 3 pixels from the others'
   --  anchors. Of the free places, the one taken covers the fewest Ink
   --  pixels (box and a one-pixel margin), a place farther away counting
   --  as 10 pixels more per 10 pixels of distance (plus 10 for its leader
   --  line); ties go to the nearer place in the order above. Ink (X, Y):
   --  whether pixel (X, Y) is already drawn on (null: nothing is).

   function Layout_Height (S : Scene; Width : Natural; Char_Width : Positive;
                           Line_Height : Positive) return Natural;
   --  Pixels of the band below the world (0 without legend or scale bar).

   function Color_Of (Robot : Positive) return Raster_Images.Color;
   --  A distinct colour per robot (cycling over ten; the first five told
   --  apart by colour-blind readers too), never red (a loss's colour).
   --  The one palette of the project: the report pictures and the live
   --  view (sancta-view) both take robot N's colour from here.
   --  Example: Color_Of (1) = (0, 114, 178); Color_Of (11) = Color_Of (1).

   Loss_Color : constant Raster_Images.Color := (200, 0, 0);
   --  Red, for a lost robot only (its cross, its name).

   function Hex (C : Raster_Images.Color) return String;
   --  "#rrggbb".

   function Render
     (World : Worlds.World; S : Scene; Scale : Real := 20.0) return Raster_Images.Image
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
