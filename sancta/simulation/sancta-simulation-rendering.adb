with Ada.Directories;
with Ada.Numerics;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with Sancta.Robot.Grids;
with Sancta.Simulation.Glyphs;
with Sancta.Simulation.Text_Files;

package body Sancta.Simulation.Rendering is

   use Ada.Strings.Unbounded;
   use Raster_Images;
   use Robot.Grids;
   use Ada.Numerics.Long_Elementary_Functions;

   function RGB (R, G, B : Byte) return Color is ((R, G, B));

   Palette : constant array (0 .. 9) of Color :=
     [RGB (0, 114, 178), RGB (230, 159, 0), RGB (0, 158, 115), RGB (204, 121, 167),
      RGB (86, 180, 233),
      RGB (51, 34, 136), RGB (153, 153, 51), RGB (170, 68, 153), RGB (221, 204, 119),
      RGB (0, 90, 90)];
   --  The first five: Okabe and Ito's colours for colour-blind readers
   --  (blue, orange, bluish green, reddish purple, sky blue), without their
   --  vermillion (near the red of a loss), black (walls, text) and yellow
   --  (faint on white). Then Tol's muted indigo, olive, purple, sand and a
   --  dark teal: told apart by most readers, not by all. No red: red marks
   --  a lost robot only (Loss_Color).

   function Color_Of (Robot : Positive) return Color is (Palette ((Robot - 1) mod 10));

   function Hex (C : Color) return String is
      Digits_16 : constant String := "0123456789abcdef";
      function Two (B : Byte) return String is
        [Digits_16 (Natural (B) / 16 + 1), Digits_16 (Natural (B) mod 16 + 1)];
   begin
      return "#" & Two (C.R) & Two (C.G) & Two (C.B);
   end Hex;

   Far : constant := 1.0E8;
   --  Pixel coordinates are clamped to -Far .. Far before they become
   --  integers: a point a million kilometres away (a trajectory, a marker)
   --  is drawn as far outside the picture, not an overflow.

   function Clamped (V : Real) return Real is (Real'Max (-Far, Real'Min (Far, V)));

   function To_Pixel (V : Real) return Integer is (Integer (Clamped (V)));
   --  Example: To_Pixel (3.4) = 3; To_Pixel (1.0E300) = 100_000_000.

   function Num (X : Real) return String is
      --  Fixed-point text with two decimals.
      V : constant Long_Long_Integer := Long_Long_Integer (Clamped (X) * 100.0);
      A : constant Long_Long_Integer := abs V;
      F : constant String := Long_Long_Integer'Image (A mod 100);
      Frac : constant String := (if A mod 100 < 10 then "0" & F (2 .. F'Last) else F (2 .. F'Last));
      I : constant String := Long_Long_Integer'Image (A / 100);
   begin
      return (if V < 0 then "-" else "") & I (2 .. I'Last) & "." & Frac;
   end Num;

   ------------------
   -- Place_Labels --
   ------------------

   function Place_Labels
     (Anchors_X, Anchors_Y : Pixel_Array;
      Widths               : Pixel_Array;
      Height               : Natural;
      Left, Top, Right, Bottom : Integer;
      Marker_Radius        : Natural := 4;
      Ink                  : access function (X, Y : Integer) return Boolean := null)
      return Label_Boxes
   is
      N      : constant Natural := Anchors_X'Length;
      Result : Label_Boxes (1 .. N);
      D      : constant Natural := Marker_Radius + 3;
      --  From the anchor to the label's side.

      function Inside (B : Label_Box) return Boolean is
        (B.X >= Left and then B.Y >= Top and then B.X + B.Width - 1 <= Right
         and then B.Y + B.Height - 1 <= Bottom);

      function Overlaps (A, B : Label_Box) return Boolean is
        (A.X <= B.X + B.Width and then B.X <= A.X + A.Width
         and then A.Y <= B.Y + B.Height and then B.Y <= A.Y + A.Height);
      --  With one pixel of air between boxes.

      function Free (B : Label_Box; Placed : Natural; Self : Positive) return Boolean is
      begin
         for K in 1 .. Placed loop
            if Overlaps (B, Result (K)) then
               return False;
            end if;
         end loop;
         --  Nor over another marker.
         for K in 1 .. N loop
            if K /= Self and then Anchors_X (K) in B.X - 3 .. B.X + B.Width + 3
              and then Anchors_Y (K) in B.Y - 3 .. B.Y + B.Height + 3
            then
               return False;
            end if;
         end loop;
         return True;
      end Free;

      function Inked (B : Label_Box; Limit : Natural) return Natural is
         --  Drawn pixels under B and its margin, counted up to Limit.
         Count : Natural := 0;
      begin
         if Ink /= null then
            for Y in B.Y - 1 .. B.Y + B.Height loop
               for X in B.X - 1 .. B.X + B.Width loop
                  if Ink (X, Y) then
                     Count := Count + 1;
                     if Count >= Limit then
                        return Count;
                     end if;
                  end if;
               end loop;
            end loop;
         end if;
         return Count;
      end Inked;
   begin
      for I in 1 .. N loop
         declare
            AX   : constant Integer := Anchors_X (I);
            AY   : constant Integer := Anchors_Y (I);
            W    : constant Natural := Widths (I);
            H    : constant Natural := Height;
            Near : constant array (1 .. 8) of Label_Box :=
              [Label_Box'(AX + D, AY - H / 2, W, H, False),
               Label_Box'(AX - D - W, AY - H / 2, W, H, False),
               Label_Box'(AX - W / 2, AY - H - D + 1, W, H, False),
               Label_Box'(AX - W / 2, AY + D - 1, W, H, False),
               Label_Box'(AX + D - 1, AY - H - D + 2, W, H, False),
               Label_Box'(AX + D - 1, AY + D - 2, W, H, False),
               Label_Box'(AX - D + 1 - W, AY - H - D + 2, W, H, False),
               Label_Box'(AX - D + 1 - W, AY + D - 2, W, H, False)];
            Best  : Natural := Natural'Last;
            --  Score of Result (I) when Found.
            Found : Boolean := False;

            procedure Consider (B : Label_Box; Penalty : Natural) is
            begin
               if Penalty < Best and then Inside (B) and then Free (B, I - 1, I) then
                  declare
                     Score : constant Natural := Penalty + Inked (B, Best - Penalty);
                  begin
                     if Score < Best then
                        Best := Score;
                        Result (I) := B;
                        Found := True;
                     end if;
                  end;
               end if;
            end Consider;
         begin
            for B of Near loop
               Consider (B, 0);
               exit when Best = 0;
            end loop;
            --  Farther, on rings around the marker, with a leader line.
            Ring :
            for Radius in 2 .. 12 loop
               exit Ring when Radius * 10 + 10 >= Best;
               for Step in 0 .. 15 loop
                  declare
                     A  : constant Long_Float := 2.0 * Ada.Numerics.Pi * Long_Float (Step) / 16.0;
                     CX : constant Integer := AX + Integer (Long_Float (Radius * 10) * Cos (A));
                     CY : constant Integer := AY - Integer (Long_Float (Radius * 10) * Sin (A));
                  begin
                     Consider ((CX - W / 2, CY - H / 2, W, H, True), Radius * 10 + 10);
                  end;
               end loop;
            end loop Ring;
            if not Found then
               --  Nowhere free: right of the marker, moved inside.
               Result (I) :=
                 (Integer'Max (Left, Integer'Min (AX + D, Right - W + 1)),
                  Integer'Max (Top, Integer'Min (AY - H / 2, Bottom - H + 1)), W, H, False);
            end if;
         end;
      end loop;
      return Result;
   end Place_Labels;

   --  The band below the world: legend entries left to right (wrapped), the
   --  scale bar at the right of the first line.

   Scale_Bar_Room : constant := 130;

   procedure Legend_Layout
     (S : Scene; Width : Natural; Char_Width : Positive;
      Xs, Lines : out Pixel_Array; Line_Count : out Natural)
   is
      X : Integer := 8;
      L : Natural := 1;
   begin
      Line_Count := (if S.Legend.Is_Empty and then not S.Scale_Bar then 0 else 1);
      for I in 1 .. Natural (S.Legend.Length) loop
         declare
            W : constant Natural := 22 + Length (S.Legend (I).Text) * Char_Width;
         begin
            if X > 8 and then X + W > Width - (if S.Scale_Bar then Scale_Bar_Room else 8) then
               X := 8;
               L := L + 1;
            end if;
            Xs (I) := X;
            Lines (I) := L;
            X := X + W + 14;
            Line_Count := Natural'Max (Line_Count, L);
         end;
      end loop;
   end Legend_Layout;

   function Layout_Height (S : Scene; Width : Natural; Char_Width : Positive;
                           Line_Height : Positive) return Natural is
      Xs, Lines  : Pixel_Array (1 .. Natural (S.Legend.Length));
      Line_Count : Natural;
   begin
      Legend_Layout (S, Width, Char_Width, Xs, Lines, Line_Count);
      return (if Line_Count = 0 then 0 else Line_Count * Line_Height + 8);
   end Layout_Height;

   function Bar_Metres (Scale : Real) return Real is
      Lengths : constant array (1 .. 9) of Real :=
        [1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0];
      Result  : Real := 1.0;
   begin
      for L of Lengths loop
         if L * Scale <= 100.0 then
            Result := L;
         end if;
      end loop;
      return Result;
   end Bar_Metres;
   --  The longest round length drawn in at most 100 pixels.

   function Bar_Text (Metres : Real) return String is
     (Ada.Strings.Fixed.Trim (Integer (Metres)'Image, Ada.Strings.Left) & " m");


   ------------
   -- Render --
   ------------

   function Render (World : Worlds.World; S : Scene; Scale : Real := 20.0) return Image is
      F      : constant Frame := Worlds.Frame_Of (World);
      W_M    : constant Real := Real (F.Width) * F.Resolution;
      H_M    : constant Real := Real (F.Height) * F.Resolution;
      Width  : constant Natural := Natural'Max (1, To_Pixel (W_M * Scale));
      Height : constant Natural := Natural'Max (1, To_Pixel (H_M * Scale));
      --  Of the world; the title band above it and the legend band below.
      Line_H : constant := Glyphs.Glyph_Height + 7;
      Cross  : constant Natural := To_Pixel (Real'Min (0.3 * Scale, 1000.0)) + 1;
      --  Half a marker's cross, pixels.
      Top    : constant Natural := (if Length (S.Title) > 0 then Line_H + 4 else 0);
      Below  : constant Natural := Layout_Height (S, Width, Glyphs.Advance, Line_H);
      Img    : Image :=
        (if Width > Max_Side or else Height + Top + Below > Max_Side
           or else Width * (Height + Top + Below) > Max_Pixels
         then raise Format_Error with "picture too large: lower the scale"
         else Create (Width, Height + Top + Below));

      function PX (P : Point) return Integer is
        (To_Pixel (Real'Floor ((P.X - F.Origin.X) * Scale)) + 1);
      function PY (P : Point) return Integer is
        (Top + Height - To_Pixel (Real'Floor ((P.Y - F.Origin.Y) * Scale)));

      procedure Dot (X, Y, R : Integer; C : Color) is
      begin
         for DX in -R .. R loop
            for DY in -R .. R loop
               if DX * DX + DY * DY <= R * R then
                  Set (Img, X + DX, Y + DY, C);
               end if;
            end loop;
         end loop;
      end Dot;

      procedure Line (A, B : Point; C : Color; R : Natural := 1) is
         X0 : constant Integer := PX (A);
         Y0 : constant Integer := PY (A);
         X1 : constant Integer := PX (B);
         Y1 : constant Integer := PY (B);
         N  : constant Natural := Natural'Max (abs (X1 - X0), abs (Y1 - Y0));
      begin
         if N > 4 * (Width + Height) then
            return;  --  Far outside the picture.
         end if;
         for K in 0 .. N loop
            declare
               T : constant Real := (if N = 0 then 0.0 else Real (K) / Real (N));
            begin
               Dot (X0 + Integer (T * Real (X1 - X0)), Y0 + Integer (T * Real (Y1 - Y0)), R, C);
            end;
         end loop;
      end Line;

      procedure Circle (Center : Point; Radius : Real; C : Color) is
         Steps : constant := 48;
      begin
         for K in 0 .. Steps - 1 loop
            declare
               A0 : constant Real := 2.0 * Pi * Real (K) / Real (Steps);
               A1 : constant Real := 2.0 * Pi * Real (K + 1) / Real (Steps);
            begin
               Line (Transform ((Center.X, Center.Y, A0), (Radius, 0.0)),
                     Transform ((Center.X, Center.Y, A1), (Radius, 0.0)), C, 0);
            end;
         end loop;
      end Circle;
   begin
      --  The world, cell by cell (pixel centres sampled).
      for Y in 1 .. Height loop
         for X in 1 .. Raster_Images.Width (Img) loop
            declare
               WX : constant Real := F.Origin.X + (Real (X) - 0.5) / Scale;
               WY : constant Real := F.Origin.Y + (Real (Height - Y) + 0.5) / Scale;
            begin
               if Worlds.Is_Occupied (World, Column (F, WX), Row (F, WY)) then
                  Set (Img, X, Y + Top, (50, 50, 50));
               end if;
            end;
         end loop;
      end loop;
      for R in 1 .. S.Trajectories.Last_Index loop
         declare
            Path : Point_Vectors.Vector renames S.Trajectories (R);
         begin
            for K in 2 .. Path.Last_Index loop
               Line (Path (K - 1), Path (K), Color_Of (R));
            end loop;
            if not Path.Is_Empty then
               Dot (PX (Path.First_Element), PY (Path.First_Element), 3, Color_Of (R));
            end if;
         end;
      end loop;
      for R in 1 .. S.Robots.Last_Index loop
         declare
            P : constant Pose := S.Robots (R);
         begin
            Circle (Position (P), S.Robot_Radius, Black);
            Line (Position (P), Transform (P, (S.Robot_Radius, 0.0)), Black, 0);
         end;
      end loop;
      for P of S.Lost loop
         Line (P - (0.45, 0.45), P + (0.45, 0.45), Loss_Color, 2);
         Line (P + (-0.45, 0.45), P + (0.45, -0.45), Loss_Color, 2);
      end loop;
      for M of S.Markers loop
         --  A cross of Cross pixels each side (lines one pixel thick).
         Line (M.Where - (0.3, 0.3), M.Where + (0.3, 0.3), Black);
         Line (M.Where + (-0.3, 0.3), M.Where + (0.3, -0.3), Black);
      end loop;
      --  Labels last, over every line, where they fit and hide the least
      --  of what is drawn (Place_Labels).
      declare
         N         : constant Natural := Natural (S.Markers.Length);
         AX, AY, W : Pixel_Array (1 .. N);

         function Inked (X, Y : Integer) return Boolean is
           (X in 1 .. Width and then Y in 1 .. Raster_Images.Height (Img)
            and then Get (Img, X, Y) /= White);
      begin
         for I in 1 .. N loop
            AX (I) := PX (S.Markers (I).Where);
            AY (I) := PY (S.Markers (I).Where);
            W (I) := Glyphs.Text_Width (To_String (S.Markers (I).Label)) + 1;
         end loop;
         declare
            Boxes : constant Label_Boxes :=
              Place_Labels (AX, AY, W, Glyphs.Glyph_Height + 2, 1, Top + 1, Width,
                            Top + Height, Marker_Radius => Cross + 1,
                            Ink => Inked'Access);
         begin
            for I in 1 .. N loop
               if Length (S.Markers (I).Label) > 0 then
                  if Boxes (I).Leader then
                     Line (S.Markers (I).Where,
                           (F.Origin.X + Real (Boxes (I).X + Boxes (I).Width / 2 - 1) / Scale,
                            F.Origin.Y + Real (Top + Height - Boxes (I).Y
                                               - Boxes (I).Height / 2) / Scale),
                           (160, 160, 160), 0);
                  end if;
                  Glyphs.Draw_Text (Img, Boxes (I).X + 1, Boxes (I).Y + 1,
                                    To_String (S.Markers (I).Label), Black);
               end if;
            end loop;
         end;
      end;
      --  Title, legend, scale bar.
      if Top > 0 then
         Glyphs.Draw_Text (Img, 6, 5, To_String (S.Title), Black, Halo => False);
      end if;
      if Below > 0 then
         declare
            Xs, Lines  : Pixel_Array (1 .. Natural (S.Legend.Length));
            Line_Count : Natural;
            Band       : constant Integer := Top + Height;
         begin
            Legend_Layout (S, Width, Glyphs.Advance, Xs, Lines, Line_Count);
            for I in Xs'Range loop
               declare
                  Y : constant Integer := Band + 4 + (Lines (I) - 1) * Line_H + Line_H / 2;
               begin
                  for DX in 0 .. 15 loop
                     for DY in -1 .. 1 loop
                        Set (Img, Xs (I) + DX, Y + DY, S.Legend (I).Color);
                     end loop;
                  end loop;
                  Glyphs.Draw_Text (Img, Xs (I) + 20, Y - Glyphs.Cap_Height / 2,
                                    To_String (S.Legend (I).Text), Black, Halo => False);
               end;
            end loop;
            if S.Scale_Bar then
               declare
                  Metres : constant Real := Bar_Metres (Scale);
                  Pixels : constant Integer := To_Pixel (Metres * Scale);
                  X1     : constant Integer := Width - 8;
                  X0     : constant Integer := X1 - Pixels;
                  Y      : constant Integer := Band + 4 + Line_H / 2;
                  Text   : constant String := Bar_Text (Metres);
               begin
                  for X in X0 .. X1 loop
                     Set (Img, X, Y, Black);
                     Set (Img, X, Y + 1, Black);
                  end loop;
                  for DY in -4 .. 4 loop
                     Set (Img, X0, Y + DY, Black);
                     Set (Img, X1, Y + DY, Black);
                  end loop;
                  Glyphs.Draw_Text (Img, X0 - Glyphs.Text_Width (Text) - 4,
                                    Y - Glyphs.Cap_Height / 2, Text, Black, Halo => False);
               end;
            end if;
         end;
      end if;
      return Img;
   end Render;

   ---------------
   -- Write_SVG --
   ---------------

   procedure Write_SVG
     (World     : Worlds.World;
      S         : Scene;
      File_Name : String;
      Scale     : Real := 20.0)
   is
      use Ada.Text_IO;
      F    : constant Frame := Worlds.Frame_Of (World);
      W_M  : constant Real := Real (F.Width) * F.Resolution;
      H_M  : constant Real := Real (F.Height) * F.Resolution;
      Out_File : File_Type;

      Char_W  : constant := 7;
      --  Pixels per character of the 12-pixel sans-serif labels (DejaVu
      --  Sans averages 0.55 em; a little more for safety).
      Line_H  : constant := 20;
      Width   : constant Natural := To_Pixel (W_M * Scale);
      Top     : constant Natural := (if Length (S.Title) > 0 then 26 else 0);
      Below   : constant Natural := Layout_Height (S, Width, Char_W, Line_H);
      Total_H : constant Real := H_M * Scale + Real (Top + Below);

      function SX (X : Real) return String is (Num ((X - F.Origin.X) * Scale));
      function SY (Y : Real) return String is
        (Num ((F.Origin.Y + H_M - Y) * Scale + Real (Top)));
      function Img (N : Integer) return String is
        (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));
      function Escape (T : String) return String is
         R : Unbounded_String;
      begin
         for C of T loop
            case C is
               when '<' => Append (R, "&lt;");
               when '>' => Append (R, "&gt;");
               when '&' => Append (R, "&amp;");
               when others => Append (R, C);
            end case;
         end loop;
         return To_String (R);
      end Escape;

      procedure Put_Rectangle (Row, First_Column, Last_Column : Integer) is
      begin
         Put_Line (Out_File, "<rect x="""
           & SX (F.Origin.X + Real (First_Column) * F.Resolution)
           & """ y=""" & SY (F.Origin.Y + Real (Row + 1) * F.Resolution)
           & """ width=""" & Num (Real (Last_Column - First_Column + 1) * F.Resolution * Scale)
           & """ height=""" & Num (F.Resolution * Scale) & """/>");
      end Put_Rectangle;

      procedure Put_Rectangles is new Robot.Grids.For_Each_Occupied_Run (Put_Rectangle);
   begin
      Create (Out_File, Ada.Text_IO.Out_File, File_Name);
      Put_Line (Out_File, "<?xml version=""1.0"" encoding=""UTF-8""?>");
      Put_Line (Out_File, "<svg xmlns=""http://www.w3.org/2000/svg"" width="""
                & Num (W_M * Scale) & """ height=""" & Num (Total_H)
                & """ viewBox=""0 0 " & Num (W_M * Scale) & " " & Num (Total_H) & """>");
      Put_Line (Out_File, "<rect width=""100%"" height=""100%"" fill=""white""/>");
      if Top > 0 then
         Put_Line (Out_File, "<text class=""title"" x=""8"" y=""18"" font-size=""15"""
                   & " font-weight=""bold"" font-family=""sans-serif"">"
                   & Escape (To_String (S.Title)) & "</text>");
      end if;
      Put_Line (Out_File, "<g fill=""#323232"">");
      --  Occupied cells, merged into horizontal runs.
      Put_Rectangles (Worlds.Occupancy (World));
      Put_Line (Out_File, "</g>");
      for R in 1 .. S.Trajectories.Last_Index loop
         Put (Out_File, "<polyline fill=""none"" stroke=""" & Hex (Color_Of (R))
              & """ stroke-width=""2"" points=""");
         for P of S.Trajectories (R) loop
            Put (Out_File, SX (P.X) & "," & SY (P.Y) & " ");
         end loop;
         Put_Line (Out_File, """/>");
         if not S.Trajectories (R).Is_Empty then
            Put_Line (Out_File, "<circle cx=""" & SX (S.Trajectories (R).First_Element.X)
                      & """ cy=""" & SY (S.Trajectories (R).First_Element.Y)
                      & """ r=""4"" fill=""" & Hex (Color_Of (R)) & """/>");
         end if;
      end loop;
      for R in 1 .. S.Robots.Last_Index loop
         declare
            P   : constant Pose := S.Robots (R);
            Tip : constant Point := Transform (P, (S.Robot_Radius, 0.0));
         begin
            Put_Line (Out_File, "<circle cx=""" & SX (P.X) & """ cy=""" & SY (P.Y)
                      & """ r=""" & Num (S.Robot_Radius * Scale) & """ fill=""none"""
                      & " stroke=""black""/>");
            Put_Line (Out_File, "<line x1=""" & SX (P.X) & """ y1=""" & SY (P.Y)
                      & """ x2=""" & SX (Tip.X) & """ y2=""" & SY (Tip.Y)
                      & """ stroke=""black""/>");
         end;
      end loop;
      for P of S.Lost loop
         Put_Line (Out_File, "<path class=""lost"" d=""M" & SX (P.X - 0.45) & ","
                   & SY (P.Y - 0.45) & " L" & SX (P.X + 0.45) & "," & SY (P.Y + 0.45)
                   & " M" & SX (P.X - 0.45) & "," & SY (P.Y + 0.45) & " L"
                   & SX (P.X + 0.45) & "," & SY (P.Y - 0.45) & """ stroke=""" & Hex (Loss_Color)
                   & """ stroke-width=""4""/>");
      end loop;
      for M of S.Markers loop
         --  A cross as in the PNG (black: red is a loss's colour).
         Put_Line (Out_File, "<path class=""marker"" d=""M" & SX (M.Where.X - 0.3) & ","
                   & SY (M.Where.Y - 0.3) & " L" & SX (M.Where.X + 0.3) & ","
                   & SY (M.Where.Y + 0.3) & " M" & SX (M.Where.X - 0.3) & ","
                   & SY (M.Where.Y + 0.3) & " L" & SX (M.Where.X + 0.3) & ","
                   & SY (M.Where.Y - 0.3) & """ stroke=""black"" stroke-width=""1.5""/>");
      end loop;
      declare
         N         : constant Natural := Natural (S.Markers.Length);
         AX, AY, W : Pixel_Array (1 .. N);
         function Pix_X (X : Real) return Integer is (To_Pixel ((X - F.Origin.X) * Scale));
         function Pix_Y (Y : Real) return Integer is
           (To_Pixel ((F.Origin.Y + H_M - Y) * Scale) + Top);
         Bare : Scene := S;
      begin
         --  What the labels should hide least: the same picture drawn as
         --  the PNG (without title, bands, labels), one pixel to the right.
         Bare.Title := Null_Unbounded_String;
         Bare.Legend.Clear;
         Bare.Scale_Bar := False;
         for M of Bare.Markers loop
            M.Label := Null_Unbounded_String;
         end loop;
         for I in 1 .. N loop
            AX (I) := Pix_X (S.Markers (I).Where.X);
            AY (I) := Pix_Y (S.Markers (I).Where.Y);
            W (I) := Length (S.Markers (I).Label) * Char_W;
         end loop;
         declare
            function Bare_Picture return Image is
            begin
               return Render (World, Bare, Scale);
            exception
               when Format_Error =>
                  return Create (1, 1);  --  Too large as pixels: labels ignore ink.
            end Bare_Picture;
            Drawn : constant Image := Bare_Picture;
            function Inked (X, Y : Integer) return Boolean is
              (X + 1 in 1 .. Raster_Images.Width (Drawn)
               and then Y - Top in 1 .. Raster_Images.Height (Drawn)
               and then Get (Drawn, X + 1, Y - Top) /= White);
            Boxes : constant Label_Boxes :=
              Place_Labels (AX, AY, W, 13, 1, Top + 1, Width - 1,
                            Top + To_Pixel (H_M * Scale) - 1, Marker_Radius => 5,
                            Ink => Inked'Access);
         begin
            for I in 1 .. N loop
               if Length (S.Markers (I).Label) > 0 then
                  if Boxes (I).Leader then
                     Put_Line (Out_File, "<line x1=""" & Img (AX (I)) & """ y1="""
                               & Img (AY (I)) & """ x2="""
                               & Img (Boxes (I).X + Boxes (I).Width / 2)
                               & """ y2=""" & Img (Boxes (I).Y + Boxes (I).Height / 2)
                               & """ stroke=""#a0a0a0"" stroke-width=""1""/>");
                  end if;
                  Put_Line (Out_File, "<text class=""label"" x=""" & Img (Boxes (I).X)
                            & """ y=""" & Img (Boxes (I).Y + 10)
                            & """ data-width=""" & Img (Boxes (I).Width)
                            & """ font-size=""12"" font-family=""sans-serif"""
                            & " paint-order=""stroke"" stroke=""white"" stroke-width=""3"">"
                            & Escape (To_String (S.Markers (I).Label)) & "</text>");
               end if;
            end loop;
         end;
      end;
      if Below > 0 then
         declare
            Xs, Lines  : Pixel_Array (1 .. Natural (S.Legend.Length));
            Line_Count : Natural;
            Band       : constant Integer := Top + To_Pixel (H_M * Scale);
         begin
            Legend_Layout (S, Width, Char_W, Xs, Lines, Line_Count);
            for I in Xs'Range loop
               declare
                  Y : constant Integer := Band + 4 + (Lines (I) - 1) * Line_H + Line_H / 2;
               begin
                  Put_Line (Out_File, "<line x1=""" & Img (Xs (I)) & """ y1=""" & Img (Y)
                            & """ x2=""" & Img (Xs (I) + 16) & """ y2=""" & Img (Y)
                            & """ stroke=""" & Hex (S.Legend (I).Color)
                            & """ stroke-width=""3""/>");
                  Put_Line (Out_File, "<text class=""legend"" x=""" & Img (Xs (I) + 20)
                            & """ y=""" & Img (Y + 4) & """ data-width="""
                            & Img (Length (S.Legend (I).Text) * Char_W)
                            & """ font-size=""12"" font-family=""sans-serif"">"
                            & Escape (To_String (S.Legend (I).Text)) & "</text>");
               end;
            end loop;
            if S.Scale_Bar then
               declare
                  Metres : constant Real := Bar_Metres (Scale);
                  X1     : constant Integer := Width - 8;
                  X0     : constant Integer := X1 - To_Pixel (Metres * Scale);
                  Y      : constant Integer := Band + 4 + Line_H / 2;
               begin
                  Put_Line (Out_File, "<g class=""scale-bar"" stroke=""black"" stroke-width=""2"">"
                            & "<line x1=""" & Img (X0) & """ y1=""" & Img (Y) & """ x2="""
                            & Img (X1) & """ y2=""" & Img (Y) & """/><line x1=""" & Img (X0)
                            & """ y1=""" & Img (Y - 4) & """ x2=""" & Img (X0)
                            & """ y2=""" & Img (Y + 4) & """/><line x1=""" & Img (X1)
                            & """ y1=""" & Img (Y - 4) & """ x2=""" & Img (X1)
                            & """ y2=""" & Img (Y + 4) & """/></g>");
                  Put_Line (Out_File, "<text class=""scale"" x=""" & Img (X0 - 6)
                            & """ y=""" & Img (Y + 4) & """ data-pixels="""
                            & Img (X1 - X0) & """ text-anchor=""end"" font-size=""12"""
                            & " font-family=""sans-serif"">" & Bar_Text (Metres) & "</text>");
               end;
            end if;
         end;
      end if;
      Put_Line (Out_File, "</svg>");
      Close (Out_File);
   end Write_SVG;

   -----------------------
   -- Read_Trajectories --
   -----------------------

   function Read_Trajectories (File_Name : String) return Path_Vectors.Vector is
      Result  : Path_Vectors.Vector;
      Ignored : Natural;

      procedure Read_Sample (Line : String; Line_No : Positive) is
         C1   : constant Natural := Ada.Strings.Fixed.Index (Line, ",");
         C2   : constant Natural :=
           (if C1 = 0 then 0 else Ada.Strings.Fixed.Index (Line (C1 + 1 .. Line'Last), ","));
         Robot : Integer;
         X, Y  : Real;

         procedure Fail (Reason : String) with No_Return is
         begin
            raise Format_Error with File_Name & ":"
              & Ada.Strings.Fixed.Trim (Line_No'Image, Ada.Strings.Left) & ": " & Reason;
         end Fail;
      begin
         if Line'Length > 0 and then Line (Line'First) /= '#'
           and then not (Line_No = 1 and then Ada.Strings.Fixed.Index (Line, "robot") > 0)
         then
            if C1 = 0 or else C2 = 0 then
               Fail ("expected ""robot,x,y""");
            end if;
            begin
               Robot := Integer'Value (Line (Line'First .. C1 - 1));
               X := Real'Value (Line (C1 + 1 .. C2 - 1));
               Y := Real'Value (Line (C2 + 1 .. Line'Last));
            exception
               when Constraint_Error =>
                  Fail ("expected ""robot,x,y"" with a robot number and two reals");
            end;
            if Robot not in 1 .. 10_000 then
               Fail ("robot number out of 1 .. 10000");
            elsif not (X'Valid and then Y'Valid) or else abs X > 1.0E12 or else abs Y > 1.0E12
            then
               --  1e400 reads as an infinity.
               Fail ("x and y must be numbers within 1e12");
            end if;
            while Result.Last_Index < Robot loop
               Result.Append (Point_Vectors.Empty_Vector);
            end loop;
            Result (Robot).Append (Point'(X, Y));
         end if;
      end Read_Sample;

      procedure Read_Samples is new Text_Files.Read_Lines (Read_Sample);
   begin
      Read_Samples (File_Name, Ignored);
      return Result;
   end Read_Trajectories;

   procedure Write_Trajectories (Paths : Path_Vectors.Vector; File_Name : String) is
      use Ada.Text_IO;
      F : File_Type;
   begin
      Create (F, Out_File, File_Name);
      Put_Line (F, "robot,x,y");
      for R in 1 .. Paths.Last_Index loop
         for P of Paths (R) loop
            Put_Line (F, Ada.Strings.Fixed.Trim (R'Image, Ada.Strings.Left) & ","
                      & Num (P.X) & "," & Num (P.Y));
         end loop;
      end loop;
      Close (F);
   end Write_Trajectories;

   procedure Write_Map (World : Worlds.World; Base_Name : String) is
      use Ada.Text_IO;
      F   : constant Frame := Worlds.Frame_Of (World);
      Img : Image := Create (F.Width, F.Height, (254, 254, 254));
      Y_F : File_Type;
   begin
      for I in 0 .. F.Width - 1 loop
         for J in 0 .. F.Height - 1 loop
            if Worlds.Is_Occupied (World, I, J) then
               Set (Img, I + 1, F.Height - J, Black);
            end if;
         end loop;
      end loop;
      Save_PGM (Img, Base_Name & ".pgm");
      Create (Y_F, Out_File, Base_Name & ".yaml");
      Put_Line (Y_F, "image: " & Ada.Directories.Simple_Name (Base_Name) & ".pgm");
      Put_Line (Y_F, "resolution: " & Num (F.Resolution));
      Put_Line (Y_F, "origin: [" & Num (F.Origin.X) & ", " & Num (F.Origin.Y) & ", 0.0]");
      Put_Line (Y_F, "negate: 0");
      Put_Line (Y_F, "occupied_thresh: 0.65");
      Put_Line (Y_F, "free_thresh: 0.196");
      Close (Y_F);
   end Write_Map;

end Sancta.Simulation.Rendering;
