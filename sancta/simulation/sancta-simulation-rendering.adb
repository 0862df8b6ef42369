with Ada.Directories;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with Sancta.Robot.Grids;
with Sancta.Simulation.Glyphs;

package body Sancta.Simulation.Rendering is

   use Ada.Strings.Unbounded;
   use Images;
   use Robot.Grids;

   function RGB (R, G, B : Byte) return Color is ((R, G, B));

   Palette : constant array (0 .. 9) of Color :=
     [RGB (31, 119, 180), RGB (255, 127, 14), RGB (44, 160, 44), RGB (214, 39, 40),
      RGB (148, 103, 189), RGB (140, 86, 75), RGB (227, 119, 194), RGB (127, 127, 127),
      RGB (188, 189, 34), RGB (23, 190, 207)];

   function Color_Of (Robot : Positive) return Color is (Palette ((Robot - 1) mod 10));

   function Hex (C : Color) return String is
      Digits_16 : constant String := "0123456789abcdef";
      function Two (B : Byte) return String is
        [Digits_16 (Natural (B) / 16 + 1), Digits_16 (Natural (B) mod 16 + 1)];
   begin
      return "#" & Two (C.R) & Two (C.G) & Two (C.B);
   end Hex;

   function Num (X : Real) return String is
      --  Fixed-point text with two decimals.
      V : constant Long_Long_Integer := Long_Long_Integer (X * 100.0);
      A : constant Long_Long_Integer := abs V;
      F : constant String := Long_Long_Integer'Image (A mod 100);
      Frac : constant String := (if A mod 100 < 10 then "0" & F (2 .. F'Last) else F (2 .. F'Last));
      I : constant String := Long_Long_Integer'Image (A / 100);
   begin
      return (if V < 0 then "-" else "") & I (2 .. I'Last) & "." & Frac;
   end Num;

   ------------
   -- Render --
   ------------

   function Render (World : Worlds.World; S : Scene; Scale : Real := 20.0) return Image is
      F      : constant Frame := Worlds.Frame_Of (World);
      W_M    : constant Real := Real (F.Width) * F.Resolution;
      H_M    : constant Real := Real (F.Height) * F.Resolution;
      Width  : constant Natural := Natural'Max (1, Natural (W_M * Scale));
      Height : constant Natural := Natural'Max (1, Natural (H_M * Scale));
      Img    : Image :=
        (if Width > Max_Side or else Height > Max_Side or else Width * Height > Max_Pixels
         then raise Format_Error with "picture too large: lower the scale"
         else Create (Width, Height));

      function PX (P : Point) return Integer is
        (Integer (Real'Floor ((P.X - F.Origin.X) * Scale)) + 1);
      function PY (P : Point) return Integer is
        (Height - Integer (Real'Floor ((P.Y - F.Origin.Y) * Scale)));

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
      for Y in 1 .. Images.Height (Img) loop
         for X in 1 .. Images.Width (Img) loop
            declare
               WX : constant Real := F.Origin.X + (Real (X) - 0.5) / Scale;
               WY : constant Real := F.Origin.Y + (Real (Height - Y) + 0.5) / Scale;
            begin
               if Worlds.Is_Occupied (World, Column (F, WX), Row (F, WY)) then
                  Set (Img, X, Y, (50, 50, 50));
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
      for M of S.Markers loop
         Line (M.Where - (0.3, 0.3), M.Where + (0.3, 0.3), (200, 0, 0));
         Line (M.Where + (-0.3, 0.3), M.Where + (0.3, -0.3), (200, 0, 0));
      end loop;
      --  Labels last, over every line (as in the SVG: right of the marker).
      for M of S.Markers loop
         if Length (M.Label) > 0 then
            Glyphs.Draw_Text (Img, PX (M.Where) + 7, PY (M.Where) - Glyphs.Glyph_Height / 2,
                              To_String (M.Label), (120, 0, 0));
         end if;
      end loop;
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

      function SX (X : Real) return String is (Num ((X - F.Origin.X) * Scale));
      function SY (Y : Real) return String is (Num ((F.Origin.Y + H_M - Y) * Scale));
   begin
      Create (Out_File, Ada.Text_IO.Out_File, File_Name);
      Put_Line (Out_File, "<?xml version=""1.0"" encoding=""UTF-8""?>");
      Put_Line (Out_File, "<svg xmlns=""http://www.w3.org/2000/svg"" width="""
                & Num (W_M * Scale) & """ height=""" & Num (H_M * Scale)
                & """ viewBox=""0 0 " & Num (W_M * Scale) & " " & Num (H_M * Scale) & """>");
      Put_Line (Out_File, "<rect width=""100%"" height=""100%"" fill=""white""/>");
      Put_Line (Out_File, "<g fill=""#323232"">");
      --  Occupied cells, merged into horizontal runs.
      for J in 0 .. F.Height - 1 loop
         declare
            I : Integer := 0;
         begin
            while I < F.Width loop
               if Worlds.Is_Occupied (World, I, J) then
                  declare
                     Start : constant Integer := I;
                  begin
                     while I < F.Width and then Worlds.Is_Occupied (World, I, J) loop
                        I := I + 1;
                     end loop;
                     Put_Line (Out_File, "<rect x="""
                       & SX (F.Origin.X + Real (Start) * F.Resolution)
                       & """ y=""" & SY (F.Origin.Y + Real (J + 1) * F.Resolution)
                       & """ width=""" & Num (Real (I - Start) * F.Resolution * Scale)
                       & """ height=""" & Num (F.Resolution * Scale) & """/>");
                  end;
               else
                  I := I + 1;
               end if;
            end loop;
         end;
      end loop;
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
      for M of S.Markers loop
         Put_Line (Out_File, "<circle cx=""" & SX (M.Where.X) & """ cy=""" & SY (M.Where.Y)
                   & """ r=""5"" fill=""#c80000""/>");
         if Length (M.Label) > 0 then
            Put_Line (Out_File, "<text x=""" & Num ((M.Where.X - F.Origin.X) * Scale + 7.0)
                      & """ y=""" & SY (M.Where.Y) & """ font-size=""12"""
                      & " font-family=""sans-serif"">"
                      & To_String (M.Label) & "</text>");
         end if;
      end loop;
      Put_Line (Out_File, "</svg>");
      Close (Out_File);
   end Write_SVG;

   -----------------------
   -- Read_Trajectories --
   -----------------------

   function Read_Trajectories (File_Name : String) return Path_Vectors.Vector is
      use Ada.Text_IO;
      F      : File_Type;
      Result : Path_Vectors.Vector;
      Line_No : Natural := 0;

      procedure Fail (Reason : String) with No_Return is
      begin
         Close (F);
         raise Format_Error with File_Name & ":"
           & Ada.Strings.Fixed.Trim (Line_No'Image, Ada.Strings.Left) & ": " & Reason;
      end Fail;
   begin
      begin
         Open (F, In_File, File_Name);
      exception
         when others =>
            raise Format_Error with File_Name & ": cannot be opened";
      end;
      while not End_Of_File (F) loop
         declare
            Line : constant String := Get_Line (F);
            C1   : constant Natural := Ada.Strings.Fixed.Index (Line, ",");
            C2   : constant Natural :=
              (if C1 = 0 then 0 else Ada.Strings.Fixed.Index (Line (C1 + 1 .. Line'Last), ","));
            Robot : Integer;
            X, Y  : Real;
         begin
            Line_No := Line_No + 1;
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
               end if;
               while Result.Last_Index < Robot loop
                  Result.Append (Point_Vectors.Empty_Vector);
               end loop;
               Result (Robot).Append (Point'(X, Y));
            end if;
         end;
      end loop;
      Close (F);
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
