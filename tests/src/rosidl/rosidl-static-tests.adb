with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Exceptions;
with Ada.Streams;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with AUnit.Assertions;
with ROSIDL.CDR;
with ROSIDL.CDR_Samples;
with ROSIDL.Dynamic;
with ROSIDL.Interfaces;
with ROSIDL.Static.Bundled_Types;
with ROSIDL.Static.Registries;
with ROSIDL.Static.Test_Types;
with ROSIDL.Static.Nav_Msgs.Messages.Odometry;
with ROSIDL.Static.Sancta_Test_Msgs.Messages.Point2;
with ROSIDL.Static.Sancta_Test_Msgs.Services.Compute;
with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
with ROSIDL.Static.Sensor_Msgs.Messages.NavSatStatus;
with ROSIDL.Static.Visualization_Msgs.Messages.Marker;
with ROSIDL.Type_Hashes;
with ROSIDL.Typesupport;
with Suite_Support; use Suite_Support;

package body ROSIDL.Static.Tests is

   use Ada.Streams;
   use AUnit.Assertions;
   use ROSIDL.CDR;
   use ROSIDL.Static.Registries;
   use type ROSIDL.Int32, ROSIDL.UInt64, ROSIDL.Float32, ROSIDL.Float64;

   type Stream_Element_Offset_Array is array (Positive range <>) of Stream_Element_Offset;

   package Entry_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Type_Entry);

   procedure Use_User_Interfaces is
   begin
      ROSIDL.CDR_Samples.Use_Test_Interfaces;
      ROSIDL.CDR_Samples.Use_User_Interfaces;
   end Use_User_Interfaces;

   function Generated return Entry_Maps.Map is
      Result : Entry_Maps.Map;
   begin
      for T of ROSIDL.Static.Bundled_Types.Types loop
         Result.Include (T.Full_Name.all, T);
      end loop;
      for T of ROSIDL.Static.Test_Types.Types loop
         Result.Include (T.Full_Name.all, T);
      end loop;
      return Result;
   end Generated;

   ------------------------------------------------------------------------

   function Package_Of (Full_Name : String) return String is
     (Full_Name (Full_Name'First .. Ada.Strings.Fixed.Index (Full_Name, "/") - 1));

   function Is_Generated_Package (Types : Entry_Maps.Map; Full_Name : String) return Boolean is
   begin
      for C in Types.Iterate loop
         if Package_Of (Entry_Maps.Key (C)) = Package_Of (Full_Name) then
            return True;
         end if;
      end loop;
      return False;
   end Is_Generated_Package;
   --  Other tests may put other interface packages (sancta_msgs) on the
   --  search path: those have no generated types here.

   procedure Every_Type_As_Dynamic (Unused : in out Fixture) is
      Types : constant Entry_Maps.Map := Generated;
      Seed  : UInt64 := 16#5EED_0012#;
      Count : Natural := 0;
   begin
      Use_User_Interfaces;
      for Support of ROSIDL.CDR_Samples.All_Types loop
         declare
            Name : constant String := ROSIDL.Typesupport.Full_Name (Support);
         begin
            if not Is_Generated_Package (Types, Name) then
               goto Next_Type;
            end if;
            Assert (Types.Contains (Name), Name & ": no generated type");
            declare
               T : constant Type_Entry := Types (Name);
            begin
               Assert (T.DDS_Type_Name.all = ROSIDL.Typesupport.DDS_Type_Name (Support),
                       Name & ": DDS type name " & T.DDS_Type_Name.all);
               Assert (T.Type_Hash.all
                       = ROSIDL.Type_Hashes.Hash (ROSIDL.Typesupport.Definition (Support)),
                       Name & ": type hash " & T.Type_Hash.all);
               Assert (T.Default.all
                       = Encode (ROSIDL.Dynamic.Init (Support), Little_Endian),
                       Name & ": the default message differs from the dynamic one's");
               for Round in 1 .. 4 loop
                  declare
                     Msg : constant ROSIDL.Dynamic.Message :=
                       ROSIDL.CDR_Samples.Random_Message (Support, Seed);
                     LE  : constant Stream_Element_Array := Encode (Msg, Little_Endian);
                     BE  : constant Stream_Element_Array := Encode (Msg, Big_Endian);
                  begin
                     Assert (T.Recode (LE, Little_Endian) = LE,
                             Name & ": generated encoding differs (little-endian)");
                     Assert (T.Recode (BE, Big_Endian) = BE,
                             Name & ": generated encoding differs (big-endian)");
                     Assert (T.Recode (BE, Little_Endian) = LE,
                             Name & ": big-endian input decoded differently");
                     Assert (T.Round_Trips (LE), Name & ": Decode (Encode (X)) /= X");
                  end;
               end loop;
               Count := Count + 1;
            end;
         end;
         <<Next_Type>>
      end loop;
      Assert (Count = Natural (Types.Length),
              "checked" & Count'Image & " of the" & Types.Length'Image & " generated types");
   end Every_Type_As_Dynamic;

   ------------------------------------------------------------------------

   package Scan renames ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
   package Odometry renames ROSIDL.Static.Nav_Msgs.Messages.Odometry;
   package Compute renames ROSIDL.Static.Sancta_Test_Msgs.Services.Compute;
   use type Scan.Message, Odometry.Message, Compute.Request.Message;

   function Sample_Scan return Scan.Message is
   begin
      return M : Scan.Message do
         M.Header.Stamp := (Sec => 10, Nanosec => 500);
         M.Header.Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("laser");
         M.Angle_Min := -1.5;
         M.Angle_Max := 1.5;
         M.Angle_Increment := 0.25;
         M.Time_Increment := 0.001;
         M.Scan_Time := 0.1;
         M.Range_Min := 0.1;
         M.Range_Max := 30.0;
         M.Ranges.Set_Length (13);
         for I in 0 .. 12 loop
            M.Ranges (I) := Float32 (I + 1) * 0.5;
            M.Intensities.Append (100.0 + Float32 (I + 1));
         end loop;
      end return;
   end Sample_Scan;

   function Definition_Constant (Full_Name, Name : String) return String is
   begin
      for K of ROSIDL.Interfaces.Message (Full_Name).Constants loop
         if Ada.Strings.Unbounded.To_String (K.Name) = Name then
            return Ada.Strings.Unbounded.To_String (K.Value);
         end if;
      end loop;
      return "(no constant " & Name & ")";
   end Definition_Constant;

   function Image (Attribute_Image : String) return String is
     (Ada.Strings.Fixed.Trim (Attribute_Image, Ada.Strings.Left));

   procedure Records_As_Users_Write_Them (Unused : in out Fixture) is
      O : Odometry.Message;
   begin
      --  The same values as the dynamic samples (ROSIDL.CDR_Samples).
      Assert (Scan.Encode (Sample_Scan, Little_Endian)
              = ROSIDL.CDR_Samples.Encode_Sample ("laser_scan", Little_Endian),
              "laser_scan differs from the dynamic sample");
      O.Header.Stamp := (Sec => 5, Nanosec => 6);
      O.Header.Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("odom");
      O.Child_Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("base_link");
      O.Pose.Pose.Position := (X => 1.0, Y => 2.0, Z => 3.0);
      O.Pose.Pose.Orientation.Z := 0.5;
      O.Pose.Pose.Orientation.W := 0.75;
      for I in O.Pose.Covariance'Range loop
         O.Pose.Covariance (I) := Float64 (I) * 0.125;
         O.Twist.Covariance (I) := -Float64 (I);
      end loop;
      O.Twist.Twist.Linear.X := 0.5;
      O.Twist.Twist.Angular.Z := 0.25;
      Assert (Odometry.Encode (O, Big_Endian)
              = ROSIDL.CDR_Samples.Encode_Sample ("odometry", Big_Endian),
              "odometry differs from the dynamic sample");
      Assert (Odometry.Decode (Odometry.Encode (O)) = O, "odometry round trip");

      --  Constants, defaults, reserved words, a user package and a service.
      Assert (Definition_Constant ("visualization_msgs/msg/Marker", "DELETEALL")
              = Image (ROSIDL.Static.Visualization_Msgs.Messages.Marker.DELETEALL'Image),
              "DELETEALL");
      Assert (Definition_Constant ("sensor_msgs/msg/NavSatStatus", "STATUS_NO_FIX")
              = Image (ROSIDL.Static.Sensor_Msgs.Messages.NavSatStatus.STATUS_NO_FIX'Image),
              "STATUS_NO_FIX");
      declare
         M : ROSIDL.Static.Visualization_Msgs.Messages.Marker.Message;
         P : constant ROSIDL.Static.Sancta_Test_Msgs.Messages.Point2.Message := (others => <>);
         R : Compute.Request.Message;
      begin
         M.Type_Field := ROSIDL.Static.Visualization_Msgs.Messages.Marker.ARROW;
         Assert (M.Type_Field = 0 and then M.Points.Length = 0, "Marker defaults");
         Assert (P.X = 1.5 and then P.Y = 0.0, "Point2 default x = 1.5");
         Assert (Compute.Request.Decode (Compute.Request.Encode (R)) = R,
                 "Compute request round trip");
      end;
   end Records_As_Users_Write_Them;

   ------------------------------------------------------------------------

   function Message_Of (E : Ada.Exceptions.Exception_Occurrence) return String
     renames Ada.Exceptions.Exception_Message;

   procedure Malformed_Input (Unused : in out Fixture) is
      Good : constant Stream_Element_Array := Scan.Encode (Sample_Scan, Little_Endian);
      Msg  : Scan.Message;
      Seed : UInt64 := 16#BAD_DA7A#;

      function Next return Natural is
      begin
         Seed := Seed * 6364136223846793005 + 1442695040888963407;
         return Natural (Seed / 2 ** 33);
      end Next;
   begin
      --  Every truncation: Decode_Error with a byte offset inside the
      --  buffer, or (only when what is cut is final padding) a good decode.
      for Last in Good'First - 1 .. Good'Last - 1 loop
         begin
            Scan.Decode (Good (Good'First .. Last), Msg);
            Assert (Last >= Good'Last - 3 and then Msg = Sample_Scan,
                    "truncated to" & Last'Image & " bytes: accepted");
         exception
            when E : ROSIDL.Decode_Error =>
               declare
                  Text : constant String := Message_Of (E);
                  At_Offset : constant Natural := Ada.Strings.Fixed.Index (Text, "byte offset ");
               begin
                  Assert (At_Offset > 0, "no byte offset: " & Text);
                  Assert (Natural'Value (Text (At_Offset + 12 .. Text'Last))
                          <= Natural (Last - Good'First + 1) + 7,
                          "offset beyond the data and its alignment: " & Text);
               end;
         end;
      end loop;

      --  A sequence count far beyond the data: named, with its offset.
      declare
         Bad : Stream_Element_Array := Good;
         Count_At : constant Stream_Element_Offset := Good'First + 4 + 48;
         --  header (8 + 4 + 6 -> 20, aligned 20) + 7 floats = 48.
      begin
         Assert (Bad (Count_At) = 13, "the ranges count is at byte 52");
         Bad (Count_At + 3) := 16#7F#;
         Scan.Decode (Bad, Msg);
         Assert (False, "a count of 2**31 was accepted");
      exception
         when E : ROSIDL.Decode_Error =>
            Assert (Contains (Message_Of (E), "sensor_msgs/msg/LaserScan.ranges")
                    and then Contains (Message_Of (E), "at byte offset 52"),
                    "error message: " & Message_Of (E));
      end;

      --  An unknown encapsulation; a string without its NUL.
      declare
         Bad : Stream_Element_Array := Good;
      begin
         Bad (Good'First + 1) := 7;
         Scan.Decode (Bad, Msg);
         Assert (False, "encapsulation 0, 7 was accepted");
      exception
         when E : ROSIDL.Decode_Error =>
            --  The type named (a program logging it may serve many).
            Assert (Contains (Message_Of (E), "sensor_msgs/msg/LaserScan: unknown encapsulation")
                    and then Contains (Message_Of (E), "at byte offset 0"),
                    "error message: " & Message_Of (E));
      end;
      declare
         Bad : Stream_Element_Array := Good;
      begin
         Bad (Good'First + 4 + 12 + 5) := Character'Pos ('x');
         --  frame_id "laser": length at 12, characters from 16, NUL at 21.
         Scan.Decode (Bad, Msg);
         Assert (False, "a string without NUL was accepted");
      exception
         when E : ROSIDL.Decode_Error =>
            Assert (Contains (Message_Of (E), "NUL")
                    and then Contains (Message_Of (E), "std_msgs/msg/Header"),
                    "error message: " & Message_Of (E));
      end;

      --  Random corruption of every generated type's random messages: only
      --  ever Decode_Error (an over-read would be Constraint_Error).
      Use_User_Interfaces;
      declare
         Types : constant Entry_Maps.Map := Generated;
         Gen   : UInt64 := 77;
      begin
         for Support of ROSIDL.CDR_Samples.All_Types loop
            if not Is_Generated_Package (Types, ROSIDL.Typesupport.Full_Name (Support)) then
               goto Next_Type;
            end if;
            declare
               T    : constant Type_Entry := Types (ROSIDL.Typesupport.Full_Name (Support));
               Data : Stream_Element_Array :=
                 Encode (ROSIDL.CDR_Samples.Random_Message (Support, Gen), Little_Endian);
            begin
               for Unused_Round in 1 .. 8 loop
                  declare
                     Cut : constant Stream_Element_Offset :=
                       Data'First + Stream_Element_Offset (Next mod Data'Length);
                  begin
                     Data (Data'First + Stream_Element_Offset (Next mod Data'Length)) :=
                       Stream_Element (Next mod 256);
                     if T.Round_Trips (Data (Data'First .. Cut)) then
                        null;
                     end if;
                  exception
                     when ROSIDL.Decode_Error =>
                        null;
                     when E : others =>
                        Assert (False, ROSIDL.Typesupport.Full_Name (Support) & ": "
                                & Ada.Exceptions.Exception_Information (E));
                  end;
               end loop;
            end;
            <<Next_Type>>
         end loop;
      end;
   end Malformed_Input;

   ------------------------------------------------------------------------

   --  The encoder makes no size pass before writing: a buffer too small
   --  must still give Encode_Error naming the type and the size needed,
   --  after writing nothing past the buffer's end (guard bytes checked).
   --  Every buffer size for LaserScan and the two Everything test types
   --  (every kind of field), a few sizes for every other type (an exception costs
   --  ~0.1 ms with tracebacks on).
   procedure Too_Small_Buffers (Unused : in out Fixture) is
      Types   : constant Entry_Maps.Map := Generated;
      Gen     : UInt64 := 16#5A11#;
      Guard   : constant Stream_Element := 16#A5#;
      Checked : Natural := 0;

      procedure Check
        (Name : String; T : Type_Entry; Data : Stream_Element_Array; Order : Byte_Order;
         Cut  : Stream_Element_Offset)
      is
         Size  : constant Stream_Element_Offset := Data'Length;
         Space : Stream_Element_Array (1 .. Cut + 16) := [others => Guard];
         Last  : Stream_Element_Offset;
      begin
         T.Recode_Into (Data, Space (1 .. Cut), Last, Order);
         Assert (Cut >= Size, Name & ": encoded into" & Cut'Image & " of"
                 & Size'Image & " bytes needed");
         Assert (Last = Size and then Space (1 .. Last) = Data,
                 Name & ": encoding into a buffer of" & Cut'Image & " bytes differs");
      exception
         when E : ROSIDL.Encode_Error =>
            Assert (Cut < Size, Name & ": Encode_Error with" & Cut'Image & " of"
                    & Size'Image & " bytes: " & Message_Of (E));
            Assert (Ada.Strings.Fixed.Index (Message_Of (E), Name & ":") = 1
                    and then Contains (Message_Of (E), "needs" & Size'Image),
                    Name & ": error message: " & Message_Of (E));
            Assert (Space (Cut + 1 .. Space'Last) = [1 .. 16 => Guard],
                    Name & ": wrote past a buffer of" & Cut'Image & " bytes");
      end Check;

   begin
      Use_User_Interfaces;
      for Support of ROSIDL.CDR_Samples.All_Types loop
         if not Is_Generated_Package (Types, ROSIDL.Typesupport.Full_Name (Support)) then
            goto Next_Type;
         end if;
         declare
            Name  : constant String := ROSIDL.Typesupport.Full_Name (Support);
            T     : constant Type_Entry := Types (Name);
            Order : constant Byte_Order :=
              (if Checked mod 2 = 0 then Little_Endian else Big_Endian);
            Data  : constant Stream_Element_Array :=
              Encode (ROSIDL.CDR_Samples.Random_Message (Support, Gen), Order);
            Size  : constant Stream_Element_Offset := Data'Length;
         begin
            if Name in "sensor_msgs/msg/LaserScan" | "sancta_test_msgs/msg/Everything"
              | "cdr_test_msgs/msg/Everything"
            then
               for Cut in 0 .. Size + 8 loop
                  Check (Name, T, Data, Order, Cut);
               end loop;
            else
               for Cut of Stream_Element_Offset_Array'[0, 3, Size / 2, Size - 1, Size, Size + 5]
               loop
                  Check (Name, T, Data, Order, Cut);
               end loop;
            end if;
            Checked := Checked + 1;
         end;
         <<Next_Type>>
      end loop;
      Assert (Checked = Natural (Types.Length),
              "checked" & Checked'Image & " of the" & Types.Length'Image & " generated types");
   end Too_Small_Buffers;

   procedure Bounded_Types_Are_Known (Unused : in out Fixture) is
      Bounded : Natural := 0;
   begin
      for T of ROSIDL.Static.Bundled_Types.Types loop
         if T.Is_Bounded then
            Bounded := Bounded + 1;
         end if;
      end loop;
      Assert (Bounded > 20, "bounded bundled types:" & Bounded'Image);
      for T of ROSIDL.Static.Bundled_Types.Types loop
         if T.Full_Name.all = "geometry_msgs/msg/Twist" then
            Assert (T.Is_Bounded, "Twist is bounded");
         elsif T.Full_Name.all = "sensor_msgs/msg/LaserScan" then
            Assert (not T.Is_Bounded, "LaserScan is not bounded");
         end if;
      end loop;
   end Bounded_Types_Are_Known;

   Result : aliased AUnit.Test_Suites.Test_Suite;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
   begin
      Result.Add_Test (Caller.Create ("Static: every generated type encodes as the dynamic codec",
                                      Every_Type_As_Dynamic'Access));
      Result.Add_Test (Caller.Create ("Static: records as users write them",
                                      Records_As_Users_Write_Them'Access));
      Result.Add_Test (Caller.Create ("Static: malformed input raises Decode_Error with offset",
                                      Malformed_Input'Access));
      Result.Add_Test (Caller.Create ("Static: a too small buffer is Encode_Error, never overrun",
                                      Too_Small_Buffers'Access));
      Result.Add_Test (Caller.Create ("Static: bounded types", Bounded_Types_Are_Known'Access));
      return Result'Access;
   end Suite;

end ROSIDL.Static.Tests;
