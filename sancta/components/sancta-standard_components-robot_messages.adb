with Ada.Exceptions;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Strings.Fixed;
with ROSIDL;
with ROSIDL.Typesupport;

package body Sancta.Standard_Components.Robot_Messages is

   use ROSIDL.Dynamic;
   use Sancta.Geometry;

   function F64 (Ref : Field_Ref) return Real is (Real (ROSIDL.Float64'(Ref.As_Float64)));
   function F32 (Ref : Field_Ref) return Real is (Real (ROSIDL.Float32'(Ref.As_Float32)));

   function Stamp_Of (Header : Field_Ref) return Real is
     (Real (ROSIDL.Int32'(Header ("stamp")("sec").As_Int32))
      + Real (ROSIDL.UInt32'(Header ("stamp")("nanosec").As_UInt32)) * 1.0E-9);

   function To_Scan (Msg : Message) return Robot.Sensors.Laser_Scan is
      Ranges : constant Float32_Array := Msg ("ranges").Get_Float32_Array;
      Result : Robot.Sensors.Laser_Scan (Ranges'Length);
   begin
      Result.Stamp := Stamp_Of (Msg ("header"));
      Result.Angle_Min := F32 (Msg ("angle_min"));
      Result.Angle_Max := F32 (Msg ("angle_max"));
      Result.Angle_Increment := F32 (Msg ("angle_increment"));
      Result.Time_Increment := F32 (Msg ("time_increment"));
      Result.Scan_Time := F32 (Msg ("scan_time"));
      Result.Range_Min := F32 (Msg ("range_min"));
      Result.Range_Max := F32 (Msg ("range_max"));
      for I in Ranges'Range loop
         Result.Ranges (I - Ranges'First + 1) :=
           (if Ranges (I)'Valid then Real (Ranges (I)) else Result.Range_Max);
      end loop;
      return Result;
   end To_Scan;

   procedure Set_Time (Stamp : Field_Ref; T : Real) is
      Seconds : constant Real := Real'Floor (T);
      Nanos   : constant Real := Real'Floor ((T - Seconds) * 1.0E9);
   begin
      Stamp ("sec").As_Int32 := ROSIDL.Int32 (Seconds);
      Stamp ("nanosec").As_UInt32 := ROSIDL.UInt32 (Real'Min (Nanos, 999_999_999.0));
   end Set_Time;

   procedure Set_Pose (Target : Field_Ref; P : Pose) is
      use Ada.Numerics.Long_Elementary_Functions;
   begin
      Target ("position")("x").As_Float64 := ROSIDL.Float64 (P.X);
      Target ("position")("y").As_Float64 := ROSIDL.Float64 (P.Y);
      Target ("position")("z").As_Float64 := 0.0;
      Target ("orientation")("x").As_Float64 := 0.0;
      Target ("orientation")("y").As_Float64 := 0.0;
      Target ("orientation")("z").As_Float64 := ROSIDL.Float64 (Sin (Long_Float (P.Yaw) / 2.0));
      Target ("orientation")("w").As_Float64 := ROSIDL.Float64 (Cos (Long_Float (P.Yaw) / 2.0));
   end Set_Pose;

   function Scan_Message (Scan : Robot.Sensors.Laser_Scan; Frame_Id : String) return Message is
      Result : constant Message :=
        Init (ROSIDL.Typesupport.Get_Message_Support ("sensor_msgs", "LaserScan"));
      Ranges : Float32_Array (1 .. Scan.Beams);
   begin
      for I in Ranges'Range loop
         Ranges (I) := ROSIDL.Float32 (Scan.Ranges (I));
      end loop;
      Set_Time (Result ("header")("stamp"), Scan.Stamp);
      Result ("header")("frame_id").Set_String (Frame_Id);
      Result ("angle_min").As_Float32 := ROSIDL.Float32 (Scan.Angle_Min);
      Result ("angle_max").As_Float32 := ROSIDL.Float32 (Scan.Angle_Max);
      Result ("angle_increment").As_Float32 := ROSIDL.Float32 (Scan.Angle_Increment);
      Result ("time_increment").As_Float32 := ROSIDL.Float32 (Scan.Time_Increment);
      Result ("scan_time").As_Float32 := ROSIDL.Float32 (Scan.Scan_Time);
      Result ("range_min").As_Float32 := ROSIDL.Float32 (Scan.Range_Min);
      Result ("range_max").As_Float32 := ROSIDL.Float32 (Scan.Range_Max);
      Result ("ranges").Set_Float32_Array (Ranges);
      return Result;
   end Scan_Message;

   function Fix_Message (Fix : Robot.Sensors.GPS_Fix) return Message is
      Result : constant Message := Init
        (ROSIDL.Typesupport.Get_Message_Support ("geometry_msgs", "PoseWithCovarianceStamped"));
      Cov    : Float64_Array (1 .. 36) := [others => 0.0];
   begin
      Set_Time (Result ("header")("stamp"), Fix.Stamp);
      Result ("header")("frame_id").Set_String ("map");
      Set_Pose (Result ("pose")("pose"), (Fix.Position.X, Fix.Position.Y, 0.0));
      Cov (1) := ROSIDL.Float64 (Fix.Std_Dev ** 2);
      Cov (8) := ROSIDL.Float64 (Fix.Std_Dev ** 2);
      Cov (36) := 1.0E6;
      Result ("pose")("covariance").Set_Float64_Array (Cov);
      return Result;
   end Fix_Message;

   function Twist_Message (Command : Robot.Sensors.Twist) return Message is
      Result : constant Message :=
        Init (ROSIDL.Typesupport.Get_Message_Support ("geometry_msgs", "Twist"));
   begin
      Result ("linear")("x").As_Float64 := ROSIDL.Float64 (Command.Linear_X);
      Result ("angular")("z").As_Float64 := ROSIDL.Float64 (Command.Angular_Z);
      return Result;
   end Twist_Message;

   function To_Twist (Msg : Message) return Robot.Sensors.Twist is
     ((Linear_X => F64 (Msg ("linear")("x")), Angular_Z => F64 (Msg ("angular")("z"))));

   function To_Fix (Msg : Message) return Robot.Sensors.GPS_Fix is
      Cov : constant Float64_Array := Msg ("pose")("covariance").Get_Float64_Array;
      Var : constant Real :=
        Real'Max (0.0, (Real (Cov (Cov'First)) + Real (Cov (Cov'First + 7))) / 2.0);
   begin
      return (Stamp    => Stamp_Of (Msg ("header")),
              Position => (F64 (Msg ("pose")("pose")("position")("x")),
                           F64 (Msg ("pose")("pose")("position")("y"))),
              Std_Dev  => Real (Ada.Numerics.Long_Elementary_Functions.Sqrt (Long_Float (Var))));
   end To_Fix;

   function Grid_Message
     (Frame    : Robot.Grids.Frame;
      Data     : Robot.Mappers.Cell_Value_Array;
      Stamp    : Real;
      Frame_Id : String) return Message
   is
      Result  : constant Message :=
        Init (ROSIDL.Typesupport.Get_Message_Support ("nav_msgs", "OccupancyGrid"));
      Cells   : Int8_Array (1 .. Data'Length);
      Seconds : constant Real := Real'Floor (Stamp);
   begin
      for I in Cells'Range loop
         Cells (I) := ROSIDL.Int8 (Data (Data'First + I - 1));
      end loop;
      Result ("header")("stamp")("sec").As_Int32 := ROSIDL.Int32 (Seconds);
      Result ("header")("stamp")("nanosec").As_UInt32 :=
        ROSIDL.UInt32 (Real'Min (Real'Floor ((Stamp - Seconds) * 1.0E9), 999_999_999.0));
      Result ("header")("frame_id").Set_String (Frame_Id);
      Result ("info")("map_load_time").Set_Message (Result ("header")("stamp").To_Message);
      Result ("info")("resolution").As_Float32 := ROSIDL.Float32 (Frame.Resolution);
      Result ("info")("width").As_UInt32 := ROSIDL.UInt32 (Frame.Width);
      Result ("info")("height").As_UInt32 := ROSIDL.UInt32 (Frame.Height);
      Result ("info")("origin")("position")("x").As_Float64 := ROSIDL.Float64 (Frame.Origin.X);
      Result ("info")("origin")("position")("y").As_Float64 := ROSIDL.Float64 (Frame.Origin.Y);
      Result ("info")("origin")("orientation")("w").As_Float64 := 1.0;
      Result ("data").Set_Int8_Array (Cells);
      return Result;
   end Grid_Message;

   function Parse_Goals (Text : String) return Robot.Goal_Sequencers.Point_Array is
      use Ada.Strings.Fixed;
      Count : constant Natural :=
        (if Trim (Text, Ada.Strings.Both) = "" then 0 else Ada.Strings.Fixed.Count (Text, ";") + 1);
      Result : Robot.Goal_Sequencers.Point_Array (1 .. Count);
      First  : Positive := Text'First;
   begin
      for G in 1 .. Count loop
         declare
            Stop  : constant Natural :=
              (if G = Count then Text'Last else Index (Text, ";", First) - 1);
            Item  : constant String := Text (First .. Stop);
            Comma : constant Natural := Index (Item, ",");

            function Coordinate (Part : String; Name : String) return Real is
               T : constant String := Trim (Part, Ada.Strings.Both);
            begin
               return Real'Value
                 (if T'Length > 0 and then Index (T, ".") = 0 and then Index (T, "e") = 0
                  then T & ".0" else T);
            exception
               when Constraint_Error =>
                  raise Goal_Error with "goal" & G'Image & " (column"
                    & Natural'Image (Item'First - Text'First + 1) & "): expected " & Name
                    & " (a number), found """ & T & """";
            end Coordinate;
         begin
            if Comma = 0 then
               raise Goal_Error with "goal" & G'Image & " (column"
                 & Natural'Image (Item'First - Text'First + 1) & "): expected ""x,y"", found """
                 & Trim (Item, Ada.Strings.Both) & """";
            end if;
            Result (G) := (Coordinate (Item (Item'First .. Comma - 1), "x"),
                           Coordinate (Item (Comma + 1 .. Item'Last), "y"));
            if not Result (G).X'Valid or else not Result (G).Y'Valid
              or else abs Result (G).X > 1.0E6 or else abs Result (G).Y > 1.0E6
            then
               raise Goal_Error with "goal" & G'Image & ": coordinates out of range";
            end if;
            First := Stop + 2;
         end;
      end loop;
      return Result;
   end Parse_Goals;

   function Goals_Problem (Text : String) return String is
   begin
      return (if Parse_Goals (Text)'Length = Natural'Last then "too many goals" else "");
   exception
      when E : Goal_Error =>
         return Ada.Exceptions.Exception_Message (E);
   end Goals_Problem;

   function Goals_Image (Goals : Robot.Goal_Sequencers.Point_Array) return String is
      function Img (X : Real) return String is
        (Runtime.Values.Real_Image (Long_Float (X)));
   begin
      if Goals'Length = 0 then
         return "";
      elsif Goals'Length = 1 then
         return Img (Goals (Goals'First).X) & "," & Img (Goals (Goals'First).Y);
      else
         return Goals_Image (Goals (Goals'First .. Goals'First))
           & ";" & Goals_Image (Goals (Goals'First + 1 .. Goals'Last));
      end if;
   end Goals_Image;

end Sancta.Standard_Components.Robot_Messages;
