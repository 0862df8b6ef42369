with Ada.Directories;
with Ada.Environment_Variables;
with ROSIDL.Interfaces;
with ROSIDL.Typesupport;

package body ROSIDL.CDR.Samples is

   use ROSIDL.Dynamic;
   use ROSIDL.Typesupport;
   use type Int8, Int16, Int32, Int64, Float32, Float64;

   Added : Boolean := False;

   procedure Use_Test_Interfaces is
      Root : constant String :=
        (if Ada.Environment_Variables.Exists ("SANCTA_ROOT")
         then Ada.Environment_Variables.Value ("SANCTA_ROOT")
         else Ada.Directories.Current_Directory);
   begin
      if not Added then
         ROSIDL.Interfaces.Add_Folder (Root & "/tests/interfaces");
         Added := True;
      end if;
   end Use_Test_Interfaces;

   procedure Set_Header (H : Field_Ref; Sec : Int32; Nanosec : UInt32; Frame : String)
   is
   begin
      H ("stamp")("sec").As_Int32 := Sec;
      H ("stamp")("nanosec").As_UInt32 := Nanosec;
      H ("frame_id").Set_String (Frame);
   end Set_Header;

   procedure Set_Point (P : Field_Ref; X, Y, Z : Float64) is
   begin
      P ("x").As_Float64 := X;
      P ("y").As_Float64 := Y;
      P ("z").As_Float64 := Z;
   end Set_Point;

   function Make (Name : String) return Message is
   begin
      if Name = "string_hi" then
         return M : constant Message :=
           Init (Get_Message_Support ("std_msgs", "String"))
         do
            M ("data").Set_String ("hi");
         end return;

      elsif Name = "header" then
         return M : constant Message :=
           Init (Get_Message_Support ("std_msgs", "Header"))
         do
            M ("stamp")("sec").As_Int32 := 1_700_000_000;
            M ("stamp")("nanosec").As_UInt32 := 123_456_789;
            M ("frame_id").Set_String ("base_link");
         end return;

      elsif Name = "laser_scan" then
         return M : constant Message :=
           Init (Get_Message_Support ("sensor_msgs", "LaserScan"))
         do
            Set_Header (M ("header"), 10, 500, "laser");
            M ("angle_min").As_Float32 := -1.5;
            M ("angle_max").As_Float32 := 1.5;
            M ("angle_increment").As_Float32 := 0.25;
            M ("time_increment").As_Float32 := 0.001;
            M ("scan_time").As_Float32 := 0.1;
            M ("range_min").As_Float32 := 0.1;
            M ("range_max").As_Float32 := 30.0;
            declare
               Ranges      : Float32_Array (1 .. 13);
               Intensities : Float32_Array (1 .. 13);
            begin
               for I in Ranges'Range loop
                  Ranges (I) := Float32 (I) * 0.5;
                  Intensities (I) := 100.0 + Float32 (I);
               end loop;
               M ("ranges").Set_Float32_Array (Ranges);
               M ("intensities").Set_Float32_Array (Intensities);
            end;
         end return;

      elsif Name = "odometry" then
         return M : constant Message := Init (Get_Message_Support ("nav_msgs", "Odometry")) do
            Set_Header (M ("header"), 5, 6, "odom");
            M ("child_frame_id").Set_String ("base_link");
            Set_Point (M ("pose")("pose")("position"), 1.0, 2.0, 3.0);
            M ("pose")("pose")("orientation")("z").As_Float64 := 0.5;
            M ("pose")("pose")("orientation")("w").As_Float64 := 0.75;
            declare
               Cov : Float64_Array (1 .. 36);
            begin
               for I in Cov'Range loop
                  Cov (I) := Float64 (I - 1) * 0.125;
               end loop;
               M ("pose")("covariance").Set_Float64_Array (Cov);
               for I in Cov'Range loop
                  Cov (I) := -Float64 (I - 1);
               end loop;
               M ("twist")("covariance").Set_Float64_Array (Cov);
            end;
            M ("twist")("twist")("linear")("x").As_Float64 := 0.5;
            M ("twist")("twist")("angular")("z").As_Float64 := 0.25;
         end return;

      elsif Name = "occupancy_grid" then
         return M : constant Message :=
           Init (Get_Message_Support ("nav_msgs", "OccupancyGrid"))
         do
            Set_Header (M ("header"), 1, 2, "map");
            M ("info")("map_load_time")("sec").As_Int32 := 3;
            M ("info")("map_load_time")("nanosec").As_UInt32 := 4;
            M ("info")("resolution").As_Float32 := 0.05;
            M ("info")("width").As_UInt32 := 4;
            M ("info")("height").As_UInt32 := 3;
            Set_Point (M ("info")("origin")("position"), -1.0, -2.0, 0.0);
            M ("info")("origin")("orientation")("w").As_Float64 := 1.0;
            declare
               Data : Int8_Array (1 .. 12);
            begin
               for I in Data'Range loop
                  Data (I) := Int8 ((I mod 3) * 50 - 1);
               end loop;
               M ("data").Set_Int8_Array (Data);
            end;
         end return;

      elsif Name = "add_two_ints_request" then
         return M : constant Message :=
           Init (Request_Support
                   (Get_Service_Support ("example_interfaces", "AddTwoInts")))
         do
            M ("a").As_Int64 := 2;
            M ("b").As_Int64 := 3;
         end return;

      elsif Name = "everything" then
         Use_Test_Interfaces;
         return M : constant Message :=
           Init (Get_Message_Support ("cdr_test_msgs", "Everything"))
         do
            M ("b").As_Bool := True;
            M ("by").As_Byte := 16#AB#;
            M ("c").As_Char := Character'Pos ('Z');
            M ("f32").As_Float32 := -2.5;
            M ("f64").As_Float64 := 3.125;
            M ("i8").As_Int8 := -8;
            M ("u8").As_UInt8 := 200;
            M ("i16").As_Int16 := -16_000;
            M ("u16").As_UInt16 := 65_000;
            M ("i32").As_Int32 := -2_000_000_000;
            M ("u32").As_UInt32 := 4_000_000_000;
            M ("i64").As_Int64 := -9_000_000_000_000_000_000;
            M ("u64").As_UInt64 := 18_000_000_000_000_000_000;
            M ("s").Set_String ("every");
            M ("bs").Set_String ("bounded");
         end return;

      elsif Name = "arrays" then
         Use_Test_Interfaces;
         return M : constant Message := Init (Get_Message_Support ("cdr_test_msgs", "Arrays")) do
            M ("fixed_i32").Set_Int32_Array ([-1, 0, 1]);
            M ("fixed_f64").Set_Float64_Array ([0.5, -0.25]);
            M ("fixed_strings").As_Array (1).Set_String ("a");
            M ("fixed_strings").As_Array (2).Set_String ("bcd");
            M ("bounded_u8").Set_UInt8_Array ([1, 2, 3]);
            M ("bounded_f32").Set_Float32_Array ([1.5]);
            M ("bounded_strings").As_Array.Resize (2);
            M ("bounded_strings").As_Array (1).Set_String ("x");
            M ("bounded_strings").As_Array (2).Set_String ("yz");
            M ("seq_i16").Set_Int16_Array ([7, -7, 300, -300, 0]);
            Set_Point (M ("points").As_Array (1), 1.0, 2.0, 3.0);
            Set_Point (M ("points").As_Array (2), -1.0, -2.0, -3.0);
            M ("bounded_points").As_Array.Resize (1);
            Set_Point (M ("bounded_points").As_Array (1), 0.5, 0.25, 0.125);
            M ("flags").Set_Bool_Array ([True, False, True]);
            M ("tail").As_UInt8 := 255;
         end return;

      elsif Name = "wstrings" then
         Use_Test_Interfaces;
         return M : constant Message :=
           Init (Get_Message_Support ("cdr_test_msgs", "WStrings"))
         do
            M ("head").As_UInt8 := 1;
            M ("w").Set_WString ("h" & Wide_Wide_Character'Val (16#E9#)
                                 & Wide_Wide_Character'Val (16#1F600#));
            M ("bw").Set_WString ("abc");
            M ("ws").As_Array.Resize (2);
            M ("ws").As_Array (2).Set_WString ("z");
         end return;
      end if;
      raise Constraint_Error with "unknown sample " & Name;
   end Make;

   function Encode_Sample
     (Name : String; Order : Byte_Order := Little_Endian)
      return Ada.Streams.Stream_Element_Array is
   begin
      if Is_Request (Name) then
         return Encode (Make (Name), Test_Header, Order);
      else
         return Encode (Make (Name), Order);
      end if;
   end Encode_Sample;

   Digit : constant String := "0123456789abcdef";

   function Hex (Data : Ada.Streams.Stream_Element_Array) return String is
      Result : String (1 .. 2 * Data'Length);
      J      : Positive := 1;
   begin
      for B of Data loop
         Result (J) := Digit (Natural (B) / 16 + 1);
         Result (J + 1) := Digit (Natural (B) mod 16 + 1);
         J := J + 2;
      end loop;
      return Result;
   end Hex;

   function From_Hex (Text : String) return Ada.Streams.Stream_Element_Array is
      Clean : String (1 .. Text'Length);
      N     : Natural := 0;
   begin
      for C of Text loop
         if C /= ' ' and then C /= ASCII.LF then
            N := N + 1;
            Clean (N) := C;
         end if;
      end loop;
      if N mod 2 /= 0 then
         raise Constraint_Error with "odd number of hex digits";
      end if;
      return Result : Stream_Element_Array (1 .. Stream_Element_Offset (N / 2)) do
         for I in Result'Range loop
            Result (I) := Stream_Element'Value
              ("16#" & Clean (Natural (I) * 2 - 1 .. Natural (I) * 2) & "#");
         end loop;
      end return;
   end From_Hex;

end ROSIDL.CDR.Samples;
