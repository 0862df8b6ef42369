--  The drawing of a scene with Cairo, the same for the window and for the
--  off-screen snapshot: the world map, the tasks (coloured by state, the
--  OR alternatives not chosen greyed), each robot's planned tour, trail,
--  laser scan, body, heading, name and state, and a side panel (team
--  figures, one row per robot, a legend and the event log).
--
--     T : Transform;
--     Draw (Cr, Scene, 1280, 800, Options, T);     --  T: world -> pixels
--     Write_Snapshot (Scene, 1280, 800, Options, "out/view.png");
with Ada.Strings.Unbounded;
with Cairo;
with Sancta.Geometry;
with Sancta.Views.Scenes;

package Sancta.Views.Drawing is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;

   type RGB is record
      R, G, B : Float range 0.0 .. 1.0;
   end record;

   function Colour_Of (Index : Natural) return RGB;
   --  The report pictures' palette (Sancta.Simulation.Rendering.Color_Of:
   --  ten colours, cycling; 0 reads as 1): robot "r3" has the same colour
   --  here as in gantt.png. A robot's colour is Colour_Of
   --  (Scenes.Colour_Index (Id)). Task states are drawn in greys and black
   --  (no hue of a robot nor the loss's red), explained by the panel's
   --  legend.

   Lost_Colour : constant RGB := (0.55, 0.55, 0.55);

   type View_Options is record
      Zoom        : Real := 1.0;
      --  Times the scale that fits the world in the map area.
      Centre      : Point;
      Has_Centre  : Boolean := False;
      --  The world point shown at the centre of the map area (panned);
      --  else the world's centre.
      Follow      : Unbounded_String;
      --  A robot kept at the centre ("" none).
      Show_Scans  : Boolean := False;
      Show_Trails : Boolean := True;
      Paused      : Boolean := False;
      Panel_Width : Natural := 330;
   end record;

   type Transform is record
      Scale  : Real := 1.0;
      --  Pixels per metre.
      X0, Y0 : Real := 0.0;
      --  Pixel of the world origin: x_px = X0 + Scale * x, y_px = Y0 - Scale * y.
   end record;

   function To_World (T : Transform; X, Y : Real) return Point;

   function Fit
     (S : Scenes.Scene; Width, Height : Natural; Options : View_Options) return Transform;
   --  The transform Draw uses for this size and these options.

   procedure Draw
     (Cr      : Cairo.Cairo_Context;
      S       : Scenes.Scene;
      Width   : Natural;
      Height  : Natural;
      Options : View_Options;
      T       : out Transform);

   procedure Write_Snapshot
     (S         : Scenes.Scene;
      Width     : Positive;
      Height    : Positive;
      Options   : View_Options;
      File_Name : String;
      T         : out Transform);
   --  Draws off-screen into File_Name (PNG). Ada.IO_Exceptions.Use_Error
   --  naming the file when it cannot be written.

   procedure Write_Description
     (S         : Scenes.Scene;
      T         : Transform;
      File_Name : String;
      Offset_X  : Real := 0.0;
      Offset_Y  : Real := 0.0);
   --  What was drawn, as JSON (for tests and reports): the transform (with
   --  Offset, the drawing's position in a larger picture), each robot's
   --  colour, state, pose and pixel, its tour's pixel polyline, the team
   --  figures, the red of a loss, and each task's kind, choice, state,
   --  fill colour and marker centre (pixel; an explore task's: the end it
   --  starts from; an OR task's: its choice's, the first when none).
   --  Written to File_Name & ".part", then renamed: a reader never sees a
   --  half-written file.

end Sancta.Views.Drawing;
