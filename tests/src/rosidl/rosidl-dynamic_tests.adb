with Ada.Exceptions;
with Ada.Streams;
with AUnit.Assertions;
with ROSIDL.CDR;
with ROSIDL.CDR_Samples;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Suite_Support; use Suite_Support;

package body ROSIDL.Dynamic_Tests is

   use AUnit.Assertions;
   use ROSIDL.Dynamic;
   use ROSIDL.Typesupport;
   use type Int8, Int16, Int32, Int64, UInt32, Float32, Float64;
   use type Ada.Streams.Stream_Element_Offset;

   function Text_Of (E : Ada.Exceptions.Exception_Occurrence) return String
     renames Ada.Exceptions.Exception_Message;

   function Defaults return Message is
   begin
      ROSIDL.CDR_Samples.Use_Test_Interfaces;
      return Init (Get_Message_Support ("cdr_test_msgs", "Defaults"));
   end Defaults;

   LF : constant Character := ASCII.LF;

   ---------------------------------------------------------------------------

   procedure Scalars_By_Name (Unused : in out Fixture) is
      M : constant Message := Init (Get_Message_Support ("geometry_msgs", "Point"));
   begin
      Assert (M ("x").As_Float64 = 0.0, "zero by default");
      M ("x").As_Float64 := 1.5;
      M ("y").As_Float64 := M ("x").As_Float64 * 2.0;
      Assert (M ("x").As_Float64 = 1.5 and then M ("y").As_Float64 = 3.0, "set/get");
      Assert (Type_Name (M) = "geometry_msgs/msg/Point", Type_Name (M));
      Assert (Name (M ("z")) = "z", "name");
   end Scalars_By_Name;

   procedure Spec_Example (Unused : in out Fixture) is
      --  The usage example of the ROSIDL.Dynamic spec, as written there.
      Scan : constant Float32_Array (1 .. 720) := [others => 2.0];
      Msg  : constant Message :=
        Init (Get_Message_Support ("sensor_msgs", "LaserScan"));
   begin
      Msg ("angle_min").As_Float32 := -1.57;
      Msg ("header")("frame_id").Set_String ("laser");
      Msg ("header").Get_Message ("stamp")("sec").As_Int32 := 12;
      Msg ("ranges").As_Array.Resize (720);
      Msg ("ranges").As_Array (42).As_Float32 := 1.5;
      Assert (Msg ("ranges").As_Array (42).As_Float32 = 1.5, "element 42");
      Msg ("ranges").Set_Float32_Array (Scan);
      Assert (Msg ("ranges").As_Array (42).As_Float32 = 2.0, "bulk");
      Assert (Msg ("header")("stamp")("sec").As_Int32 = 12, "nested");
      Assert (Contains (Image (Msg), "  frame_id: laser" & LF), Image (Msg));
   end Spec_Example;

   procedure Defaults_And_Constants (Unused : in out Fixture) is
      M : constant Message := Defaults;
   begin
      Assert (M ("count").As_Int32 = 7, "int default");
      Assert (M ("ratio").As_Float32 = 0.25, "float default");
      Assert (M ("name").Get_String = "robot", "string default");
      Assert (M ("enabled").As_Bool, "bool default");
      Assert (M ("triple").Get_Int16_Array = [1, 2, 3], "fixed array default");
      Assert (M ("weights").Get_Float64_Array = [0.5, 1.5], "sequence default");
      Assert (M ("bytes_seq").As_Array.Length = 0, "sequences empty");
      Assert (M ("nested")("s").Get_String = "", "nested zero");
      Assert (Constant_Value (M, "ANSWER") = "42", "constant text");
      Assert (Constant_Int64 (M, "ANSWER") = 42, "constant int");
      Assert (Constant_Float64 (M, "HALF") = 0.5, "constant float");
      Assert (Constant_Value (M, "GREETING") = "hello", "string constant");
      Assert (Constant_Value (M, "FLAG") = "true", "bool constant");
      declare
         Q : constant Message :=
           Init (Get_Message_Support ("geometry_msgs", "Quaternion"));
      begin
         Assert (Q ("w").As_Float64 = 1.0, "Quaternion.w defaults to 1");
      end;
      begin
         Assert (Constant_Value (M, "NOPE") = "", "unknown constant");
         Assert (False, "unknown constant must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "ANSWER, HALF, GREETING, FLAG"), Text_Of (E));
      end;
   end Defaults_And_Constants;

   procedure Non_Finite_Defaults (Unused : in out Fixture) is
      --  cdr_test_msgs/NonFinite: nan, inf and -inf defaults and constants
      --  (non-finite values are looked at through Is_NaN and Image: reading
      --  them as Ada floats fails validity checks).
      M : Message;
      procedure Not_A_Number (Name : String) is
      begin
         Assert (Constant_Float64 (M, Name) = 0.0, "non-finite constant as a number");
         Assert (False, Name & " as Float64 must raise Field_Error");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "not a finite number"), Text_Of (E));
      end Not_A_Number;
   begin
      ROSIDL.CDR_Samples.Use_Test_Interfaces;
      M := Init (Get_Message_Support ("cdr_test_msgs", "NonFinite"));
      declare
         Text : constant String := Image (M);
      begin
         Assert (Contains (Text, "quiet: .nan" & ASCII.LF), "nan default: " & Text);
         Assert (Contains (Text, "top: .inf" & ASCII.LF), "inf default: " & Text);
         Assert (Contains (Text, "bottom: -.inf" & ASCII.LF), "-inf default: " & Text);
         Assert (Contains (Text, "mixed:" & ASCII.LF & "- .nan" & ASCII.LF & "- -.inf"
                           & ASCII.LF & "- 1.5" & ASCII.LF), "array defaults: " & Text);
         Assert (Contains (Text, "dynamic_seq:" & ASCII.LF & "- .inf" & ASCII.LF & "- .nan"),
                 "sequence defaults: " & Text);
      end;
      Assert (M ("quiet").Is_NaN and not M ("top").Is_NaN, "Is_NaN");
      Assert (M ("mixed").As_Array (1).Is_NaN, "array nan");
      Assert (M ("mixed").As_Array (3).As_Float32 = 1.5, "array 1.5");
      Assert (M ("dynamic_seq").As_Array.Length = 2, "sequence default length");
      Assert (Constant_Value (M, "NOT_A_NUMBER") = "nan", "nan constant text");
      Assert (Constant_Value (M, "SMALL") = "-inf", "-inf constant text");
      Not_A_Number ("NOT_A_NUMBER");
      Not_A_Number ("BIG");
      Not_A_Number ("SMALL");
   end Non_Finite_Defaults;

   procedure UTF_8_WStrings (Unused : in out Fixture) is
      --  cdr_test_msgs/Unicode: wstring defaults and constants in UTF-8.
      E_Acute : constant Wide_Wide_Character := Wide_Wide_Character'Val (16#E9#);
      Euro    : constant Wide_Wide_Character := Wide_Wide_Character'Val (16#20AC#);
      Smile   : constant Wide_Wide_Character := Wide_Wide_Character'Val (16#1F600#);
      M       : Message;
   begin
      ROSIDL.CDR_Samples.Use_Test_Interfaces;
      M := Init (Get_Message_Support ("cdr_test_msgs", "Unicode"));
      Assert (M ("word").Get_WString = E_Acute & "t" & E_Acute,
              "wstring default decoded as UTF-8 (3 characters), got"
              & M ("word").Get_WString'Length'Image);
      Assert (M ("bounded").Get_WString = Euro & Euro, "bounded wstring default");
      Assert (M ("pair").As_Array (1).Get_WString = Wide_Wide_Character'Val (16#E0#) & "",
              "wstring array default");
      Assert (M ("pair").As_Array (2).Get_WString = "b", "wstring array default 2");
      Assert (M ("plain").Get_String = "" & Character'Val (16#C3#) & Character'Val (16#A9#),
              "string default keeps its UTF-8 bytes");
      Assert (Constant_WString (M, "GREETING") = "h" & E_Acute & " " & Euro & " " & Smile,
              "wstring constant decoded as UTF-8");
      declare
         Encoded : constant Ada.Streams.Stream_Element_Array := ROSIDL.CDR.Encode (M);
         Back    : constant Message := ROSIDL.CDR.Decode (Support (M), Encoded);
      begin
         Assert (Back ("word").Get_WString = E_Acute & "t" & E_Acute, "CDR round trip");
      end;
   end UTF_8_WStrings;

   procedure Nested_References (Unused : in out Fixture) is
      M     : constant Message :=
        Init (Get_Message_Support ("sensor_msgs", "LaserScan"));
      Stamp : constant Field_Ref := M ("header").Get_Message ("stamp");
   begin
      Stamp ("sec").As_Int32 := 12;
      M ("header")("stamp")("nanosec").As_UInt32 := 34;
      M ("header")("frame_id").Set_String ("laser");
      Assert (M ("header")("stamp")("sec").As_Int32 = 12, "write through a reference");
      Assert (Stamp ("nanosec").As_UInt32 = 34, "reference sees later writes");
      declare
         Copy : constant Message := To_Message (M ("header"));
      begin
         Assert (Copy ("frame_id").Get_String = "laser", "To_Message copies");
         Copy ("frame_id").Set_String ("other");
         Assert (M ("header")("frame_id").Get_String = "laser", "a copy is separate");
         M ("header").Set_Message (Copy);
         Assert (M ("header")("frame_id").Get_String = "other", "Set_Message");
      end;
   end Nested_References;

   procedure Value_Semantics (Unused : in out Fixture) is
      A : constant Message := ROSIDL.CDR_Samples.Make ("laser_scan");
      B : Message := A;
   begin
      Assert (A = B, "copy equal");
      B ("ranges").As_Array (1).As_Float32 := 99.0;
      Assert (A ("ranges").As_Array (1).As_Float32 = 0.5, "copy is deep");
      Assert (A /= B, "now different");
      B := A;
      Assert (A = B, "assignment copies back");
      --  Decoded messages share storage with their copies until written.
      declare
         D1 : constant Message := ROSIDL.CDR.Decode (Support (A), ROSIDL.CDR.Encode (A));
         D2 : constant Message := D1;
         D3 : Message := D1;
      begin
         D2 ("angle_min").As_Float32 := 7.0;
         Assert (D1 ("angle_min").As_Float32 = -1.5, "write to a sharing copy");
         Assert (D2 ("angle_min").As_Float32 = 7.0, "the copy changed");
         ROSIDL.CDR.Decode (ROSIDL.CDR.Encode (D2), D3);
         Assert (D3 = D2 and then D1 = A, "decoding into a sharing copy");
         D3 := D1;
         D1 ("ranges").As_Array (2).As_Float32 := -5.0;
         Assert (D3 ("ranges").As_Array (2).As_Float32 = 1.0, "referenced root copied");
      end;
   end Value_Semantics;

   procedure Concurrent_Readers (Unused : in out Fixture) is
      --  Two tasks index the same message object while it shares its
      --  storage: each takes a private copy under a lock, once.
      Original : constant Message := ROSIDL.CDR_Samples.Make ("laser_scan");
      Source   : constant Message :=
        ROSIDL.CDR.Decode (Support (Original), ROSIDL.CDR.Encode (Original));
      --  Never indexed: its storage stays shareable.
      Expected : Float32 := 0.0;
   begin
      for K in 1 .. 13 loop
         Expected := Expected + Original ("ranges").As_Array (K).As_Float32;
      end loop;
      for Round in 1 .. 300 loop
         declare
            Shared : constant Message := Source;
            Sums   : array (1 .. 2) of Float32 := [others => 0.0];

            protected Start is
               entry Go;
               --  Released when both readers have arrived.
            private
               Arrived : Natural := 0;
            end Start;

            protected body Start is
               entry Go when Go'Count + Arrived >= 2 is
               begin
                  Arrived := Arrived + 1;
               end Go;
            end Start;

            task type Reader (Id : Positive);
            task body Reader is
            begin
               Start.Go;
               for K in 1 .. 13 loop
                  Sums (Id) := Sums (Id) + Shared ("ranges").As_Array (K).As_Float32;
               end loop;
            end Reader;
         begin
            declare
               R1 : Reader (1);
               R2 : Reader (2);
               pragma Unreferenced (R1, R2);
            begin
               null;
            end;
            Assert (Sums (1) = Expected and then Sums (2) = Expected,
                    "round" & Round'Image & ": a reader saw other values");
         end;
      end loop;
      Assert (Source = Original, "the shared source is unchanged");
   end Concurrent_Readers;

   procedure Arrays_And_Limits (Unused : in out Fixture) is
      M : constant Message := ROSIDL.CDR_Samples.Make ("arrays");
      R : constant Array_Ref := M ("seq_i16").As_Array;
   begin
      Assert (R.Length = 5 and then R (3).As_Int16 = 300, "length / element");
      R.Resize (7);
      Assert (R.Length = 7 and then R (7).As_Int16 = 0 and then R (5).As_Int16 = 0,
              "grown with zeros, contents kept");
      Assert (R (1).As_Int16 = 7, "kept");
      R.Resize (2);
      Assert (M ("seq_i16").Get_Int16_Array = [7, -7], "shrunk");
      Assert (R.Capacity = Natural'Last, "unbounded capacity");
      Assert (M ("bounded_u8").As_Array.Capacity = 5, "bound");
      begin
         M ("seq_i16").As_Array (3).As_Int16 := 1;
         Assert (False, "index 3 of 2 must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "index 3 out of range 1 .. 2"), Text_Of (E));
      end;
      begin
         M ("fixed_i32").As_Array.Resize (4);
         Assert (False, "a fixed array is not resizable");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "fixed array int32[3]"), Text_Of (E));
      end;
      begin
         M ("bounded_u8").As_Array.Resize (6);
         Assert (False, "a bounded sequence is not resizable beyond its bound");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "uint8[<=5]"), Text_Of (E));
      end;
      begin
         M ("bounded_u8").Set_UInt8_Array ([1, 2, 3, 4, 5, 6]);
         Assert (False, "bulk set beyond a bound");
      exception
         when Field_Error =>
            null;
      end;
      M ("bounded_u8").As_Array.Resize (5);
      Assert (M ("bounded_u8").Get_UInt8_Array = [1, 2, 3, 0, 0], "resize to the bound");
      Assert (M ("points").As_Array (2)("y").As_Float64 = -2.0, "nested element");
      M ("bounded_points").As_Array.Resize (3);
      M ("bounded_points").As_Array (3)("z").As_Float64 := 4.0;
      Assert (M ("bounded_points").As_Array (1)("x").As_Float64 = 0.5
              and then M ("bounded_points").As_Array (3)("z").As_Float64 = 4.0,
              "nested sequence resize");
      Assert (M ("fixed_strings").As_Array (2).Get_String = "bcd", "string element");
   end Arrays_And_Limits;

   procedure Bulk_Access (Unused : in out Fixture) is
      M      : constant Message :=
        Init (Get_Message_Support ("nav_msgs", "OccupancyGrid"));
      Values : Int8_Array (1 .. 1_000);
   begin
      for I in Values'Range loop
         Values (I) := Int8 (I mod 100);
      end loop;
      M ("data").Set_Int8_Array (Values);
      Assert (M ("data").As_Array.Length = 1_000, "length");
      Assert (M ("data").As_Array (250).As_Int8 = 50, "element");
      Assert (M ("data").Get_Int8_Array = Values, "get");
      begin
         Assert (M ("data").Get_UInt8_Array'Length = 0, "wrong bulk type");
         Assert (False, "uint8 bulk access to int8[] must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "expected int8[], requested a uint8"),
                    Text_Of (E));
      end;
   end Bulk_Access;

   procedure Non_Finite_Floats (Unused : in out Fixture) is
      --  A LaserScan whose ranges hold NaN and +inf (as lasers report), from
      --  bytes: bulk access copies them; Is_NaN tells them apart.
      Scan : constant Message := Init (Get_Message_Support ("sensor_msgs", "LaserScan"));
   begin
      Scan ("ranges").Set_Float32_Array ([1.0, 2.0, 3.0]);
      declare
         Data : Ada.Streams.Stream_Element_Array := ROSIDL.CDR.Encode (Scan);
         Last : constant Ada.Streams.Stream_Element_Offset := Data'Last;
      begin
         --  ranges[1] := NaN, ranges[2] := +inf (little-endian), then the
         --  empty intensities count (last 4 bytes).
         Data (Last - 11 .. Last - 8) := [16#00#, 16#00#, 16#C0#, 16#7F#];
         Data (Last - 7 .. Last - 4) := [16#00#, 16#00#, 16#80#, 16#7F#];
         declare
            Back   : constant Message := ROSIDL.CDR.Decode (Support (Scan), Data);
            Ranges : constant Float32_Array := Back ("ranges").Get_Float32_Array;
         begin
            Assert (Ranges'Length = 3, "three ranges");
            Assert (not Back ("ranges").As_Array (1).Is_NaN, "1.0 is a number");
            Assert (Back ("ranges").As_Array (2).Is_NaN, "NaN");
            Assert (not Back ("ranges").As_Array (3).Is_NaN, "+inf is not NaN");
            Assert (Contains (Image (Back), "- 1.0" & LF & "- .nan" & LF & "- .inf" & LF),
                    Image (Back));
         end;
      end;
   end Non_Finite_Floats;

   procedure Matrix_Views (Unused : in out Fixture) is
      M      : constant Message :=
        Init (Get_Message_Support ("std_msgs", "Float32MultiArray"));
      Dims   : constant Array_Ref := M ("layout")("dim").As_Array;
      Values : Float32_Array (1 .. 2 + 3 * 4);
   begin
      --  A 3 x 4 row-major matrix after 2 leading elements.
      Dims.Resize (2);
      Dims (1)("label").Set_String ("rows");
      Dims (1)("size").As_UInt32 := 3;
      Dims (1)("stride").As_UInt32 := 12;
      Dims (2)("label").Set_String ("cols");
      Dims (2)("size").As_UInt32 := 4;
      Dims (2)("stride").As_UInt32 := 4;
      M ("layout")("data_offset").As_UInt32 := 2;
      for I in Values'Range loop
         Values (I) := Float32 (I - 1);
      end loop;
      M ("data").Set_Float32_Array (Values);
      --  (row 2, col 3) is at 2 + 1 * 4 + 2 = 8.
      Assert (As_Matrix (M, [2, 3]).As_Float32 = 8.0, "element (2, 3)");
      As_Matrix (M, [3, 4]).As_Float32 := -1.0;
      Assert (M ("data").As_Array (14).As_Float32 = -1.0, "last element written");
      begin
         As_Matrix (M, [4, 1]).As_Float32 := 0.0;
         Assert (False, "row 4 of 3 must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "exceeds the size 3 of dimension 1"),
                    Text_Of (E));
      end;
      begin
         As_Matrix (M, [1]).As_Float32 := 0.0;
         Assert (False, "one index for two dimensions must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "2 dimensions"), Text_Of (E));
      end;
      --  A MultiArray nested in a field, RCLAda's Image (100, 50, 1) style.
      declare
         Img : constant Message :=
           Init (Get_Message_Support ("std_msgs", "Int8MultiArray"));
         D   : constant Array_Ref := Img ("layout")("dim").As_Array;
      begin
         D.Resize (3);
         D (1)("size").As_UInt32 := 100;
         D (1)("stride").As_UInt32 := 5_000;
         D (2)("size").As_UInt32 := 50;
         D (2)("stride").As_UInt32 := 50;
         D (3)("size").As_UInt32 := 1;
         D (3)("stride").As_UInt32 := 1;
         Img ("data").As_Array.Resize (5_000);
         As_Matrix (Img, [100, 50, 1]).As_Int8 := 7;
         Assert (Img ("data").As_Array (5_000).As_Int8 = 7, "(100, 50, 1) is the last");
      end;
   end Matrix_Views;

   procedure Error_Texts (Unused : in out Fixture) is
      M : constant Message := Init (Get_Message_Support ("std_msgs", "Header"));
   begin
      begin
         M ("frameid").Set_String ("x");
         Assert (False, "unknown field must raise");
      exception
         when E : Field_Error =>
            Assert (Text_Of (E) = "std_msgs/msg/Header has no field ""frameid""; "
                    & "valid fields: stamp, frame_id", Text_Of (E));
      end;
      begin
         M ("frame_id").As_Float32 := 1.0;
         Assert (False, "wrong type must raise");
      exception
         when E : Field_Error =>
            Assert (Text_Of (E) = "std_msgs/msg/Header field ""frame_id"": expected "
                    & "string, requested float32; valid fields: stamp, frame_id",
                    Text_Of (E));
      end;
      begin
         M ("stamp")("secs").As_Int32 := 1;
         Assert (False, "unknown nested field must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "builtin_interfaces/msg/Time (in field ""stamp"")"
                    & " has no field ""secs""; valid fields: sec, nanosec"), Text_Of (E));
      end;
      begin
         M ("stamp").As_Array.Resize (2);
         Assert (False, "As_Array of a single field must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "expected builtin_interfaces/Time, requested an array"),
                    Text_Of (E));
      end;
      declare
         L : constant Message := Init (Get_Message_Support ("sensor_msgs", "LaserScan"));
      begin
         L ("ranges").As_Float32 := 1.0;
         Assert (False, "single access to an array must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "is float32[], an array"), Text_Of (E));
      end;
      declare
         U : Message;
      begin
         U ("x").As_Float64 := 1.0;
         Assert (False, "uninitialised message must raise");
      exception
         when E : Field_Error =>
            Assert (Contains (Text_Of (E), "uninitialised"), Text_Of (E));
      end;
   end Error_Texts;

   procedure Echo_Image (Unused : in out Fixture) is
      S : constant Message := ROSIDL.CDR_Samples.Make ("string_hi");
      L : constant Message := Init (Get_Message_Support ("sensor_msgs", "LaserScan"));
      P : constant Message := Init (Get_Message_Support ("geometry_msgs", "PoseArray"));
   begin
      Assert (Image (S) = "data: hi" & LF, Image (S));
      L ("angle_min").As_Float32 := 0.1;
      L ("angle_max").As_Float32 := 1.0E-5;
      L ("range_max").As_Float32 := 1.0E20;
      L ("ranges").Set_Float32_Array ([1.0, 2.5]);
      Assert (Image (L) =
                "header:" & LF & "  stamp:" & LF & "    sec: 0" & LF
              & "    nanosec: 0" & LF & "  frame_id: ''" & LF
              & "angle_min: 0.10000000149011612" & LF
              & "angle_max: 9.999999747378752e-06" & LF
              & "angle_increment: 0.0" & LF & "time_increment: 0.0" & LF
              & "scan_time: 0.0" & LF & "range_min: 0.0" & LF
              & "range_max: 1.0000000200408773e+20" & LF
              & "ranges:" & LF & "- 1.0" & LF & "- 2.5" & LF
              & "intensities: []" & LF, Image (L));
      P ("poses").As_Array.Resize (2);
      P ("poses").As_Array (2)("position")("x").As_Float64 := 1.0E-5;
      Assert (Image (P) =
                "header:" & LF & "  stamp:" & LF & "    sec: 0" & LF
              & "    nanosec: 0" & LF & "  frame_id: ''" & LF
              & "poses:" & LF
              & "- position:" & LF & "    x: 0.0" & LF & "    y: 0.0" & LF
              & "    z: 0.0" & LF & "  orientation:" & LF & "    x: 0.0" & LF
              & "    y: 0.0" & LF & "    z: 0.0" & LF & "    w: 1.0" & LF
              & "- position:" & LF & "    x: 1.0e-05" & LF & "    y: 0.0" & LF
              & "    z: 0.0" & LF & "  orientation:" & LF & "    x: 0.0" & LF
              & "    y: 0.0" & LF & "    z: 0.0" & LF & "    w: 1.0" & LF, Image (P));
      declare
         E : constant Message := ROSIDL.CDR_Samples.Make ("everything");
      begin
         E ("s").Set_String ("true");
         --  byte 16#AB# is shown as the character U+00AB, in UTF-8.
         Assert (Contains (Image (E), "b: true" & LF & "by: "
                           & Character'Val (16#C2#) & Character'Val (16#AB#) & LF),
                 Image (E));
         E ("s").Set_String ("caf" & Character'Val (16#C3#) & Character'Val (16#A9#));
         Assert (Contains (Image (E), LF & "s: caf" & Character'Val (16#C3#)), Image (E));
         E ("s").Set_String ("a" & ASCII.LF & "b");
         Assert (Contains (Image (E), LF & "s: ""a\nb""" & LF), Image (E));
         Assert (Contains (Image (E), "c: Z" & LF & "f32: -2.5" & LF), Image (E));
         Assert (Contains (Image (E), "u64: 18000000000000000000" & LF), Image (E));
         E ("s").Set_String ("true");
         Assert (Contains (Image (E), "s: 'true'" & LF), "quoted: " & Image (E));
      end;
      Assert (Image (L, Truncate_Length => 1) /= Image (L), "truncation");
      S ("data").Set_String ("h" & Character'Val (16#C3#) & Character'Val (16#A9#) & "llo");
      Assert (Image (S, Truncate_Length => 2)
              = "data: h" & Character'Val (16#C3#) & Character'Val (16#A9#) & "..." & LF,
              "strings cut after 2 characters: " & Image (S, Truncate_Length => 2));
      Assert (Image (S, Truncate_Length => 5) = Image (S), "not cut at its length");
      Assert (Contains (Image (L, Truncate_Length => 1), "- 1.0" & LF & "- '...'" & LF),
              Image (L, Truncate_Length => 1));
   end Echo_Image;

   ---------------------------------------------------------------------------

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("dynamic: scalar fields by name",
                                      Scalars_By_Name'Access));
      Result.Add_Test (Caller.Create ("dynamic: the spec's usage example",
                                      Spec_Example'Access));
      Result.Add_Test (Caller.Create ("dynamic: defaults and constants",
                                      Defaults_And_Constants'Access));
      Result.Add_Test (Caller.Create ("dynamic: nested references, no copy",
                                      Nested_References'Access));
      Result.Add_Test (Caller.Create ("dynamic: messages are values",
                                      Value_Semantics'Access));
      Result.Add_Test (Caller.Create ("dynamic: concurrent readers of a shared message",
                                      Concurrent_Readers'Access));
      Result.Add_Test (Caller.Create ("dynamic: arrays, resize limits",
                                      Arrays_And_Limits'Access));
      Result.Add_Test (Caller.Create ("dynamic: bulk access", Bulk_Access'Access));
      Result.Add_Test (Caller.Create ("dynamic: nan/inf defaults and constants",
                                      Non_Finite_Defaults'Access));
      Result.Add_Test (Caller.Create ("dynamic: UTF-8 wstring defaults and constants",
                                      UTF_8_WStrings'Access));
      Result.Add_Test (Caller.Create ("dynamic: NaN and infinities",
                                      Non_Finite_Floats'Access));
      Result.Add_Test (Caller.Create ("dynamic: matrix views of MultiArrays",
                                      Matrix_Views'Access));
      Result.Add_Test (Caller.Create ("dynamic: Field_Error texts", Error_Texts'Access));
      Result.Add_Test (Caller.Create ("dynamic: ros2 topic echo image",
                                      Echo_Image'Access));
      return Result;
   end Suite;

end ROSIDL.Dynamic_Tests;
