with Ada.Directories;
with Ada.Environment_Variables;
with Ada.Strings.Unbounded;
with ROSIDL.Interfaces;

package body ROSIDL.CDR_Samples is

   use Ada.Strings.Unbounded;
   use ROSIDL.Definitions;
   use ROSIDL.Dynamic;
   use type UInt64;
   use ROSIDL.Typesupport;
   use type Int8, Int16, Int32, Int64, Float32, Float64;

   Test_Folder_Added, User_Folder_Added : Boolean := False;

   procedure Add_Once (Folder : String; Added : in out Boolean) is
      --  Folder (relative to the repository) on the search path, once.
      Root : constant String :=
        (if Ada.Environment_Variables.Exists ("SANCTA_ROOT")
         then Ada.Environment_Variables.Value ("SANCTA_ROOT")
         else Ada.Directories.Current_Directory);
   begin
      if not Added then
         ROSIDL.Interfaces.Add_Folder (Root & "/" & Folder);
         Added := True;
      end if;
   end Add_Once;

   procedure Use_Test_Interfaces is
   begin
      Add_Once ("tests/interfaces", Test_Folder_Added);
   end Use_Test_Interfaces;

   procedure Use_User_Interfaces is
   begin
      Add_Once ("tests/data/user_interfaces", User_Folder_Added);
   end Use_User_Interfaces;

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

      elsif Name = "texts" then
         Use_Test_Interfaces;
         return M : constant Message :=
           Init (Get_Message_Support ("cdr_test_msgs", "Texts"))
         do
            declare
               T : constant Field_Ref := M ("texts");
            begin
               T.As_Array.Resize (64);
               T.As_Array (1).Set_String ("");
               T.As_Array (2).Set_String ("true");
               T.As_Array (3).Set_String ("123");
               T.As_Array (4).Set_String ("1.5");
               T.As_Array (5).Set_String ("-x");
               T.As_Array (6).Set_String ("a: b");
               T.As_Array (7).Set_String ("#c");
               T.As_Array (8).Set_String (" lead");
               T.As_Array (9).Set_String ("trail ");
               T.As_Array (10).Set_String ("it's");
               T.As_Array (11).Set_String ("caf" & Character'Val (195) & Character'Val (169));
               T.As_Array (12).Set_String ("null");
               T.As_Array (13).Set_String ("~");
               T.As_Array (14).Set_String ("yes");
               T.As_Array (15).Set_String ("y");
               T.As_Array (16).Set_String ("0x1F");
               T.As_Array (17).Set_String ("tab" & Character'Val (9) & "here");
               T.As_Array (18).Set_String ("quote" & Character'Val (34) & "d");
               T.As_Array (19).Set_String ("[x]");
               T.As_Array (20).Set_String ("{y}");
               T.As_Array (21).Set_String ("@at");
               T.As_Array (22).Set_String ("`b");
               T.As_Array (23).Set_String ("%p");
               T.As_Array (24).Set_String ("!bang");
               T.As_Array (25).Set_String ("&amp");
               T.As_Array (26).Set_String ("*star");
               T.As_Array (27).Set_String ("|pipe");
               T.As_Array (28).Set_String (">gt");
               T.As_Array (29).Set_String ("?q");
               T.As_Array (30).Set_String (",comma");
               T.As_Array (31).Set_String ("a #b");
               T.As_Array (32).Set_String ("a#b");
               T.As_Array (33).Set_String ("x:");
               T.As_Array (34).Set_String ("1e5");
               T.As_Array (35).Set_String (".5");
               T.As_Array (36).Set_String ("+1");
               T.As_Array (37).Set_String ("Yes");
               T.As_Array (38).Set_String ("NO");
               T.As_Array (39).Set_String ("tRue");
               T.As_Array (40).Set_String ("2023-01-01");
               T.As_Array (41).Set_String ("2023-1-1 10:00:00");
               T.As_Array (42).Set_String ("0o17");
               T.As_Array (43).Set_String ("1_000");
               T.As_Array (44).Set_String (":colon");
               T.As_Array (45).Set_String ("-");
               T.As_Array (46).Set_String ("- x");
               T.As_Array (47).Set_String ("=");
               T.As_Array (48).Set_String ("<<");
               T.As_Array (49).Set_String ("1:30");
               T.As_Array (50).Set_String ("1.0e+5");
               T.As_Array (51).Set_String ("1.0e5");
               T.As_Array (52).Set_String ("---");
               T.As_Array (53).Set_String ("--- x");
               T.As_Array (54).Set_String ("...");
               T.As_Array (55).Set_String ("back\slash");
               T.As_Array (56).Set_String ("bell" & Character'Val (7));
               T.As_Array (57).Set_String ("del" & Character'Val (127));
               T.As_Array (58).Set_String (".nan");
               T.As_Array (59).Set_String ("-.inf");
               T.As_Array (60).Set_String (".");
               T.As_Array (61).Set_String ("0b101");
               T.As_Array (62).Set_String ("0777");
               T.As_Array (63).Set_String ("09");
               T.As_Array (64).Set_String ("plain text");
            end;
         end return;

      elsif Name = "doubles" then
         return M : constant Message :=
           Init (Get_Message_Support ("std_msgs", "Float64MultiArray"))
         do
            M ("layout")("dim").As_Array.Resize (1);
            M ("layout")("dim").As_Array (1)("label").Set_String ("x");
            M ("layout")("dim").As_Array (1)("size").As_UInt32 := 9;
            M ("layout")("dim").As_Array (1)("stride").As_UInt32 := 9;
            M ("data").Set_Float64_Array
              ([0.1, 1.0E-5, 1.0E22, 1.0E16, 123_456.789, -2.5, 0.0, -0.0,
                Float64'Last]);
         end return;

      elsif Name = "floats" then
         return M : constant Message :=
           Init (Get_Message_Support ("std_msgs", "Float32MultiArray"))
         do
            M ("data").Set_Float32_Array
              ([0.1, 1.0E-5, 3.0E38, 16_777_216.0, -Float32'Succ (0.0), 0.05, Float32'Last]);
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

   ---------------------------------------------------------------------------
   --  Random messages
   ---------------------------------------------------------------------------

   function Next (Seed : in out UInt64) return UInt64 is
      use Standard.Interfaces;
   begin
      Seed := Seed xor Shift_Right (Seed, 12);
      Seed := Seed xor Shift_Left (Seed, 25);
      Seed := Seed xor Shift_Right (Seed, 27);
      return Seed * 16#2545_F491_4F6C_DD1D#;
   end Next;

   function Below (Seed : in out UInt64; N : Positive) return Natural is
     (Natural (Next (Seed) mod UInt64 (N)));

   function Random_Text
     (Bound : Natural; Seed : in out UInt64; ASCII_Text : Boolean) return String is
      Length : constant Natural :=
        Below (Seed, (if Bound > 0 then Natural'Min (Bound, 12) else 12) + 1);
      Result : String (1 .. Length);
   begin
      for C of Result loop
         C := (if ASCII_Text then Character'Val (32 + Below (Seed, 95))
               else Character'Val (1 + Below (Seed, 255)));
      end loop;
      return Result;
   end Random_Text;

   function Random_Wide_Text
     (Bound : Natural; Seed : in out UInt64) return Wide_Wide_String is
      Length : constant Natural :=
        Below (Seed, (if Bound > 0 then Natural'Min (Bound, 6) else 6) + 1);
      Result : Wide_Wide_String (1 .. Length);
   begin
      for C of Result loop
         C := Wide_Wide_Character'Val (Below (Seed, 16#11_0000#));
      end loop;
      return Result;
   end Random_Wide_Text;

   procedure Fill_Field
     (F : Field_Ref; T : Field_Type; Seed : in out UInt64; ASCII_Text : Boolean);

   procedure Fill_Element
     (E : Field_Ref; T : Field_Type; Seed : in out UInt64; ASCII_Text : Boolean)
   is
      use Standard.Interfaces;
      R : constant Unsigned_64 := Next (Seed);
   begin
      case T.Kind is
         when Bool_Kind    => E.As_Bool := R mod 2 = 0;
         when Byte_Kind    => E.As_Byte := Unsigned_8 (R mod 256);
         when Char_Kind    => E.As_Char := Unsigned_8 (R mod 256);
         when UInt8_Kind   => E.As_UInt8 := Unsigned_8 (R mod 256);
         when Int8_Kind    => E.As_Int8 := Integer_8 (Integer (R mod 256) - 128);
         when Int16_Kind   => E.As_Int16 := Integer_16 (Integer (R mod 65_536) - 32_768);
         when UInt16_Kind  => E.As_UInt16 := Unsigned_16 (R mod 65_536);
         when Int32_Kind   =>
            E.As_Int32 := Integer_32 (Long_Long_Integer (R mod 2**32) - 2**31);
         when UInt32_Kind  => E.As_UInt32 := Unsigned_32 (R mod 2**32);
         when Int64_Kind   =>
            E.As_Int64 := Integer_64 (Long_Long_Integer (R mod 2**62) - 2**61);
         when UInt64_Kind  => E.As_UInt64 := R;
         when Float32_Kind =>
            E.As_Float32 := IEEE_Float_32 (Long_Long_Integer (R mod 2**24) - 2**23)
              / 2.0 ** Natural (R / 2**60);
         when Float64_Kind =>
            E.As_Float64 := IEEE_Float_64 (Long_Long_Integer (R mod 2**50) - 2**49)
              / 2.0 ** Natural (R / 2**59);
         when String_Kind  => E.Set_String (Random_Text (T.String_Bound, Seed, ASCII_Text));
         when WString_Kind => E.Set_WString (Random_Wide_Text (T.String_Bound, Seed));
         when Message_Kind =>
            for F of T.Nested.Fields loop
               Fill_Field (E (To_String (F.Name)), F.Of_Type, Seed, ASCII_Text);
            end loop;
      end case;
   end Fill_Element;

   procedure Fill_Field
     (F : Field_Ref; T : Field_Type; Seed : in out UInt64; ASCII_Text : Boolean) is
   begin
      if T.Collection = Single then
         Fill_Element (F, T, Seed, ASCII_Text);
         return;
      end if;
      if T.Collection /= Fixed_Array then
         F.As_Array.Resize
           (Below (Seed, (if T.Collection = Bounded_Sequence then Natural'Min (T.Size, 4)
                    else 4) + 1));
      end if;
      for I in 1 .. F.As_Array.Length loop
         Fill_Element (F.As_Array (I), T, Seed, ASCII_Text);
      end loop;
   end Fill_Field;

   function Random_Message
     (Support : Message_Support; Seed : in out UInt64; ASCII_Text : Boolean := False)
      return Message is
   begin
      return M : constant Message := Init (Support) do
         for F of Definition (Support).Fields loop
            Fill_Field (M (To_String (F.Name)), F.Of_Type, Seed, ASCII_Text);
         end loop;
      end return;
   end Random_Message;


   function All_Types return Support_Vectors.Vector is
      type Part_Array is array (Positive range <>) of ROSIDL.Definitions.Message_Access;
      Result : Support_Vectors.Vector;
   begin
      Use_Test_Interfaces;
      for Pkg of ROSIDL.Interfaces.Packages loop
         for Name of ROSIDL.Interfaces.Messages (Pkg) loop
            Result.Append (Get_Message_Support (Pkg, Name));
         end loop;
         for Name of ROSIDL.Interfaces.Services (Pkg) loop
            declare
               S : constant Service_Support := Get_Service_Support (Pkg, Name);
            begin
               Result.Append (Request_Support (S));
               Result.Append (Response_Support (S));
            end;
         end loop;
         for Name of ROSIDL.Interfaces.Actions (Pkg) loop
            declare
               A : constant ROSIDL.Definitions.Action_Access :=
                 ROSIDL.Interfaces.Action (Pkg, Name);
            begin
               for Part of Part_Array'
                 [A.Goal, A.Result, A.Feedback, A.Feedback_Message,
                  A.Send_Goal.Request, A.Send_Goal.Response,
                  A.Get_Result.Request, A.Get_Result.Response]
               loop
                  Result.Append (To_Support (Part));
               end loop;
            end;
         end loop;
      end loop;
      return Result;
   end All_Types;

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
         raise Constraint_Error with "odd number of hex digits:" & Natural'Image (N);
      end if;
      for I in 1 .. N loop
         if Clean (I) not in '0' .. '9' | 'a' .. 'f' | 'A' .. 'F' then
            raise Constraint_Error with "'" & Clean (I) & "' is not a hex digit (digit"
              & Natural'Image (I) & ")";
         end if;
      end loop;
      return Result : Stream_Element_Array (1 .. Stream_Element_Offset (N / 2)) do
         for I in Result'Range loop
            Result (I) := Stream_Element'Value
              ("16#" & Clean (Natural (I) * 2 - 1 .. Natural (I) * 2) & "#");
         end loop;
      end return;
   end From_Hex;

end ROSIDL.CDR_Samples;
