with Ada.Characters.Handling;
with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Directories;
with Ada.Strings.Fixed;
with Ada.Unchecked_Deallocation;
with Sancta.Installation;
with Sancta.Simulation.Text_Files;

package body Sancta.Simulation.Map_Files is

   use Ada.Strings.Unbounded;
   use Robot.Grids;

   type Grid_Access is access Grid;
   procedure Free is new Ada.Unchecked_Deallocation (Grid, Grid_Access);

   function Into_World (G : in out Grid_Access) return Worlds.World;
   --  The world of grid G; frees G.

   function Into_World (G : in out Grid_Access) return Worlds.World is
   begin
      return Result : constant Worlds.World := Worlds.Create (G.all) do
         Free (G);
      end return;
   end Into_World;

   function Trim (S : String) return String is
     (Ada.Strings.Fixed.Trim (S, Ada.Strings.Both));

   function Img (N : Natural) return String is
     (Trim (Natural'Image (N)));

   procedure Fail (File : String; Line : Natural; Reason : String) with No_Return is
   begin
      raise Format_Error with File & ":" & Img (Line) & ": " & Reason;
   end Fail;

   function Without_Comment (S : String) return String is
      In_Quote : Character := ' ';
   begin
      for K in S'Range loop
         if In_Quote /= ' ' then
            if S (K) = In_Quote then
               In_Quote := ' ';
            end if;
         elsif S (K) in '"' | ''' then
            In_Quote := S (K);
         elsif S (K) = '#' then
            return S (S'First .. K - 1);
         end if;
      end loop;
      return S;
   end Without_Comment;

   function To_Real (File : String; Line : Natural; What, S : String) return Real is
   begin
      if S = "" then
         Fail (File, Line, "expected " & What & " (a number), found nothing");
      end if;
      declare
         T : constant String := Trim (S);
         V : Real;
      begin
         --  Real'Value wants a digit before a decimal point and accepts
         --  integers only as "1.0": add what is missing.
         if Ada.Strings.Fixed.Index (T, ".") = 0
           and then Ada.Strings.Fixed.Index (T, "e") = 0
           and then Ada.Strings.Fixed.Index (T, "E") = 0
         then
            V := Real'Value (T & ".0");
         else
            V := Real'Value (T);
         end if;
         if not V'Valid or else abs V > 1.0E12 then
            raise Constraint_Error;
         end if;
         return V;
      end;
   exception
      when Constraint_Error =>
         Fail (File, Line, "expected " & What & " (a number), found """ & Trim (S) & """");
   end To_Real;

   ---------------
   -- Read_YAML --
   ---------------

   function Read_YAML (File_Name : String) return Map_Info is
      Last_Line  : Natural;
      Result     : Map_Info;
      Have_Image, Have_Resolution, Have_Origin : Boolean := False;
      Image_Line : Positive := 1;

      procedure Read_Entry (Raw_Line : String; Line_No : Positive) is
         Line  : constant String := Trim (Without_Comment (Raw_Line));
         Colon : Natural;
      begin
         if Line /= "" and then Line /= "---" then
            Colon := Ada.Strings.Fixed.Index (Line, ":");
            if Colon = 0 then
               Fail (File_Name, Line_No, "expected ""key: value"", found """ & Line & """");
            end if;
            declare
               Key   : constant String :=
                 Ada.Characters.Handling.To_Lower (Trim (Line (Line'First .. Colon - 1)));
               Raw   : constant String := Trim (Line (Colon + 1 .. Line'Last));
               Value : constant String :=
                 (if Raw'Length >= 2 and then Raw (Raw'First) in '"' | '''
                    and then Raw (Raw'Last) = Raw (Raw'First)
                  then Raw (Raw'First + 1 .. Raw'Last - 1) else Raw);
            begin
               if Key = "image" then
                  if Value = "" then
                     Fail (File_Name, Line_No, "image: expected a file name");
                  end if;
                  Result.Image := To_Unbounded_String (Value);
                  Have_Image := True;
                  Image_Line := Line_No;
               elsif Key = "resolution" then
                  Result.Resolution := To_Real (File_Name, Line_No, "resolution", Value);
                  if Result.Resolution <= 0.0 then
                     Fail (File_Name, Line_No, "resolution must be positive");
                  end if;
                  Have_Resolution := True;
               elsif Key = "origin" then
                  if Value'Length < 2 or else Value (Value'First) /= '['
                    or else Value (Value'Last) /= ']'
                  then
                     Fail (File_Name, Line_No, "origin: expected [x, y, yaw], found """
                           & Value & """");
                  end if;
                  declare
                     Inner : constant String := Value (Value'First + 1 .. Value'Last - 1);
                     C1    : constant Natural := Ada.Strings.Fixed.Index (Inner, ",");
                     C2    : constant Natural :=
                       (if C1 = 0 then 0
                        else Ada.Strings.Fixed.Index (Inner (C1 + 1 .. Inner'Last), ","));
                  begin
                     if C1 = 0 or else C2 = 0 then
                        Fail (File_Name, Line_No, "origin: expected three numbers [x, y, yaw]");
                     end if;
                     Result.Origin :=
                       (To_Real (File_Name, Line_No, "origin x",
                                 Inner (Inner'First .. C1 - 1)),
                        To_Real (File_Name, Line_No, "origin y",
                                 Inner (C1 + 1 .. C2 - 1)),
                        To_Real (File_Name, Line_No, "origin yaw",
                                 Inner (C2 + 1 .. Inner'Last)));
                     if Result.Origin.Yaw /= 0.0 then
                        Fail (File_Name, Line_No, "origin: a rotated map (yaw /= 0) is not"
                              & " supported");
                     end if;
                  end;
                  Have_Origin := True;
               elsif Key = "negate" then
                  if Value in "0" | "false" | "False" then
                     Result.Negate := False;
                  elsif Value in "1" | "true" | "True" then
                     Result.Negate := True;
                  else
                     Fail (File_Name, Line_No, "negate: expected 0 or 1, found """
                           & Value & """");
                  end if;
               elsif Key = "occupied_thresh" then
                  Result.Occupied_Thresh :=
                    To_Real (File_Name, Line_No, "occupied_thresh", Value);
               elsif Key = "free_thresh" then
                  Result.Free_Thresh := To_Real (File_Name, Line_No, "free_thresh", Value);
               elsif Key = "mode" then
                  if Value not in "trinary" | "scale" then
                     Fail (File_Name, Line_No, "mode: only trinary and scale are supported,"
                           & " found """ & Value & """");
                  end if;
               else
                  Fail (File_Name, Line_No, "unknown key """ & Key & """");
               end if;
            end;
         end if;
      end Read_Entry;

      procedure Read_Entries is new Text_Files.Read_Lines (Read_Entry);
   begin
      Read_Entries (File_Name, Last_Line);
      if not (Have_Image and then Have_Resolution and then Have_Origin) then
         Fail (File_Name, Last_Line + 1, "missing key(s):"
               & (if Have_Image then "" else " image")
               & (if Have_Resolution then "" else " resolution")
               & (if Have_Origin then "" else " origin"));
      end if;
      if Result.Free_Thresh > Result.Occupied_Thresh
        or else Result.Occupied_Thresh > 1.0 or else Result.Free_Thresh < 0.0
      then
         Fail (File_Name, Last_Line, "thresholds must satisfy 0 <= free_thresh <="
               & " occupied_thresh <= 1");
      end if;
      declare
         Name : constant String := To_String (Result.Image);
      begin
         --  Not Ada.Directories.Compose: it refuses a relative path with
         --  folders ("maps/room.pgm").
         Result.Image_Path := To_Unbounded_String
           (if Name (Name'First) = '/' then Name
            else Ada.Directories.Containing_Directory
                   (Ada.Directories.Full_Name (File_Name)) & "/" & Name);
         --  Said here, with the line, before the path (an exception message
         --  keeps 200 characters: a long path would hide the reason).
         declare
            use type Ada.Directories.File_Kind;
            Path : constant String := To_String (Result.Image_Path);
         begin
            if not Ada.Directories.Exists (Path) then
               Fail (File_Name, Image_Line, "image: no such file: " & Path);
            elsif Ada.Directories.Kind (Path) /= Ada.Directories.Ordinary_File then
               Fail (File_Name, Image_Line, "image: not a regular file: " & Path);
            end if;
         exception
            when Ada.Directories.Name_Error =>
               Fail (File_Name, Image_Line, "image: not a valid file name: " & Path);
         end;
      end;
      return Result;
   end Read_YAML;

   --------------
   -- To_World --
   --------------

   function To_World (Img : Raster_Images.Image; Info : Map_Info) return Worlds.World is
      W : constant Natural := Raster_Images.Width (Img);
      H : constant Natural := Raster_Images.Height (Img);
      G : Grid_Access := new Grid (W - 1, H - 1);
   begin
      G.Origin := Position (Info.Origin);
      G.Resolution := Info.Resolution;
      for Y in 1 .. H loop
         for X in 1 .. W loop
            declare
               V : constant Real :=
                 Real (Raster_Images.Gray (Raster_Images.Get (Img, X, Y))) / 255.0;
               P : constant Real := (if Info.Negate then V else 1.0 - V);
            begin
               --  Occupied or unknown is solid; only free cells are open.
               G.Occupied (X - 1, H - Y) := not (P < Info.Free_Thresh);
            end;
         end loop;
      end loop;
      return Into_World (G);
   end To_World;

   function Load_Map (File_Name : String) return Worlds.World is
      Info : constant Map_Info := Read_YAML (File_Name);
   begin
      return To_World (Raster_Images.Load (To_String (Info.Image_Path)), Info);
   end Load_Map;

   ----------------
   -- Read_Walls --
   ----------------

   package Segment_Vectors is new Ada.Containers.Vectors (Positive, Segment);

   function Read_Walls
     (File_Name  : String;
      Resolution : out Real;
      Low, High  : out Point) return Segment_Array
   is
      Last_Line : Natural;
      Walls     : Segment_Vectors.Vector;
      Thickness : Real := 0.1;
      Bounded   : Boolean := False;

      procedure Read_Statement (Raw_Line : String; Line_No : Positive) is
         Line  : constant String := Trim (Without_Comment (Raw_Line));
         Words : array (1 .. 8) of Unbounded_String;
         Count : Natural := 0;
         K     : Natural := Line'First;
         Start : Natural;

         function N (I : Positive; What : String) return Real is
           (To_Real (File_Name, Line_No, What, To_String (Words (I))));

         procedure Expect (Low_Count, High_Count : Natural; Form : String) is
         begin
            if Count - 1 not in Low_Count .. High_Count then
               Fail (File_Name, Line_No, "expected """ & Form & """");
            end if;
         end Expect;
      begin
         while K <= Line'Last loop
            if Line (K) in ' ' | ASCII.HT then
               K := K + 1;
            else
               Start := K;
               while K <= Line'Last and then Line (K) not in ' ' | ASCII.HT loop
                  K := K + 1;
               end loop;
               Count := Count + 1;
               if Count > Words'Last then
                  Fail (File_Name, Line_No, "too many words");
               end if;
               Words (Count) := To_Unbounded_String (Line (Start .. K - 1));
            end if;
         end loop;
         if Count > 0 then
            declare
               Key : constant String := To_String (Words (1));
            begin
               if Key = "resolution" then
                  Expect (1, 1, "resolution METRES");
                  Resolution := N (2, "resolution");
                  if Resolution <= 0.0 then
                     Fail (File_Name, Line_No, "resolution must be positive");
                  end if;
               elsif Key = "thickness" then
                  Expect (1, 1, "thickness METRES");
                  Thickness := N (2, "thickness");
               elsif Key = "bounds" then
                  Expect (4, 4, "bounds X0 Y0 X1 Y1");
                  Low := (N (2, "X0"), N (3, "Y0"));
                  High := (N (4, "X1"), N (5, "Y1"));
                  if High.X <= Low.X or else High.Y <= Low.Y then
                     Fail (File_Name, Line_No, "bounds: X1 > X0 and Y1 > Y0 expected");
                  end if;
                  Bounded := True;
               elsif Key = "wall" or else Key = "box" then
                  Expect (4, 5, Key & " X1 Y1 X2 Y2 [THICKNESS]");
                  declare
                     A : constant Point := (N (2, "X1"), N (3, "Y1"));
                     B : constant Point := (N (4, "X2"), N (5, "Y2"));
                     T : constant Real := (if Count = 6 then N (6, "thickness") else Thickness);
                  begin
                     if T < 0.0 then
                        Fail (File_Name, Line_No, "negative thickness");
                     end if;
                     if Key = "wall" then
                        Walls.Append (Segment'(A, B, T));
                     else
                        Walls.Append (Segment'((A.X, A.Y), (B.X, A.Y), T));
                        Walls.Append (Segment'((B.X, A.Y), (B.X, B.Y), T));
                        Walls.Append (Segment'((B.X, B.Y), (A.X, B.Y), T));
                        Walls.Append (Segment'((A.X, B.Y), (A.X, A.Y), T));
                     end if;
                  end;
               else
                  Fail (File_Name, Line_No, "expected resolution, thickness, bounds, wall"
                        & " or box, found """ & Key & """");
               end if;
            end;
         end if;
      end Read_Statement;

      procedure Read_Statements is new Text_Files.Read_Lines (Read_Statement);
   begin
      Resolution := 0.05;
      Low := (0.0, 0.0);
      High := (0.0, 0.0);
      Read_Statements (File_Name, Last_Line);
      if Walls.Is_Empty and then not Bounded then
         Fail (File_Name, Last_Line, "no walls and no bounds");
      end if;
      if not Bounded then
         Low := (Real'Last, Real'Last);
         High := (Real'First, Real'First);
         for S of Walls loop
            Low := (Real'Min (Low.X, Real'Min (S.A.X, S.B.X) - S.Thickness),
                    Real'Min (Low.Y, Real'Min (S.A.Y, S.B.Y) - S.Thickness));
            High := (Real'Max (High.X, Real'Max (S.A.X, S.B.X) + S.Thickness),
                     Real'Max (High.Y, Real'Max (S.A.Y, S.B.Y) + S.Thickness));
         end loop;
         Low := Low - (0.5, 0.5);
         High := High + (0.5, 0.5);
      end if;
      if (High.X - Low.X) / Resolution > 20_000.0
        or else (High.Y - Low.Y) / Resolution > 20_000.0
        or else (High.X - Low.X) * (High.Y - Low.Y) / Resolution ** 2 > 40.0E6
      then
         Fail (File_Name, Last_Line, "world too large for its resolution (over 20000 cells"
               & " a side or 40 million cells)");
      end if;
      return Result : Segment_Array (1 .. Natural (Walls.Length)) do
         for K in Result'Range loop
            Result (K) := Walls (K);
         end loop;
      end return;
   end Read_Walls;

   function Load_Walls (File_Name : String) return Worlds.World is
      Resolution : Real;
      Low, High  : Point;
      Walls      : constant Segment_Array := Read_Walls (File_Name, Resolution, Low, High);
      W          : constant Natural :=
        Natural (Real'Ceiling ((High.X - Low.X) / Resolution - 1.0E-9));
      H          : constant Natural :=
        Natural (Real'Ceiling ((High.Y - Low.Y) / Resolution - 1.0E-9));
      G          : Grid_Access := new Grid (W - 1, H - 1);
   begin
      G.Origin := Low;
      G.Resolution := Resolution;
      for S of Walls loop
         Draw (G.all, S);
      end loop;
      return Into_World (G);
   end Load_Walls;

   function Load_World (File_Name : String) return Worlds.World is
      Ext : constant String :=
        Ada.Characters.Handling.To_Lower (Ada.Directories.Extension (File_Name));
      use type Ada.Directories.File_Kind;
   begin
      if Ada.Directories.Exists (File_Name)
        and then Ada.Directories.Kind (File_Name) /= Ada.Directories.Ordinary_File
      then
         raise Format_Error with File_Name & ": not a regular file";
      end if;
      if Ext = "yaml" or else Ext = "yml" then
         return Load_Map (File_Name);
      else
         return Load_Walls (File_Name);
      end if;
   end Load_World;

   function World_File (Name : String) return String is
      Share : constant String := Installation.Share_File ("worlds/");
   begin
      if Name = "" then
         return "";
      elsif Ada.Directories.Exists (Name) then
         return Name;
      elsif Ada.Strings.Fixed.Index (Name, "/") = 0 then
         if Ada.Directories.Exists (Share & Name & ".yaml") then
            return Share & Name & ".yaml";
         elsif Ada.Directories.Exists (Share & Name & ".walls") then
            return Share & Name & ".walls";
         end if;
      end if;
      return "";
   end World_File;

   function Bundled_Worlds return String is
      package Name_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);
      package Sorting is new Name_Vectors.Generic_Sorting;
      Share : constant String := Installation.Share_File ("worlds/");
      Files : constant Ada.Directories.Filter_Type :=
        [Ada.Directories.Ordinary_File => True, others => False];
      Names : Name_Vectors.Vector;
      procedure Add (Entry_Found : Ada.Directories.Directory_Entry_Type) is
         Name : constant String := Ada.Directories.Base_Name
           (Ada.Directories.Simple_Name (Entry_Found));
      begin
         if not Names.Contains (Name) then
            Names.Append (Name);
         end if;
      end Add;
      Result : Unbounded_String;
   begin
      if Ada.Directories.Exists (Share) then
         Ada.Directories.Search (Share, "*.yaml", Files, Add'Access);
         Ada.Directories.Search (Share, "*.walls", Files, Add'Access);
      end if;
      Sorting.Sort (Names);
      for Name of Names loop
         Append (Result, (if Length (Result) = 0 then "" else ", ") & Name);
      end loop;
      return (if Length (Result) = 0 then "none" else To_String (Result));
   end Bundled_Worlds;

end Sancta.Simulation.Map_Files;
