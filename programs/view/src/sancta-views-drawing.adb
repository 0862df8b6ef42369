with Ada.Characters.Handling;
with Ada.Containers;
with Ada.Numerics;
with Ada.Numerics.Generic_Elementary_Functions;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with Ada.IO_Exceptions;
with Ada.Unchecked_Deallocation;
with Cairo.Image_Surface;
with Cairo.Png;
with GNAT.OS_Lib;
with Glib;
with Sancta.Robot.Grids;
with Sancta.Simulation.Raster_Images;
with Sancta.Simulation.Rendering;

package body Sancta.Views.Drawing is

   package Raster_Images renames Sancta.Simulation.Raster_Images;
   package Rendering renames Sancta.Simulation.Rendering;

   use Cairo;
   use Glib;
   use Sancta.Views.Scenes;
   use type Sancta.Views.Scenes.Grid_Access;
   use type Ada.Containers.Count_Type;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   function To_RGB (C : Raster_Images.Color) return RGB is
     ((Float (C.R) / 255.0, Float (C.G) / 255.0, Float (C.B) / 255.0));

   function Colour_Of (Index : Natural) return RGB is
     (To_RGB (Rendering.Color_Of (Positive'Max (1, Index))));
   --  The report pictures' palette: robot 3 is the same bluish green in
   --  the view and in gantt.png (it was purple here, green there).

   Lost_Mark : constant RGB := To_RGB (Rendering.Loss_Color);
   Ink       : constant RGB := (0.10, 0.10, 0.10);

   --  Task states in greys and black only: every hue is a robot's (the
   --  palette's ten) or the loss's red. Pending: white, grey edge;
   --  assigned: white, the robot's edge; under way: the robot's fill;
   --  done: light grey with a black tick; re-allocated (its robot lost):
   --  the new robot's colour in a dashed black ring.
   Pending   : constant RGB := (0.50, 0.50, 0.50);
   Done_Fill : constant RGB := (0.75, 0.75, 0.75);
   Done_Edge : constant RGB := (0.45, 0.45, 0.45);
   Greyed    : constant RGB := (0.78, 0.78, 0.78);
   Realloc   : RGB renames Ink;

   function Robot_Colour (S : Scene; Id : String) return RGB is
     (if S.Robots.Contains (Id) then Colour_Of (S.Robots (Id).Colour) else Pending);

   procedure Set (Cr : Cairo_Context; C : RGB; Alpha : Float := 1.0) is
   begin
      Set_Source_Rgba (Cr, Gdouble (C.R), Gdouble (C.G), Gdouble (C.B), Gdouble (Alpha));
   end Set;

   function Img (X : Real) return String renames Scenes.Image;

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   --  Transform --------------------------------------------------------------

   type Pixel is record
      X, Y : Gdouble;
   end record;

   function Px (T : Transform; P : Point) return Pixel is
     ((Gdouble (T.X0 + T.Scale * P.X), Gdouble (T.Y0 - T.Scale * P.Y)));

   function To_World (T : Transform; X, Y : Real) return Point is
     (((X - T.X0) / T.Scale, (T.Y0 - Y) / T.Scale));

   type Box is record
      Low, High : Point;
   end record;

   function Bounds (S : Scene) return Box is
      B     : Box := ((Real'Last, Real'Last), (Real'First, Real'First));
      Empty : Boolean := True;
      procedure Add (P : Point) is
      begin
         B := ((Real'Min (B.Low.X, P.X), Real'Min (B.Low.Y, P.Y)),
               (Real'Max (B.High.X, P.X), Real'Max (B.High.Y, P.Y)));
         Empty := False;
      end Add;
   begin
      if S.Map /= null then
         return (S.Map.Origin,
                 (S.Map.Origin.X + Real (Sancta.Robot.Grids.Width (S.Map.all)) * S.Map.Resolution,
                  S.Map.Origin.Y + Real (Sancta.Robot.Grids.Height (S.Map.all))
                    * S.Map.Resolution));
      end if;
      for T of S.Tasks loop
         for P of T.Points loop
            Add (P);
         end loop;
      end loop;
      for R of S.Robots loop
         Add (Position (R.Where));
      end loop;
      if Empty then
         return ((-5.0, -5.0), (5.0, 5.0));
      end if;
      return ((B.Low.X - 1.0, B.Low.Y - 1.0), (B.High.X + 1.0, B.High.Y + 1.0));
   end Bounds;

   function Map_Width (Width : Natural; Options : View_Options) return Natural is
     (if Width > 2 * Options.Panel_Width then Width - Options.Panel_Width else Width);

   function Fit
     (S : Scene; Width, Height : Natural; Options : View_Options) return Transform
   is
      B      : constant Box := Bounds (S);
      W      : constant Real := Real (Natural'Max (1, Map_Width (Width, Options)));
      H      : constant Real := Real (Natural'Max (1, Height));
      Size_X : constant Real := Real'Max (1.0, B.High.X - B.Low.X);
      Size_Y : constant Real := Real'Max (1.0, B.High.Y - B.Low.Y);
      Scale  : constant Real :=
        Real'Min (W / Size_X, H / Size_Y) * 0.96 * Real'Max (0.05, Options.Zoom);
      Centre : Point := ((B.Low.X + B.High.X) / 2.0, (B.Low.Y + B.High.Y) / 2.0);
   begin
      if Options.Follow /= Null_Unbounded_String
        and then S.Robots.Contains (To_String (Options.Follow))
      then
         Centre := Position (S.Robots (To_String (Options.Follow)).Where);
      elsif Options.Has_Centre then
         Centre := Options.Centre;
      end if;
      return (Scale => Scale, X0 => W / 2.0 - Scale * Centre.X, Y0 => H / 2.0 + Scale * Centre.Y);
   end Fit;

   --  The map: drawn once per map version into an image (a pixel per cell) -

   Map_Surface : Cairo_Surface := Null_Surface;
   Map_Drawn   : Natural := 0;

   procedure Prepare_Map (S : Scene) is
      G : constant Grid_Access := S.Map;
   begin
      if G = null or else (Map_Drawn = S.Map_Version and then Map_Surface /= Null_Surface) then
         return;
      end if;
      if Map_Surface /= Null_Surface then
         Surface_Destroy (Map_Surface);
      end if;
      Map_Surface := Cairo.Image_Surface.Create
        (Cairo.Image_Surface.Cairo_Format_ARGB32,
         Gint (Sancta.Robot.Grids.Width (G.all)), Gint (Sancta.Robot.Grids.Height (G.all)));
      declare
         Cr : constant Cairo_Context := Create (Map_Surface);
         H  : constant Integer := Sancta.Robot.Grids.Height (G.all);

         procedure Add_Rectangle (Row, First_Column, Last_Column : Integer) is
         begin
            Rectangle (Cr, Gdouble (First_Column), Gdouble (H - 1 - Row),
                       Gdouble (Last_Column - First_Column + 1), 1.0);
         end Add_Rectangle;

         procedure Add_Rectangles is new Sancta.Robot.Grids.For_Each_Occupied_Run (Add_Rectangle);
      begin
         Set_Source_Rgb (Cr, 1.0, 1.0, 1.0);
         Paint (Cr);
         Set_Source_Rgb (Cr, 0.22, 0.22, 0.25);
         Add_Rectangles (G.all);
         Fill (Cr);
         Destroy (Cr);
      end;
      Map_Drawn := S.Map_Version;
   end Prepare_Map;

   procedure Draw_Map (Cr : Cairo_Context; S : Scene; T : Transform) is
      G : constant Grid_Access := S.Map;
   begin
      if G = null then
         return;
      end if;
      Prepare_Map (S);
      declare
         Top_Left : constant Pixel :=
           Px (T, (G.Origin.X,
                   G.Origin.Y + Real (Sancta.Robot.Grids.Height (G.all)) * G.Resolution));
         K        : constant Gdouble := Gdouble (T.Scale * G.Resolution);
      begin
         Save (Cr);
         Translate (Cr, Top_Left.X, Top_Left.Y);
         Scale (Cr, K, K);
         Set_Source_Surface (Cr, Map_Surface, 0.0, 0.0);
         Paint (Cr);
         Restore (Cr);
      end;
   end Draw_Map;

   --  Small drawing helpers -------------------------------------------------

   procedure Circle (Cr : Cairo_Context; At_Pixel : Pixel; Radius : Gdouble) is
   begin
      New_Sub_Path (Cr);
      Arc (Cr, At_Pixel.X, At_Pixel.Y, Radius, 0.0, 2.0 * Ada.Numerics.Pi);
   end Circle;

   procedure Line (Cr : Cairo_Context; A, B : Pixel) is
   begin
      Move_To (Cr, A.X, A.Y);
      Line_To (Cr, B.X, B.Y);
   end Line;

   procedure Text
     (Cr     : Cairo_Context;
      X, Y   : Gdouble;
      Words  : String;
      Size   : Gdouble := 12.0;
      Bold   : Boolean := False;
      Colour : RGB := Ink;
      Mono   : Boolean := False;
      Halo   : Boolean := False)
   is
      --  Halo: a white outline under the letters, legible over walls and
      --  tours.
   begin
      Select_Font_Face (Cr, (if Mono then "DejaVu Sans Mono" else "DejaVu Sans"),
                        Cairo_Font_Slant_Normal,
                        (if Bold then Cairo_Font_Weight_Bold else Cairo_Font_Weight_Normal));
      Set_Font_Size (Cr, Size);
      Move_To (Cr, X, Y);
      if Halo then
         Text_Path (Cr, Words);
         Set (Cr, (1.0, 1.0, 1.0), 0.9);
         Set_Line_Width (Cr, 3.0);
         Set_Line_Join (Cr, Cairo_Line_Join_Round);
         Stroke_Preserve (Cr);
         Set (Cr, Colour);
         Fill (Cr);
      else
         Set (Cr, Colour);
         Show_Text (Cr, Words);
      end if;
   end Text;

   procedure Label
     (Cr : Cairo_Context; X, Y : Gdouble; Words : String; Colour : RGB; Size : Gdouble := 12.0)
   is
      Width : constant Gdouble := Gdouble (Words'Length) * Size * 0.62 + 6.0;
   begin
      Set (Cr, (1.0, 1.0, 1.0), 0.85);
      Rectangle (Cr, X - 3.0, Y - Size, Width, Size + 4.0);
      Fill (Cr);
      Text (Cr, X, Y, Words, Size, Bold => True, Colour => Colour);
   end Label;

   --  Tasks and tours -------------------------------------------------------

   function Entry_Of (T : Task_View; Choice : Natural) return Point is
     (if To_String (T.Kind) = "explore" and then Choice = 2 and then T.Points.Length >= 2
      then T.Points (2)
      elsif To_String (T.Kind) = "choose" and then Choice in 1 .. Natural (T.Points.Length)
      then T.Points (Choice)
      else T.Points (1));

   function Exit_Of (T : Task_View; Choice : Natural) return Point is
     (if To_String (T.Kind) = "explore" and then T.Points.Length >= 2
      then (if Choice = 2 then T.Points (1) else T.Points (2))
      else Entry_Of (T, Choice));

   function Tour_Points (S : Scene; R : Robot_View) return Point_Vectors.Vector is
      Result : Point_Vectors.Vector;
   begin
      Result.Append (Position (R.Where));
      for K in 1 .. Natural (R.Tour.Length) loop
         declare
            Index : constant Natural := Find_Task (S, R.Tour (K));
         begin
            if Index > 0 then
               declare
                  T      : constant Task_View := S.Tasks (Index);
                  Choice : constant Natural :=
                    (if Natural (R.Choices.Length) >= K then R.Choices (K) else T.Choice);
               begin
                  Result.Append (Entry_Of (T, Choice));
                  if Exit_Of (T, Choice) /= Entry_Of (T, Choice) then
                     Result.Append (Exit_Of (T, Choice));
                  end if;
               end;
            end if;
         end;
      end loop;
      return Result;
   end Tour_Points;

   function State_Colour (S : Scene; T : Task_View) return RGB is
     (case T.State is
         when Scenes.Pending               => Pending,
         when Done                         => Done_Fill,
         when Assigned | Active | Reallocated => Robot_Colour (S, To_String (T.Robot)));

   procedure Tick (Cr : Cairo_Context; Centre : Pixel; Radius : Gdouble) is
      --  A done task's check mark, black, inside its marker.
   begin
      Move_To (Cr, Centre.X - 0.55 * Radius, Centre.Y);
      Line_To (Cr, Centre.X - 0.15 * Radius, Centre.Y + 0.45 * Radius);
      Line_To (Cr, Centre.X + 0.6 * Radius, Centre.Y - 0.5 * Radius);
      Set (Cr, Ink);
      Set_Line_Width (Cr, Gdouble'Max (1.5, 0.3 * Radius));
      Stroke (Cr);
   end Tick;

   function Task_Radius (Tr : Transform) return Gdouble is
     (Gdouble (Real'Max (5.0, 0.22 * Tr.Scale)));

   function Path_Width (Tr : Transform) return Gdouble is
     (Gdouble (Real'Max (4.0, 0.15 * Tr.Scale)));
   --  Of an explore task's line.

   Task_Text : constant Gdouble := 10.0;
   --  The size of task names, drawn right of the marker, baseline at its top.

   procedure Draw_Task (Cr : Cairo_Context; S : Scene; T : Task_View; Tr : Transform) is
      C      : constant RGB := State_Colour (S, T);
      Radius : constant Gdouble := Task_Radius (Tr);
      Kind   : constant String := To_String (T.Kind);
      Filled : constant Boolean := T.State in Active | Done | Reallocated;
      Where  : constant Pixel := Px (Tr, T.Points (1));

      procedure Marker (P : Pixel; Colour : RGB; Fill_It : Boolean; Square : Boolean) is
      begin
         if Square then
            Rectangle (Cr, P.X - Radius, P.Y - Radius, 2.0 * Radius, 2.0 * Radius);
         else
            Circle (Cr, P, Radius);
         end if;
         Set (Cr, (if Fill_It then Colour else (1.0, 1.0, 1.0)));
         Fill_Preserve (Cr);
         Set (Cr, (if Colour = Done_Fill then Done_Edge else Colour));
         Set_Line_Width (Cr, 2.0);
         Stroke (Cr);
         if Colour = Done_Fill then
            Tick (Cr, P, Radius);
         end if;
      end Marker;
   begin
      Set_Dash (Cr, No_Dashes, 0.0);
      if Kind = "explore" and then T.Points.Length >= 2 then
         declare
            A : constant Pixel := Px (Tr, Entry_Of (T, T.Choice));
            B : constant Pixel := Px (Tr, Exit_Of (T, T.Choice));
            Angle : constant Real := Math.Arctan (Real (B.Y - A.Y), Real (B.X - A.X));
            Mid : constant Pixel := ((A.X + B.X) / 2.0, (A.Y + B.Y) / 2.0);
         begin
            Set (Cr, C, (if T.State = Scenes.Pending then 0.6 else 0.9));
            Set_Line_Width (Cr, Path_Width (Tr));
            Line (Cr, A, B);
            Stroke (Cr);
            if T.Choice > 0 then
               --  The direction chosen: an arrow head at the middle.
               Move_To (Cr, Mid.X + Gdouble (9.0 * Math.Cos (Angle)),
                        Mid.Y + Gdouble (9.0 * Math.Sin (Angle)));
               Line_To (Cr, Mid.X + Gdouble (7.0 * Math.Cos (Angle + 2.4)),
                        Mid.Y + Gdouble (7.0 * Math.Sin (Angle + 2.4)));
               Line_To (Cr, Mid.X + Gdouble (7.0 * Math.Cos (Angle - 2.4)),
                        Mid.Y + Gdouble (7.0 * Math.Sin (Angle - 2.4)));
               Close_Path (Cr);
               Set (Cr, Ink);
               Fill (Cr);
            end if;
            Circle (Cr, A, Radius * 0.6);
            Circle (Cr, B, Radius * 0.6);
            Set (Cr, C);
            Fill (Cr);
            if T.State = Done then
               Tick (Cr, A, Radius);
            end if;
         end;
      elsif Kind = "choose" then
         for K in 1 .. Natural (T.Points.Length) loop
            if K /= T.Choice then
               --  An OR alternative not chosen: greyed, dashed.
               Set_Dash (Cr, [3.0, 3.0], 0.0);
               Marker (Px (Tr, T.Points (K)), Greyed, Fill_It => False, Square => True);
               Set_Dash (Cr, No_Dashes, 0.0);
            end if;
         end loop;
         if T.Choice > 0 then
            Marker (Px (Tr, T.Points (T.Choice)), C, Filled, Square => True);
         end if;
      else
         Marker (Where, C, Filled, Square => False);
      end if;
      if T.State = Reallocated then
         Circle (Cr, Px (Tr, Entry_Of (T, T.Choice)), Radius + 3.0);
         Set (Cr, Realloc);
         Set_Line_Width (Cr, 2.0);
         Set_Dash (Cr, [3.0, 2.0], 0.0);
         Stroke (Cr);
         Set_Dash (Cr, No_Dashes, 0.0);
      end if;
      Text (Cr, Where.X + Radius + 2.0, Where.Y - Radius, To_String (T.Id), Task_Text,
            Colour => (0.25, 0.25, 0.25), Halo => True);
   end Draw_Task;

   procedure Draw_Tour (Cr : Cairo_Context; S : Scene; R : Robot_View; Tr : Transform) is
      Points : constant Point_Vectors.Vector := Tour_Points (S, R);
   begin
      if Points.Length < 2 or else R.Lost or else R.Plan_Round /= S.Plan_Round then
         return;
         --  A tour of another round's plan (this robot or the view behind
         --  the team) would contradict the tasks' colours: not drawn.
      end if;
      Set (Cr, Colour_Of (R.Colour), 0.9);
      Set_Line_Width (Cr, 2.5);
      Set_Dash (Cr, [9.0, 5.0], 0.0);
      Move_To (Cr, Px (Tr, Points (1)).X, Px (Tr, Points (1)).Y);
      for K in 2 .. Natural (Points.Length) loop
         Line_To (Cr, Px (Tr, Points (K)).X, Px (Tr, Points (K)).Y);
      end loop;
      Stroke (Cr);
      Set_Dash (Cr, No_Dashes, 0.0);
   end Draw_Tour;

   --  Robots ------------------------------------------------------------------

   procedure Draw_Trail (Cr : Cairo_Context; R : Robot_View; Tr : Transform) is
   begin
      if R.Trail.Length < 2 then
         return;
      end if;
      Set (Cr, (if R.Lost then Lost_Colour else Colour_Of (R.Colour)), 0.35);
      Set_Line_Width (Cr, 3.0);
      Set_Line_Join (Cr, Cairo_Line_Join_Round);
      Move_To (Cr, Px (Tr, R.Trail (1)).X, Px (Tr, R.Trail (1)).Y);
      for K in 2 .. Natural (R.Trail.Length) loop
         Line_To (Cr, Px (Tr, R.Trail (K)).X, Px (Tr, R.Trail (K)).Y);
      end loop;
      Stroke (Cr);
   end Draw_Trail;

   procedure Draw_Scan (Cr : Cairo_Context; R : Robot_View; Tr : Transform) is
   begin
      Set (Cr, (0.85, 0.10, 0.45), 0.7);
      for H of R.Scan loop
         Circle (Cr, Px (Tr, H), 1.6);
      end loop;
      Fill (Cr);
   end Draw_Scan;

   function Body_Radius (Tr : Transform) return Gdouble is
     (Gdouble (Real'Max (8.0, 0.3 * Tr.Scale)));

   procedure Draw_Robot (Cr : Cairo_Context; R : Robot_View; Tr : Transform) is
      Centre : constant Pixel := Px (Tr, Position (R.Where));
      Radius : constant Gdouble := Body_Radius (Tr);
      Nose   : constant Pixel :=
        (Centre.X + Radius * Gdouble (Math.Cos (R.Where.Yaw)),
         Centre.Y - Radius * Gdouble (Math.Sin (R.Where.Yaw)));
   begin
      Circle (Cr, Centre, Radius);
      Set (Cr, (if R.Lost then Lost_Colour else Colour_Of (R.Colour)));
      Fill_Preserve (Cr);
      Set (Cr, Ink);
      Set_Line_Width (Cr, 1.5);
      Stroke (Cr);
      Set (Cr, (1.0, 1.0, 1.0));
      Set_Line_Width (Cr, 2.5);
      Line (Cr, Centre, Nose);
      Stroke (Cr);
      if R.Lost then
         Set (Cr, Lost_Mark);
         Set_Line_Width (Cr, 3.5);
         Line (Cr, (Centre.X - Radius - 3.0, Centre.Y - Radius - 3.0),
               (Centre.X + Radius + 3.0, Centre.Y + Radius + 3.0));
         Line (Cr, (Centre.X - Radius - 3.0, Centre.Y + Radius + 3.0),
               (Centre.X + Radius + 3.0, Centre.Y - Radius - 3.0));
         Stroke (Cr);
      end if;
   end Draw_Robot;

   function Robot_Name (R : Robot_View) return String is
     (To_String (R.Id) & (if R.Lost then " LOST" else ""));

   Robot_Text : constant Gdouble := 13.0;

   function Label_Width (Words : String; Size : Gdouble) return Gdouble is
     (Gdouble (Words'Length) * Size * 0.62 + 6.0);
   --  Of Label's white box.

   procedure Draw_Robot_Labels
     (Cr : Cairo_Context; S : Scene; Tr : Transform; Width, Height : Natural)
   is
      --  Robot names where they cover no task name, task marker nor robot
      --  (Rendering.Place_Labels, the placer of the report pictures): drawn
      --  up right of the robot whatever was there, r2's name hid task "s1b".
      package R renames Sancta.Simulation.Rendering;
      type Bits is array (Natural range <>, Natural range <>) of Boolean with Pack;
      type Bits_Access is access Bits;
      procedure Free is new Ada.Unchecked_Deallocation (Bits, Bits_Access);
      N       : constant Natural := Natural (S.Robots.Length);
      Radius  : constant Gdouble := Body_Radius (Tr);
      Marks   : constant Gdouble := Task_Radius (Tr) + 2.0;
      Taken   : Bits_Access;
      --  Pixels drawn on by what a label should not cover.

      procedure Mark (X1, Y1, X2, Y2 : Gdouble) is
         Low_X  : constant Integer := Integer (Gdouble'Max (0.0, Gdouble'Floor (X1)));
         Low_Y  : constant Integer := Integer (Gdouble'Max (0.0, Gdouble'Floor (Y1)));
         High_X : constant Integer :=
           Integer (Gdouble'Min (Gdouble (Width - 1), Gdouble'Ceiling (X2)));
         High_Y : constant Integer :=
           Integer (Gdouble'Min (Gdouble (Height - 1), Gdouble'Ceiling (Y2)));
      begin
         for Y in Low_Y .. High_Y loop
            for X in Low_X .. High_X loop
               Taken (X, Y) := True;
            end loop;
         end loop;
      end Mark;

      procedure Mark_Square (P : Pixel; Half : Gdouble) is
      begin
         if P.X in -Half .. Gdouble (Width) + Half and then P.Y in -Half .. Gdouble (Height) + Half
         then
            Mark (P.X - Half, P.Y - Half, P.X + Half, P.Y + Half);
         end if;
      end Mark_Square;

      function Inked (X, Y : Integer) return Boolean is
        (X in 0 .. Width - 1 and then Y in 0 .. Height - 1 and then Taken (X, Y));
   begin
      if N = 0 or else Width = 0 or else Height = 0 then
         return;
      end if;
      Taken := new Bits'[0 .. Width - 1 => [0 .. Height - 1 => False]];
      for T of S.Tasks loop
         declare
            Where : constant Pixel := Px (Tr, T.Points (1));
            Left  : constant Gdouble := Where.X + Marks;
         begin
            --  The name as Draw_Task writes it (halo included), the markers.
            Mark_Square (Where, Marks);
            if Left < Gdouble (Width) and then Where.Y in -20.0 .. Gdouble (Height) + 20.0 then
               Mark (Left - 2.0, Where.Y - Marks - Task_Text, Left
                     + Gdouble (Length (T.Id)) * Task_Text * 0.62 + 2.0, Where.Y - Marks + 4.0);
            end if;
            for P of T.Points loop
               Mark_Square (Px (Tr, P), Marks);
            end loop;
            if To_String (T.Kind) = "explore" and then T.Points.Length >= 2 then
               declare
                  A     : constant Pixel := Px (Tr, T.Points (1));
                  B     : constant Pixel := Px (Tr, T.Points (2));
                  Steps : constant Natural := Natural'Min
                    (2_000, Natural (Gdouble'Max (abs (B.X - A.X), abs (B.Y - A.Y)) / 2.0));
               begin
                  for K in 0 .. Steps loop
                     Mark_Square ((A.X + (B.X - A.X) * Gdouble (K) / Gdouble (Steps + 1),
                                   A.Y + (B.Y - A.Y) * Gdouble (K) / Gdouble (Steps + 1)),
                                  Path_Width (Tr) / 2.0 + 1.0);
                  end loop;
               end;
            end if;
         end;
      end loop;
      for Robot of S.Robots loop
         Mark_Square (Px (Tr, Position (Robot.Where)), Radius + 2.0);
      end loop;
      declare
         Xs, Ys, Widths : R.Pixel_Array (1 .. N);
         K              : Natural := 0;
      begin
         for Robot of S.Robots loop
            K := K + 1;
            Xs (K) := Integer (Px (Tr, Position (Robot.Where)).X);
            Ys (K) := Integer (Px (Tr, Position (Robot.Where)).Y);
            Widths (K) := Integer (Label_Width (Robot_Name (Robot), Robot_Text));
         end loop;
         declare
            Boxes : constant R.Label_Boxes := R.Place_Labels
              (Xs, Ys, Widths, Integer (Robot_Text) + 4, 0, 0, Width - 1, Height - 1,
               Marker_Radius => Natural (Radius) + 3, Ink => Inked'Access);
            --  3 pixels beyond the body: clear of a lost robot's cross.
         begin
            K := 0;
            for Robot of S.Robots loop
               K := K + 1;
               declare
                  B      : constant R.Label_Box := Boxes (K);
                  Colour : constant RGB :=
                    (if Robot.Lost then Lost_Mark else Colour_Of (Robot.Colour));
               begin
                  if B.Leader then
                     Set (Cr, Colour);
                     Set_Line_Width (Cr, 1.5);
                     Line (Cr, (Gdouble (Xs (K)), Gdouble (Ys (K))),
                           (Gdouble (B.X + B.Width / 2), Gdouble (B.Y + B.Height / 2)));
                     Stroke (Cr);
                  end if;
                  Label (Cr, Gdouble (B.X) + 3.0, Gdouble (B.Y) + Robot_Text, Robot_Name (Robot),
                         Colour, Robot_Text);
               end;
            end loop;
         end;
      end;
      Free (Taken);
   end Draw_Robot_Labels;

   --  The side panel ----------------------------------------------------------

   procedure Swatch (Cr : Cairo_Context; X, Y : Gdouble; C : RGB; Round : Boolean := False) is
   begin
      if Round then
         Circle (Cr, (X + 6.0, Y - 5.0), 6.0);
      else
         Rectangle (Cr, X, Y - 11.0, 12.0, 12.0);
      end if;
      Set (Cr, C);
      Fill_Preserve (Cr);
      Set (Cr, Ink);
      Set_Line_Width (Cr, 1.0);
      Stroke (Cr);
   end Swatch;

   procedure Draw_Panel
     (Cr : Cairo_Context; S : Scene; Left : Gdouble; Width, Height : Natural)
   is
      X     : constant Gdouble := Left + 12.0;
      Y     : Gdouble := 24.0;
      function Chars (Size : Gdouble) return Positive is
        (Positive'Max (10, Integer ((Gdouble (Width) - Left - 20.0) / (Size * 0.56))));
      --  The characters of a line of that font size across the panel.

      procedure Row (Words : String; Size : Gdouble := 12.0; Bold : Boolean := False;
                     Colour : RGB := Ink; Indent : Gdouble := 0.0) is
      begin
         Text (Cr, X + Indent, Y,
               (if Words'Length > Chars (Size)
                then Words (Words'First .. Words'First + Chars (Size) - 1)
                else Words), Size, Bold, Colour);
         Y := Y + Size + 5.0;
      end Row;

      function Pad (Words : String; Width : Positive) return String is
        (if Words'Length >= Width then Words else Words & [1 .. Width - Words'Length => ' ']);
   begin
      Set_Source_Rgb (Cr, 0.96, 0.96, 0.95);
      Rectangle (Cr, Left, 0.0, Gdouble (Width) - Left, Gdouble (Height));
      Fill (Cr);
      Set_Source_Rgb (Cr, 0.6, 0.6, 0.6);
      Set_Line_Width (Cr, 1.0);
      Line (Cr, (Left + 0.5, 0.0), (Left + 0.5, Gdouble (Height)));
      Stroke (Cr);

      Row ("SANCTA team: " & (if S.Team = Null_Unbounded_String then "(waiting for a relay)"
                             else To_String (S.Team)), 15.0, Bold => True);
      Row ("round" & S.Round'Image & (if S.Plan_Round = 0 then ", no plan yet"
                                      elsif S.Plan_Round = S.Round then ", planned by "
                                        & To_String (S.Proposer)
                                      else ", planning (plan of round" & S.Plan_Round'Image
                                        & ")"));
      Row ("tasks done " & Trim (Tasks_Done (S)) & " / " & Trim (Natural (S.Tasks.Length)));
      Row ("makespan " & Img (S.Makespan) & " m   total " & Img (S.Total) & " m");
      Y := Y + 6.0;
      Text (Cr, X + 18.0, Y, Pad ("robot", 6) & Pad ("state", 6) & Pad ("done", 5)
            & Pad ("left", 5) & Pad ("dist", 7) & "plan", 11.0, Bold => True, Mono => True);
      Y := Y + 16.0;
      for R of S.Robots loop
         Swatch (Cr, X, Y, (if R.Lost then Lost_Colour else Colour_Of (R.Colour)));
         Text (Cr, X + 18.0, Y,
               Pad (To_String (R.Id), 6) & Pad ((if R.Lost then "LOST" else "alive"), 6)
               & Pad (Trim (R.Done), 5) & Pad (Trim (R.Left), 5)
               & Pad (Img (R.Distance), 7) & Img (R.Planned_Cost), 11.0,
               Colour => (if R.Lost then Lost_Mark else Ink), Mono => True);
         Y := Y + 14.0;
         Row ((if R.Lost then "last seen doing: " else "") & To_String (R.Status), 10.0,
              Colour => (0.35, 0.35, 0.35), Indent => 18.0);
      end loop;
      Y := Y + 6.0;
      Row ("tasks", 12.0, Bold => True);
      declare
         Items : constant array (1 .. 7) of Unbounded_String :=
           [To_Unbounded_String ("pending"), To_Unbounded_String ("assigned (robot's colour)"),
            To_Unbounded_String ("under way"), To_Unbounded_String ("done"),
            To_Unbounded_String ("re-allocated (its robot lost)"),
            To_Unbounded_String ("OR alternative not chosen"),
            To_Unbounded_String ("robot lost (last pose seen)")];
         function Here return Pixel is ((X + 6.0, Y - 5.0));
         --  The centre of this row's round swatch.
      begin
         for K in Items'Range loop
            case K is
               when 1 => Swatch (Cr, X, Y, (1.0, 1.0, 1.0), Round => True);
                  Circle (Cr, Here, 6.0);
                  Set (Cr, Pending);
                  Set_Line_Width (Cr, 2.0);
                  Stroke (Cr);
               when 2 => Swatch (Cr, X, Y, (1.0, 1.0, 1.0), Round => True);
                  Circle (Cr, Here, 6.0);
                  Set (Cr, Colour_Of (1));
                  Set_Line_Width (Cr, 2.0);
                  Stroke (Cr);
               when 3 => Swatch (Cr, X, Y, Colour_Of (1), Round => True);
               when 4 => Swatch (Cr, X, Y, Done_Fill, Round => True);
                  Tick (Cr, Here, 6.0);
               when 5 => Swatch (Cr, X, Y, Colour_Of (1), Round => True);
                  Circle (Cr, Here, 9.0);
                  Set (Cr, Realloc);
                  Set_Line_Width (Cr, 2.0);
                  Set_Dash (Cr, [3.0, 2.0], 0.0);
                  Stroke (Cr);
                  Set_Dash (Cr, No_Dashes, 0.0);
               when 6 =>
                  Set_Dash (Cr, [3.0, 3.0], 0.0);
                  Rectangle (Cr, X, Y - 11.0, 12.0, 12.0);
                  Set (Cr, Greyed);
                  Set_Line_Width (Cr, 2.0);
                  Stroke (Cr);
                  Set_Dash (Cr, No_Dashes, 0.0);
               when others => Swatch (Cr, X, Y, Lost_Colour, Round => True);
                  Set (Cr, Lost_Mark);
                  Set_Line_Width (Cr, 2.5);
                  Line (Cr, (Here.X - 7.0, Here.Y - 7.0),
                        (Here.X + 7.0, Here.Y + 7.0));
                  Line (Cr, (Here.X - 7.0, Here.Y + 7.0),
                        (Here.X + 7.0, Here.Y - 7.0));
                  Stroke (Cr);
            end case;
            Text (Cr, X + 20.0, Y, To_String (Items (K)), 11.0);
            Y := Y + 16.0;
         end loop;
      end;
      Text (Cr, X, Y, "dashed: planned tours; faint: trails", 10.0,
            Colour => (0.35, 0.35, 0.35));
      Y := Y + 20.0;
      Row ("events (s since this view started)", 12.0, Bold => True);
      declare
         Fits   : constant Positive := Chars (10.0);
         function Line (K : Positive) return String is
           (Img (Real (S.Events (K).At_Time)) & "  " & To_String (S.Events (K).Text));
         function Needed (K : Positive) return Positive is
           (if Line (K)'Length > Fits then 2 else 1);
         Budget : Integer := Integer ((Gdouble (Height) - Y - 6.0) / 14.0);
         First  : Positive := Natural (S.Events.Length) + 1;
      begin
         --  The newest events that fit, a long one on two lines.
         while First > 1 and then Budget >= Needed (First - 1) loop
            First := First - 1;
            Budget := Budget - Needed (First);
         end loop;
         for K in First .. Natural (S.Events.Length) loop
            declare
               Words : constant String := Line (K);
            begin
               if Words'Length > Fits then
                  declare
                     Cut : Natural := Ada.Strings.Fixed.Index
                       (Words (Words'First .. Words'First + Fits - 1), " ",
                        Going => Ada.Strings.Backward);
                     --  The line breaks at the last space that fits.
                  begin
                     if Cut <= Words'First + 8 then
                        Cut := Words'First + Fits - 1;
                     end if;
                     Row (Words (Words'First .. Cut), 10.0);
                     Y := Y - 1.0;
                     Row ("      " & Words (Cut + 1 .. Words'Last), 10.0);
                  end;
               else
                  Row (Words, 10.0);
               end if;
               Y := Y - 1.0;
            end;
         end loop;
      end;
   end Draw_Panel;

   --  Everything -------------------------------------------------------------

   procedure Draw
     (Cr      : Cairo_Context;
      S       : Scene;
      Width   : Natural;
      Height  : Natural;
      Options : View_Options;
      T       : out Transform)
   is
      Map_W : constant Natural := Map_Width (Width, Options);
   begin
      T := Fit (S, Width, Height, Options);
      Save (Cr);
      Rectangle (Cr, 0.0, 0.0, Gdouble (Map_W), Gdouble (Height));
      Clip (Cr);
      Set_Source_Rgb (Cr, 0.86, 0.87, 0.89);
      Paint (Cr);
      Set_Line_Cap (Cr, Cairo_Line_Cap_Round);
      Draw_Map (Cr, S, T);
      if Options.Show_Trails then
         for R of S.Robots loop
            Draw_Trail (Cr, R, T);
         end loop;
      end if;
      for R of S.Robots loop
         Draw_Tour (Cr, S, R, T);
      end loop;
      for Task_Item of S.Tasks loop
         Draw_Task (Cr, S, Task_Item, T);
      end loop;
      if Options.Show_Scans then
         for R of S.Robots loop
            Draw_Scan (Cr, R, T);
         end loop;
      end if;
      for R of S.Robots loop
         Draw_Robot (Cr, R, T);
      end loop;
      Draw_Robot_Labels (Cr, S, T, Map_W, Height);
      Label (Cr, 10.0, 20.0,
             "t " & Img (Real (S.Age)) & " s   samples" & S.Samples'Image
             & (if S.Rejected > 0 then "   rejected" & S.Rejected'Image else "")
             & (if Options.Paused then "   PAUSED" else "")
             & (if Options.Follow /= Null_Unbounded_String
                then "   following " & To_String (Options.Follow) else "")
             & (if S.Robots.Is_Empty then "   waiting for GUI relays" else ""),
             Ink, 12.0);
      Restore (Cr);
      if Map_W < Width then
         Draw_Panel (Cr, S, Gdouble (Map_W), Width, Height);
      end if;
   end Draw;

   procedure Write_Snapshot
     (S         : Scene;
      Width     : Positive;
      Height    : Positive;
      Options   : View_Options;
      File_Name : String;
      T         : out Transform)
   is
      Surface : constant Cairo_Surface := Cairo.Image_Surface.Create
        (Cairo.Image_Surface.Cairo_Format_ARGB32, Gint (Width), Gint (Height));
      Cr      : constant Cairo_Context := Create (Surface);
      Status  : Cairo_Status;
   begin
      Draw (Cr, S, Width, Height, Options, T);
      Destroy (Cr);
      Status := Cairo.Png.Write_To_Png (Surface, File_Name);
      Surface_Destroy (Surface);
      if Status /= Cairo_Status_Success then
         raise Ada.IO_Exceptions.Use_Error with File_Name & ": cannot write the PNG ("
           & Status'Image & ")";
      end if;
   end Write_Snapshot;

   procedure Write_Description
     (S         : Scene;
      T         : Transform;
      File_Name : String;
      Offset_X  : Real := 0.0;
      Offset_Y  : Real := 0.0)
   is
      use Ada.Text_IO;
      F     : File_Type;
      Shift : constant Transform := (T.Scale, T.X0 + Offset_X, T.Y0 + Offset_Y);
      First : Boolean := True;

      type Fixed is delta 0.001 digits 15;
      function Num (X : Real) return String is
        (Ada.Strings.Fixed.Trim
           (Fixed'Image (Fixed (Real'Max (-1.0E9, Real'Min (1.0E9, X)))), Ada.Strings.Left));
      function Num (X : Gdouble) return String is (Num (Real (X)));
      function Signed (X : Real) return String renames Num;
      function Channel (V : Float) return String is (Trim (Integer (V * 255.0)));

      function Escaped (Words : String) return String is
         --  A JSON string's content: quotes and backslashes escaped, other
         --  control characters as '?' (ids come from the wire).
         Result : Unbounded_String;
      begin
         for C of Words loop
            if C = '"' or else C = '\' then
               Append (Result, '\' & C);
            elsif C < ' ' then
               Append (Result, '?');
            else
               Append (Result, C);
            end if;
         end loop;
         return To_String (Result);
      end Escaped;
      Part : constant String := File_Name & ".part";
      --  Written whole, then renamed over File_Name: the window rewrites it
      --  at every frame, and a reader must never see half of it.
      Renamed : Boolean;
   begin
      Create (F, Out_File, Part);
      Put_Line (F, "{""scale"": " & Signed (Shift.Scale) & ", ""x0"": " & Signed (Shift.X0)
                & ", ""y0"": " & Signed (Shift.Y0) & ",");
      Put_Line (F, " ""robot_radius_px"": " & Num (Body_Radius (T)) & ",");
      Put_Line (F, " ""round"": " & Trim (S.Round) & ", ""plan_round"": " & Trim (S.Plan_Round)
                & ", ""tasks"": " & Trim (Natural (S.Tasks.Length)) & ", ""tasks_done"": "
                & Trim (Tasks_Done (S)) & ", ""tasks_reallocated"": "
                & Trim (Tasks_In (S, Reallocated))
                & ", ""rejected"": " & Trim (S.Rejected) & ",");
      Put_Line (F, " ""robots"": [");
      for R of S.Robots loop
         declare
            C    : constant RGB := (if R.Lost then Lost_Colour else Colour_Of (R.Colour));
            P    : constant Pixel := Px (Shift, Position (R.Where));
            Tour : constant Point_Vectors.Vector := Tour_Points (S, R);
         begin
            Put (F, (if First then "  " else " ,") & "{""id"": """ & Escaped (To_String (R.Id))
                 & """, ""lost"": " & (if R.Lost then "true" else "false")
                 & ", ""colour"": [" & Channel (C.R) & ", " & Channel (C.G) & ", "
                 & Channel (C.B) & "], ""x"": " & Signed (R.Where.X) & ", ""y"": "
                 & Signed (R.Where.Y) & ", ""px"": [" & Signed (Real (P.X)) & ", "
                 & Signed (Real (P.Y)) & "], ""tour_px"": [");
            if not R.Lost and then Tour.Length >= 2 and then R.Plan_Round = S.Plan_Round then
               for K in 1 .. Natural (Tour.Length) loop
                  Put (F, (if K = 1 then "" else ", ") & "["
                       & Signed (Real (Px (Shift, Tour (K)).X)) & ", "
                       & Signed (Real (Px (Shift, Tour (K)).Y)) & "]");
               end loop;
            end if;
            Put_Line (F, "]}");
            First := False;
         end;
      end loop;
      Put_Line (F, " ],");
      Put_Line (F, " ""loss_colour"": [" & Channel (Lost_Mark.R) & ", " & Channel (Lost_Mark.G)
                & ", " & Channel (Lost_Mark.B) & "], ""task_radius_px"": "
                & Num (Task_Radius (T)) & ",");
      Put_Line (F, " ""task_markers"": [");
      First := True;
      for Task_Item of S.Tasks loop
         declare
            C : constant RGB := State_Colour (S, Task_Item);
            P : constant Pixel := Px (Shift, Entry_Of (Task_Item, Task_Item.Choice));
         begin
            Put_Line (F, (if First then "  " else " ,") & "{""id"": """
                      & Escaped (To_String (Task_Item.Id)) & """, ""kind"": """
                      & Escaped (To_String (Task_Item.Kind)) & """, ""choice"": "
                      & Trim (Task_Item.Choice) & ", ""state"": """
                      & Ada.Characters.Handling.To_Lower (Task_Item.State'Image)
                      & """, ""fill"": [" & Channel (C.R) & ", " & Channel (C.G) & ", "
                      & Channel (C.B) & "], ""px"": [" & Signed (Real (P.X)) & ", "
                      & Signed (Real (P.Y)) & "]}");
            First := False;
         end;
      end loop;
      Put_Line (F, " ]}");
      Close (F);
      GNAT.OS_Lib.Rename_File (Part, File_Name, Renamed);
      if not Renamed then
         raise Ada.IO_Exceptions.Use_Error with "cannot rename " & Part & " to " & File_Name;
      end if;
   end Write_Description;

end Sancta.Views.Drawing;
