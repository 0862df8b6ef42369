with Ada.Characters.Handling;
with Ada.IO_Exceptions;
with Ada.Strings.Fixed;
with Ada.Text_IO;

package body Sancta.Simulation.Robot_Lists is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;

   function Is_Valid_Name (Name : String) return Boolean is
      use Ada.Characters.Handling;
   begin
      if Name'Length = 0 or else Name'Length > 200
        or else not (Is_Letter (Name (Name'First)) or else Name (Name'First) = '_')
      then
         return False;
      end if;
      for C of Name loop
         if not (Is_Alphanumeric (C) or else C = '_') or else not Is_ISO_646 (C) then
            return False;
         end if;
      end loop;
      return True;
   end Is_Valid_Name;

   function Find (List : Robot_List; Name : String) return Natural is
   begin
      for I in 1 .. Natural (List.Length) loop
         if To_String (List (I).Name) = Name then
            return I;
         end if;
      end loop;
      return 0;
   end Find;

   procedure Parse_Line
     (Line   : String;
      Where  : String;
      Number : Positive;
      List   : in out Robot_List;
      Base   : Simulators.Robot_Config := Simulators.Default_Robot)
   is
      Last   : Natural := Line'Last;
      Pos    : Natural := Line'First;
      Result : Robot_Entry := (Config => Base, others => <>);

      function Here (Column : Natural) return String is
        (Where & ":" & Ada.Strings.Fixed.Trim (Number'Image, Ada.Strings.Left) & ":"
         & Ada.Strings.Fixed.Trim (Natural'Image (Column - Line'First + 1),
                                   Ada.Strings.Left) & ": ");

      procedure Fail (Column : Natural; What : String) is
      begin
         raise List_Error with Here (Column) & What;
      end Fail;

      --  The next blank-separated word: First .. Stop (First > Stop: none).
      procedure Next_Word (First, Stop : out Natural) is
      begin
         while Pos <= Last and then Line (Pos) in ' ' | ASCII.HT | ASCII.CR loop
            Pos := Pos + 1;
         end loop;
         First := Pos;
         while Pos <= Last and then Line (Pos) not in ' ' | ASCII.HT | ASCII.CR loop
            Pos := Pos + 1;
         end loop;
         Stop := Pos - 1;
      end Next_Word;

      function To_Real (Text : String; Column : Natural; What : String) return Real is
      begin
         if Text'Length = 0 then
            Fail (Column, "expected " & What & ", found the end of the line");
         end if;
         declare
            Value : constant Real :=
              Real'Value (if Ada.Strings.Fixed.Index (Text, ".") = 0
                            and then Ada.Strings.Fixed.Index (Text, "e") = 0
                            and then Ada.Strings.Fixed.Index (Text, "E") = 0
                          then Text & ".0" else Text);
         begin
            if not Value'Valid or else abs Value > 1.0E9 then
               Fail (Column, "expected " & What & ", found """ & Text & """");
            end if;
            return Value;
         end;
      exception
         when Constraint_Error =>
            Fail (Column, "expected " & What & " (a number), found """ & Text & """");
            return 0.0;
      end To_Real;

      First, Stop : Natural;
      C : Simulators.Robot_Config renames Result.Config;
   begin
      declare
         Hash : constant Natural := Ada.Strings.Fixed.Index (Line, "#");
      begin
         if Hash /= 0 then
            Last := Hash - 1;
         end if;
      end;
      Next_Word (First, Stop);
      if First > Stop then
         return;
      end if;
      if not Is_Valid_Name (Line (First .. Stop)) then
         Fail (First, "expected a robot name (letters, digits, '_'), found """
               & Line (First .. Stop) & """");
      end if;
      if Find (List, Line (First .. Stop)) /= 0 then
         Fail (First, "robot """ & Line (First .. Stop) & """ is listed twice");
      end if;
      Result.Name := To_Unbounded_String (Line (First .. Stop));
      Next_Word (First, Stop);
      Result.Start.X := To_Real (Line (First .. Stop), First, "the start X");
      Next_Word (First, Stop);
      Result.Start.Y := To_Real (Line (First .. Stop), First, "the start Y");
      Next_Word (First, Stop);
      Result.Start.Yaw := To_Real (Line (First .. Stop), First, "the start yaw");
      loop
         Next_Word (First, Stop);
         exit when First > Stop;
         declare
            Word  : constant String := Line (First .. Stop);
            Equal : constant Natural := Ada.Strings.Fixed.Index (Word, "=");
         begin
            if Equal = 0 then
               Fail (First, "expected KEY=VALUE, found """ & Word & """");
            end if;
            declare
               Key    : constant String := Word (Word'First .. Equal - 1);
               Text   : constant String := Word (Equal + 1 .. Word'Last);
               At_Val : constant Natural := First + (Equal + 1 - Word'First);

               function Value return Real is (To_Real (Text, At_Val, "a value of " & Key));
            begin
               if Key = "radius" then
                  C.Radius := Value;
               elsif Key = "max_linear" then
                  C.Max_Linear := Value;
               elsif Key = "max_angular" then
                  C.Max_Angular := Value;
               elsif Key = "beams" then
                  declare
                     V : constant Real := Value;
                  begin
                     if V /= Real'Floor (V) or else V < 1.0 or else V > 10_000.0 then
                        Fail (At_Val, "expected a whole number of beams in 1 .. 10000, found "
                              & Text);
                     end if;
                     C.Laser.Beams := Positive (V);
                  end;
               elsif Key = "fov" then
                  C.Laser.Field_Of_View := Value * Pi / 180.0;
               elsif Key = "range" then
                  C.Laser.Max_Range := Value;
               elsif Key = "laser_noise" then
                  C.Laser.Noise_Std_Dev := Value;
               elsif Key = "laser_rate" then
                  C.Laser.Rate := Value;
               elsif Key = "odom_rate" then
                  C.Odometry.Rate := Value;
               elsif Key = "odom_scale" then
                  C.Odometry.Linear_Scale_Error := Value;
               elsif Key = "odom_bias" then
                  C.Odometry.Angular_Bias := Value;
               elsif Key = "odom_noise" then
                  C.Odometry.Linear_Noise := Value;
               elsif Key = "odom_angular_scale" then
                  C.Odometry.Angular_Scale_Error := Value;
               elsif Key = "odom_angular_noise" then
                  C.Odometry.Angular_Noise := Value;
               elsif Key = "gps" then
                  if Text = "on" or else Text = "true" then
                     C.GPS.Enabled := True;
                  elsif Text = "off" or else Text = "false" then
                     C.GPS.Enabled := False;
                  else
                     Fail (At_Val, "expected on or off, found """ & Text & """");
                  end if;
               elsif Key = "gps_rate" then
                  C.GPS.Rate := Value;
               elsif Key = "gps_std" then
                  C.GPS.Std_Dev := Value;
               else
                  Fail (First, "unknown key """ & Key & """ (radius, max_linear, "
                        & "max_angular, beams, fov, range, laser_noise, laser_rate, "
                        & "odom_rate, odom_scale, odom_bias, odom_noise, odom_angular_scale, "
                        & "odom_angular_noise, gps, gps_rate, gps_std)");
               end if;
            end;
         end;
      end loop;
      if not Simulators.Is_Valid (C) then
         Fail (Line'First, "invalid robot configuration (a size, limit or rate out of range)");
      end if;
      List.Append (Result);
   end Parse_Line;

   procedure Load (File_Name : String; List : in out Robot_List) is
      use Ada.Text_IO;
      F      : File_Type;
      Number : Positive := 1;
   begin
      begin
         Open (F, In_File, File_Name);
      exception
         when Ada.IO_Exceptions.Name_Error | Ada.IO_Exceptions.Use_Error =>
            raise List_Error with File_Name & ": cannot open the robot list";
      end;
      while not End_Of_File (F) loop
         declare
            Line : constant String := Get_Line (F);
         begin
            Parse_Line (Line, File_Name, Number, List);
         exception
            when others =>
               Close (F);
               raise;
         end;
         Number := Number + 1;
      end loop;
      Close (F);
   end Load;

end Sancta.Simulation.Robot_Lists;
