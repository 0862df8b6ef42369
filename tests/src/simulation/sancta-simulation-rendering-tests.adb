with Ada.Characters.Handling;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Text_IO;
with AUnit.Assertions;   use AUnit.Assertions;
with Sancta.Robot.Grids;
with Sancta.Simulation.Glyphs;
with Sancta.Simulation.Raster_Images;
with Sancta.Simulation.Map_Files;
with Suite_Support; use Suite_Support;

package body Sancta.Simulation.Rendering.Tests is

   use Raster_Images;
   use type Robot.Grids.Frame;

   Dir : constant String := "obj/test-output/";

   function Room return Worlds.World is
      --  4 x 2 m at 0.1 m, walls on the border only.
      G : Robot.Grids.Grid (39, 19);
   begin
      G.Origin := (0.0, 0.0);
      G.Resolution := 0.1;
      for I in 0 .. 39 loop
         G.Occupied (I, 0) := True;
         G.Occupied (I, 19) := True;
      end loop;
      for J in 0 .. 19 loop
         G.Occupied (0, J) := True;
         G.Occupied (39, J) := True;
      end loop;
      return Worlds.Create (G);
   end Room;

   function Sample_Scene return Scene is
      S    : Scene;
      Path : Point_Vectors.Vector;
   begin
      Path.Append (Point'(1.0, 0.5));
      Path.Append (Point'(3.0, 0.5));
      S.Trajectories.Append (Path);
      S.Robots.Append (Pose'(3.0, 0.5, 0.0));
      S.Markers.Append (Marker'((2.0, 1.5), Ada.Strings.Unbounded.To_Unbounded_String ("dock")));
      return S;
   end Sample_Scene;

   function Without_Markers return Scene is
      S : Scene := Sample_Scene;
   begin
      S.Markers.Clear;
      return S;
   end Without_Markers;
   --  The picture is 40 x 20 pixels: a label, kept inside it, covers the
   --  pixels checked here (labels: the SVG test and the demo's test).

   procedure Picture (Unused : in out Fixture) is
      I : constant Image := Render (Room, Without_Markers, Scale => 10.0);
   begin
      Assert (Width (I) = 40 and then Height (I) = 20, "10 pixels per metre");
      Assert (Get (I, 1, 1) = (50, 50, 50) and then Get (I, 40, 20) = (50, 50, 50),
              "walls drawn at the corners");
      Assert (Get (I, 6, 6) = White, "free space white");
      --  The trajectory runs at y = 0.5 m: pixel row 20 - 5 = 15.
      Assert (Get (I, 20, 15) = Color_Of (1), "trajectory in robot 1's colour");
      Assert (Get (I, 20, 10) = White, "nothing above it");
      declare
         Back : constant Image := Decode_PNG (Encode_PNG (I), "memory");
      begin
         Assert (Get (Back, 20, 15) = Color_Of (1), "PNG keeps the picture");
      end;
   end Picture;

   procedure SVG_And_CSV (Unused : in out Fixture) is
      use Ada.Text_IO;
      F     : File_Type;
      Text  : Ada.Strings.Unbounded.Unbounded_String;
      Paths : Path_Vectors.Vector;
   begin
      Ada.Directories.Create_Path (Dir);
      Write_SVG (Room, Sample_Scene, Dir & "room.svg");
      Open (F, In_File, Dir & "room.svg");
      while not End_Of_File (F) loop
         Ada.Strings.Unbounded.Append (Text, Get_Line (F));
      end loop;
      Close (F);
      declare
         T : constant String := Ada.Strings.Unbounded.To_String (Text);
      begin
         Assert (Contains (T, "<svg"), "an SVG document");
         Assert (Contains (T, "points=""20.00,30.00 60.00,30.00 """),
                 "the trajectory in pixels (y flipped)");
         Assert (Contains (T, ">dock</text>"), "the label");
      end;
      Write_Trajectories (Sample_Scene.Trajectories, Dir & "paths.csv");
      Paths := Read_Trajectories (Dir & "paths.csv");
      Assert (Natural (Paths.Length) = 1 and then Natural (Paths (1).Length) = 2
              and then Paths (1)(2) = (3.0, 0.5), "CSV round trip");
      Create (F, Out_File, Dir & "bad.csv");
      Put_Line (F, "robot,x,y");
      Put_Line (F, "1,2.0,3.0");
      Put_Line (F, "1,two,3.0");
      Close (F);
      begin
         Paths := Read_Trajectories (Dir & "bad.csv");
         Assert (False, "bad CSV accepted");
      exception
         when E : Format_Error =>
            Assert (Contains (Ada.Exceptions.Exception_Message (E), "bad.csv:3:"),
                    "error names the line: " & Ada.Exceptions.Exception_Message (E));
      end;
   end SVG_And_CSV;

   procedure Text_In_Pictures (Unused : in out Fixture) is
      use type Raster_Images.Color;
      Img : Raster_Images.Image := Raster_Images.Create (40, 12);
      function Inked_Pixels (C : Character) return Natural is
         N : Natural := 0;
      begin
         for Row in 1 .. Glyphs.Glyph_Height loop
            for Column in 1 .. Glyphs.Glyph_Width loop
               N := N + (if Glyphs.Is_Inked (C, Column, Row) then 1 else 0);
            end loop;
         end loop;
         return N;
      end Inked_Pixels;
      Red : constant Raster_Images.Color := (200, 0, 0);
      Count : Natural := 0;
   begin
      Assert (Glyphs.Is_Inked ('1', 3, 1) and then not Glyphs.Is_Inked ('1', 1, 1), "glyph 1");
      Assert (Glyphs.Is_Inked ('T', 1, 1) and then Glyphs.Is_Inked ('T', 3, 7)
              and then not Glyphs.Is_Inked ('T', 1, 7), "glyph T");
      for C in Character range 'a' .. 'z' loop
         Assert ((for some Row in 1 .. 7 => (for some Column in 1 .. 5 =>
                   Glyphs.Is_Inked (C, Column, Row)
                   /= Glyphs.Is_Inked (Ada.Characters.Handling.To_Upper (C), Column, Row))),
                 "lower case " & C & " drawn as its upper case");
         Assert ((for some Row in 1 .. 7 => (for some Column in 1 .. 5 =>
                   Glyphs.Is_Inked (C, Column, Row) /= Glyphs.Is_Inked ('?', Column, Row))),
                 "lower case " & C & " has no glyph");
      end loop;
      --  Short letters stay below the capitals' top two rows; only g j p
      --  q y reach below the base line (rows 8 and 9).
      for C of String'("acegmnopqrsuvwxyz") loop
         Assert ((for all Row in 1 .. 2 => (for all Column in 1 .. 5 =>
                   not Glyphs.Is_Inked (C, Column, Row))),
                 "x-height of " & C);
      end loop;
      for C in Character range ' ' .. '~' loop
         Assert ((for some Row in 8 .. Glyphs.Glyph_Height => (for some Column in 1 .. 5 =>
                   Glyphs.Is_Inked (C, Column, Row))) = (C in 'g' | 'j' | 'p' | 'q' | 'y'),
                 "below the base line: " & C);
      end loop;
      Assert ((for all Row in 1 .. 7 => (for all Column in 1 .. 5 =>
                Glyphs.Is_Inked ('~', Column, Row) = Glyphs.Is_Inked ('?', Column, Row))),
              "no glyph: '?'");
      Assert (Inked_Pixels (' ') = 0 and then Inked_Pixels ('A') = 18,
              "space blank, A inked:" & Inked_Pixels ('A')'Image);
      Glyphs.Draw_Text (Img, 2, 3, "r1>t2", Red);
      for Y in 1 .. 12 loop
         for X in 1 .. 40 loop
            if Raster_Images.Get (Img, X, Y) = Red then
               Count := Count + 1;
               Assert (X in 2 .. 2 + Glyphs.Text_Width ("r1>t2") and then Y in 3 .. 9,
                       "ink outside the text box");
            end if;
         end loop;
      end loop;
      Assert (Count > 20, "text drawn:" & Count'Image & " pixels");
      --  Clipped at the edges, no failure.
      Glyphs.Draw_Text (Img, -3, 9, "clipped text running off", Red);
   end Text_In_Pictures;

   procedure Labels_Avoid_Ink (Unused : in out Fixture) is
      --  A 30 x 9 label at (50, 50) in a 200 x 200 picture; its marker 4
      --  pixels each side: the label starts 7 pixels away.
      function Right_Inked (X, Y : Integer) return Boolean is (X > 50 and then Y > 0);
      function Low_Inked (X, Y : Integer) return Boolean is (Y > 20 and then X > 0);
      B : Label_Boxes (1 .. 1);
   begin
      B := Place_Labels ([50], [50], [30], 9, 1, 1, 200, 200);
      Assert (B (1).X = 57 and then B (1).Y = 46 and then not B (1).Leader,
              "no ink: right of the marker, centred; got" & B (1).X'Image & B (1).Y'Image);
      B := Place_Labels ([50], [50], [30], 9, 1, 1, 200, 200, Ink => Right_Inked'Access);
      Assert (B (1).X = 13 and then not B (1).Leader,
              "ink right of the marker: left of it; got" & B (1).X'Image);
      B := Place_Labels ([50], [50], [30], 9, 1, 1, 200, 200, Marker_Radius => 9);
      Assert (B (1).X = 62, "a larger marker: farther; got" & B (1).X'Image);
      --  Ink everywhere below row 20: the label goes up there, with a
      --  leader line, rather than over the ink.
      B := Place_Labels ([50], [50], [30], 9, 1, 1, 200, 200, Ink => Low_Inked'Access);
      Assert (B (1).Leader and then B (1).Y + B (1).Height <= 20,
              "moved away from the ink; got" & B (1).Y'Image & B (1).Leader'Image);
   end Labels_Avoid_Ink;

   procedure Map_Pair_Round_Trip (Unused : in out Fixture) is
      W : constant Worlds.World := Room;
   begin
      Ada.Directories.Create_Path (Dir);
      Write_Map (W, Dir & "room");
      declare
         Back : constant Worlds.World := Map_Files.Load_World (Dir & "room.yaml");
      begin
         Assert (Worlds.Frame_Of (Back) = Worlds.Frame_Of (W), "same frame");
         for I in 0 .. 39 loop
            for J in 0 .. 19 loop
               Assert (Worlds.Is_Occupied (Back, I, J) = Worlds.Is_Occupied (W, I, J),
                       "same cells");
            end loop;
         end loop;
      end;
   end Map_Pair_Round_Trip;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("rendering: PNG picture", Picture'Access));
      Result.Add_Test (Caller.Create ("rendering: SVG and trajectories CSV",
                                      SVG_And_CSV'Access));
      Result.Add_Test (Caller.Create ("rendering: text in pictures (5 x 9 font, lower case)",
                                      Text_In_Pictures'Access));
      Result.Add_Test (Caller.Create ("rendering: labels avoid drawn pixels (Place_Labels)",
                                      Labels_Avoid_Ink'Access));
      Result.Add_Test (Caller.Create ("rendering: map-server pair round trip",
                                      Map_Pair_Round_Trip'Access));
      return Result;
   end Suite;

end Sancta.Simulation.Rendering.Tests;
