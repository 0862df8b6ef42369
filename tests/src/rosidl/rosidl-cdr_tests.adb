with Ada.Exceptions;
with AUnit.Assertions;
with Ada.Streams;
with ROSIDL.CDR; use ROSIDL.CDR;
with ROSIDL.CDR_Samples;
with ROSIDL.CDR_Vectors;
with ROSIDL.Definitions;
with ROSIDL.Dynamic_Tests;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Suite_Support; use Suite_Support;

package body ROSIDL.CDR_Tests is

   use Ada.Streams;
   package Samples renames ROSIDL.CDR_Samples;
   package Vectors renames ROSIDL.CDR_Vectors;

   use AUnit.Assertions;
   use ROSIDL.Definitions;
   use ROSIDL.Dynamic;
   use ROSIDL.Typesupport;
   use type UInt64;

   function Message_Of (E : Ada.Exceptions.Exception_Occurrence) return String
     renames Ada.Exceptions.Exception_Message;

   --  A deterministic generator (xorshift64*), identical on every platform.
   State : UInt64 := 16#9E37_79B9_7F4A_7C15#;

   function Next return UInt64 is
      use Standard.Interfaces;
   begin
      State := State xor Shift_Right (State, 12);
      State := State xor Shift_Left (State, 25);
      State := State xor Shift_Right (State, 27);
      return State * 16#2545_F491_4F6C_DD1D#;
   end Next;

   function Below (N : Positive) return Natural is
     (Natural (Next mod UInt64 (N)));

   ---------------------------------------------------------------------------
   --  Byte-exact vectors
   ---------------------------------------------------------------------------

   procedure Vectors_Are_Byte_Exact (Unused : in out Fixture) is
   begin
      Samples.Use_Test_Interfaces;
      Assert (Vectors.All_Vectors'Length = Natural (Samples.Names.Length),
              "one vector per sample");
      for V of Vectors.All_Vectors loop
         declare
            Name     : constant String := V.Name.all;
            Expected : constant Stream_Element_Array := Samples.From_Hex (V.Hex.all);
            Actual   : constant Stream_Element_Array := Samples.Encode_Sample (Name);
            Msg      : constant Message := Samples.Make (Name);
            Back     : Message := Init (Support (Msg));
            Header   : Request_Header;
         begin
            Assert (Samples.Hex (Actual) = V.Hex.all,
                    Name & ": encoded " & Samples.Hex (Actual) & ", expected "
                    & V.Hex.all);
            Assert (Expected'Length mod 4 = 0, Name & ": padded to 4");
            Assert (Encoded_Size (Msg, Samples.Is_Request (Name)) = Expected'Length,
                    Name & ": Encoded_Size");
            if Samples.Is_Request (Name) then
               Decode (Expected, Back, Header);
               Assert (Header = Samples.Test_Header, Name & ": request header");
            else
               Decode (Expected, Back);
            end if;
            Assert (Back = Msg, Name & ": decodes to the sample");
         end;
      end loop;
   end Vectors_Are_Byte_Exact;

   procedure Hand_Checked_Vectors (Unused : in out Fixture) is
   begin
      --  std_msgs/String "hi": header | length 3 | 'h' 'i' NUL | pad.
      Assert (Samples.Hex (Samples.Encode_Sample ("string_hi"))
              = "00010000" & "03000000" & "686900" & "00", "String hi LE");
      Assert (Samples.Hex (Samples.Encode_Sample ("string_hi", Big_Endian))
              = "00000000" & "00000003" & "686900" & "00", "String hi BE");
      --  std_msgs/Header: sec 1_700_000_000 = 16#6553_F100#, nanosec
      --  123_456_789 = 16#075B_CD15#, frame_id "base_link" (10 with NUL),
      --  padded to 4.
      Assert (Samples.Hex (Samples.Encode_Sample ("header", Big_Endian))
              = "00000000" & "6553f100" & "075bcd15" & "0000000a"
                & "626173655f6c696e6b00" & "0000", "Header BE");
      --  AddTwoInts request: header | guid | seq | a | b = 36 bytes.
      Assert (Samples.Hex (Samples.Encode_Sample ("add_two_ints_request"))
              = "00010000" & "0807060504030201" & "2a00000000000000"
                & "0200000000000000" & "0300000000000000", "AddTwoInts LE");
      --  wstrings (no Python peer): head 1 | pad 3 | w: 3 chars 'h' U+E9
      --  U+1F600 | bw: 3 chars "abc" | ws: 2 elements "" and "z".
      Assert (Samples.Hex (Samples.Encode_Sample ("wstrings"))
              = "00010000" & "01000000" & "03000000" & "68000000e900000000f60100"
                & "03000000" & "610000006200000063000000" & "02000000"
                & "00000000" & "01000000" & "7a000000", "WStrings LE");
   end Hand_Checked_Vectors;

   procedure Both_Byte_Orders_Round_Trip (Unused : in out Fixture) is
   begin
      for Name of Samples.Names loop
         for Order in Byte_Order loop
            declare
               Msg    : constant Message := Samples.Make (Name);
               Data   : constant Stream_Element_Array :=
                 Samples.Encode_Sample (Name, Order);
               Back   : Message := Init (Support (Msg));
               Header : Request_Header;
            begin
               Assert (Byte_Order_Of (Data) = Order, Name & ": header order");
               if Samples.Is_Request (Name) then
                  Decode (Data, Back, Header);
                  Assert (Header = Samples.Test_Header, Name & ": header");
               else
                  Decode (Data, Back);
               end if;
               Assert (Back = Msg, Name & " " & Order'Image & ": round trip");
            end;
         end loop;
      end loop;
   end Both_Byte_Orders_Round_Trip;

   procedure Caller_Buffers (Unused : in out Fixture) is
      Msg    : constant Message := Samples.Make ("laser_scan");
      Size   : constant Stream_Element_Count := Encoded_Size (Msg);
      Buffer : Stream_Element_Array (101 .. 100 + Size + 10) := [others => 16#EE#];
      Last   : Stream_Element_Offset;
      Small  : Stream_Element_Array (1 .. Size - 1);
   begin
      Encode (Msg, Buffer, Last);
      Assert (Last = 100 + Size, "Last");
      Assert (Buffer (Last + 1) = 16#EE#, "nothing written after Last");
      Assert (Buffer (101 .. Last) = Encode (Msg), "same bytes as the function");
      Assert (Decode (Support (Msg), Buffer (101 .. Last)) = Msg,
              "decode from a slice not starting at 1");
      begin
         Encode (Msg, Small, Last);
         Assert (False, "a too small buffer must raise Encode_Error");
      exception
         when E : Encode_Error =>
            Assert (Contains (Message_Of (E), "buffer of"), Message_Of (E));
      end;
   end Caller_Buffers;

   procedure Lenient_And_Long_Values (Unused : in out Fixture) is
      E : Stream_Element_Array := Samples.Encode_Sample ("everything");
      M : Message := Samples.Make ("everything");
      W : constant Message := Samples.Make ("wstrings");
      Long : Wide_Wide_String (1 .. 1_000);
   begin
      --  bool is read as "non-zero" (offset 4 is everything.b).
      for Value of Stream_Element_Array'[2, 16#FF#, 0] loop
         E (E'First + 4) := Value;
         Decode (E, M);
         Assert (M ("b").As_Bool = (Value /= 0), "bool from" & Value'Image);
         Assert (Encode (M) (E'First + 4) = (if Value /= 0 then 1 else 0),
                 "bool re-encoded as 0 or 1");
      end loop;
      --  wstrings longer than the decoder's chunk, all planes.
      for I in Long'Range loop
         Long (I) := Wide_Wide_Character'Val ((I * 7_919) mod 16#11_0000#);
      end loop;
      W ("ws").As_Array.Resize (3);
      W ("ws").As_Array (3).Set_WString (Long);
      declare
         Back : constant Message := Decode (Support (W), Encode (W, Big_Endian));
      begin
         Assert (Back ("ws").As_Array (3).Get_WString = Long, "long wstring");
         Assert (Back = W, "wstrings round trip");
      end;
   end Lenient_And_Long_Values;

   ---------------------------------------------------------------------------
   --  Error reports
   ---------------------------------------------------------------------------

   procedure Encode_Errors_Name_The_Field (Unused : in out Fixture) is
      M : constant Message := Samples.Make ("everything");
      A : constant Message := Samples.Make ("arrays");
   begin
      M ("bs").Set_String ("eleven char");
      begin
         declare
            Unused_Data : constant Stream_Element_Array := Encode (M);
         begin
            Assert (False, "string<=10 holding 11 characters must not encode");
         end;
      exception
         when E : Encode_Error =>
            Assert (Contains (Message_Of (E), "cdr_test_msgs/msg/Everything: bs:")
                    and then Contains (Message_Of (E), "bound 10"), Message_Of (E));
      end;
      A ("bounded_strings").As_Array (2).Set_String ("too long!");
      begin
         declare
            Unused_Data : constant Stream_Element_Array := Encode (A);
         begin
            Assert (False, "string<=8 element of 9 characters must not encode");
         end;
      exception
         when E : Encode_Error =>
            Assert (Contains (Message_Of (E), ": bounded_strings[1]:"), Message_Of (E));
      end;
   end Encode_Errors_Name_The_Field;

   procedure Expect_Decode_Error
     (Sample : String; Data : Stream_Element_Array; Parts : String_Vectors.Vector)
   is
      M : Message := Samples.Make (Sample);
   begin
      Decode (Data, M);
      Assert (False, Sample & ": expected Decode_Error containing " & Parts (1));
   exception
      when E : Decode_Error =>
         for P of Parts loop
            Assert (Contains (Message_Of (E), P),
                    Sample & ": """ & Message_Of (E) & """ lacks """ & P & """");
         end loop;
   end Expect_Decode_Error;

   procedure Decode_Errors_Name_Path_And_Offset (Unused : in out Fixture) is
      function Vector (Name : String) return Stream_Element_Array is
        (Samples.Encode_Sample (Name));
      Laser : constant Stream_Element_Array := Vector ("laser_scan");
   begin
      Expect_Decode_Error ("string_hi", Samples.From_Hex ("0001"),
                           ["encapsulation header", "byte offset 0"]);
      Expect_Decode_Error ("string_hi", Samples.From_Hex ("000200000300000068690000"),
                           ["unknown encapsulation", "byte offset 0"]);
      Expect_Decode_Error ("string_hi", Samples.From_Hex ("000100000300000068697800"),
                           ["std_msgs/msg/String: data:", "NUL", "byte offset 10"]);
      Expect_Decode_Error ("string_hi", Samples.From_Hex ("0001000000000000"),
                           ["data:", "length 0", "byte offset 4"]);
      Expect_Decode_Error ("string_hi", Samples.From_Hex ("00010000ffffffff68690000"),
                           ["data:", "string length 4294967295", "byte offset 4"]);
      --  LaserScan cut inside header.frame_id, then inside ranges (whose
      --  count is checked against the remaining bytes before anything).
      Expect_Decode_Error ("laser_scan", Laser (1 .. 20),
                           ["sensor_msgs/msg/LaserScan: header.frame_id:",
                            "byte offset 12"]);
      Expect_Decode_Error ("laser_scan", Laser (1 .. 70),
                           ["ranges:", "sequence count 13 cannot fit in the 14",
                            "byte offset 52"]);
      --  Arrays: bounded_u8 (count at offset 52) holding 6 > 5.
      declare
         A : Stream_Element_Array := Vector ("arrays");
      begin
         A (A'First + 52) := 6;
         Expect_Decode_Error ("arrays", A, ["bounded_u8:", "bound", "byte offset 52"]);
      end;
      --  Arrays cut inside the z of its second point.
      declare
         A : constant Stream_Element_Array := Vector ("arrays");
      begin
         Expect_Decode_Error ("arrays", A (1 .. 150),
                              ["cdr_test_msgs/msg/Arrays: points[1].z: truncated: "
                               & "float64 needs 8 bytes, 2 remain at byte offset 148"]);
      end;
      --  OccupancyGrid: data count (offset 100) 16#7FFF_FFFF#.
      declare
         G : Stream_Element_Array := Vector ("occupancy_grid");
      begin
         G (G'First + 100 .. G'First + 103) := [16#FF#, 16#FF#, 16#FF#, 16#7F#];
         Expect_Decode_Error ("occupancy_grid", G,
                              ["data:", "2147483647", "cannot fit", "byte offset 100"]);
      end;
      --  Odometry cut in twist.covariance.
      declare
         O : constant Stream_Element_Array := Vector ("odometry");
      begin
         Expect_Decode_Error ("odometry", O (1 .. O'Length - 20),
                              ["twist.covariance[33]:", "truncated"]);
      end;
   end Decode_Errors_Name_Path_And_Offset;

   ---------------------------------------------------------------------------
   --  Corrupted corpus
   ---------------------------------------------------------------------------

   Decoded_OK, Rejected : Natural := 0;

   --  Decodes Data as a Template; the only exception allowed is
   --  Decode_Error (with a byte offset); a success must re-encode and
   --  decode to the same message.
   procedure Try (Template : Message; Data : Stream_Element_Array; Label : String)
   is
      M : Message := Init (Support (Template));
   begin
      Decode (Data, M);
      Decoded_OK := Decoded_OK + 1;
      declare
         Again : constant Stream_Element_Array := Encode (M);
      begin
         Assert (Decode (Support (M), Again) = M, Label & ": re-encoding differs");
      end;
   exception
      when E : Decode_Error =>
         Rejected := Rejected + 1;
         Assert (Contains (Message_Of (E), "byte offset"),
                 Label & ": no offset in " & Message_Of (E));
      when E : others =>
         Assert (False, Label & ": " & Ada.Exceptions.Exception_Information (E));
   end Try;

   procedure Check_Corpus (Template : Message; Data : Stream_Element_Array;
                           Label : String; Mutations : Natural) is
   begin
      --  Every truncation.
      for L in Stream_Element_Offset range 0 .. Data'Length - 1 loop
         Try (Template, Data (Data'First .. Data'First + L - 1),
              Label & " cut at" & L'Image);
      end loop;
      --  Random byte flips (1 to 3 bytes).
      for K in 1 .. Mutations loop
         declare
            D : Stream_Element_Array := Data;
         begin
            for Unused in 0 .. Below (3) loop
               D (D'First + Stream_Element_Offset (Below (Positive (D'Length)))) :=
                 Stream_Element (Below (256));
            end loop;
            Try (Template, D, Label & " flip" & K'Image);
         end;
      end loop;
      --  Huge and boundary values at every aligned 4-byte position.
      for P in Stream_Element_Offset range 1 .. Data'Length / 4 - 1 loop
         for Value of Stream_Element_Array'[16#FF#, 16#7F#, 16#80#, 16#10#] loop
            declare
               D : Stream_Element_Array := Data;
               F : constant Stream_Element_Offset :=
                 D'First + 4 * P;
            begin
               D (F .. F + 3) := [16#FF#, 16#FF#, 16#FF#, Value];
               Try (Template, D, Label & " huge at" & P'Image);
               D (F .. F + 3) := [Value, 16#FF#, 16#FF#, 16#FF#];
               Try (Template, D, Label & " huge (BE) at" & P'Image);
            end;
         end loop;
      end loop;
   end Check_Corpus;

   procedure Corrupted_Buffers_Are_Rejected (Unused : in out Fixture) is
   begin
      Decoded_OK := 0;
      Rejected := 0;
      for Name of Samples.Names loop
         if not Samples.Is_Request (Name) then
            for Order in Byte_Order loop
               Check_Corpus (Samples.Make (Name), Samples.Encode_Sample (Name, Order),
                             Name & " " & Order'Image, 300);
            end loop;
         end if;
      end loop;
      --  Truncations alone give more rejections than successes.
      Assert (Rejected > 5_000, "rejected only" & Rejected'Image);
      Assert (Decoded_OK > 0, "some mutations are still valid messages");
   end Corrupted_Buffers_Are_Rejected;

   procedure Request_Corpus (Unused : in out Fixture) is
      Request_Type : constant String := "example_interfaces/srv/AddTwoInts_Request";
      Data : constant Stream_Element_Array :=
        Samples.Encode_Sample ("add_two_ints_request");
      M    : Message := Samples.Make ("add_two_ints_request");
      H    : Request_Header;
   begin
      for L in Stream_Element_Offset range 0 .. Data'Length - 1 loop
         begin
            Decode (Data (1 .. L), M, H);
            Assert (False, "a cut request header/body must not decode");
         exception
            when E : Decode_Error =>
               Assert (Contains (Message_Of (E), "byte offset")
                       and then Contains (Message_Of (E), Request_Type & ": "),
                       Message_Of (E));
         end;
      end loop;
      --  The header alone (a client reads it first: whose reply is it?).
      H := Request_Header_Of (Data (1 .. 20), Request_Type);
      Assert (H = Samples.Test_Header, "header read alone");
      for L in Stream_Element_Offset range 0 .. 19 loop
         begin
            H := Request_Header_Of (Data (1 .. L), Request_Type);
            Assert (False, "a cut request header must not be read");
         exception
            when E : Decode_Error =>
               Assert (Contains (Message_Of (E), Request_Type & ": ")
                       and then Contains
                         (Message_Of (E), "at byte offset"
                          & (if L < 4 then " 0" elsif L < 12 then " 4" else " 12")),
                       Message_Of (E));
         end;
      end loop;
      --  An unknown encapsulation, as any decoder of a type says it.
      declare
         Bad : Stream_Element_Array := Data;
      begin
         Bad (2) := 7;
         Decode (Bad, M, H);
         Assert (False, "encapsulation 0, 7 was accepted");
      exception
         when E : Decode_Error =>
            Assert (Contains (Message_Of (E), Request_Type & ": unknown encapsulation identifier")
                    and then Contains (Message_Of (E), "at byte offset 0"), Message_Of (E));
      end;
   end Request_Corpus;

   ---------------------------------------------------------------------------
   --  Random round trips of every bundled message type
   ---------------------------------------------------------------------------

   Cases_Per_Type : constant := 12;

   procedure Round_Trip (Support : Message_Support; Types, Cases : in out Natural) is
   begin
      Types := Types + 1;
      for K in 1 .. Cases_Per_Type loop
         declare
            M     : constant Message := Samples.Random_Message (Support, State);
            Order : constant Byte_Order := (if K mod 2 = 0 then Big_Endian
                                            else Little_Endian);
            Data  : constant Stream_Element_Array := Encode (M, Order);
            Back  : constant Message := Decode (Support, Data);
         begin
            Assert (Data'Length = Encoded_Size (M), Full_Name (Support) & ": size");
            Assert (Back = M, Full_Name (Support) & ": round trip, case" & K'Image);
            Assert (Encode (Back, Order) = Data, Full_Name (Support) & ": re-encoding");
            if K = 1 then
               --  Every truncation of one random message of each type.
               for L in Stream_Element_Offset range 0 .. Data'Length - 1 loop
                  Try (M, Data (Data'First .. Data'First + L - 1),
                       Full_Name (Support) & " cut at" & L'Image);
               end loop;
            end if;
            Cases := Cases + 1;
         end;
      end loop;
   end Round_Trip;

   procedure Every_Bundled_Type_Round_Trips (Unused : in out Fixture) is
      Types, Cases : Natural := 0;
   begin
      for Support of Samples.All_Types loop
         Round_Trip (Support, Types, Cases);
      end loop;
      Assert (Types > 150, "only" & Types'Image & " types found");
      Assert (Cases = Types * Cases_Per_Type, "cases");
   end Every_Bundled_Type_Round_Trips;

   ---------------------------------------------------------------------------

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("cdr: byte-exact vectors of every sample",
                                      Vectors_Are_Byte_Exact'Access));
      Result.Add_Test (Caller.Create ("cdr: hand-checked vectors",
                                      Hand_Checked_Vectors'Access));
      Result.Add_Test (Caller.Create ("cdr: both byte orders round trip",
                                      Both_Byte_Orders_Round_Trip'Access));
      Result.Add_Test (Caller.Create ("cdr: encode into / decode from caller buffers",
                                      Caller_Buffers'Access));
      Result.Add_Test (Caller.Create ("cdr: bool non-zero, long wstrings",
                                      Lenient_And_Long_Values'Access));
      Result.Add_Test (Caller.Create ("cdr: encode errors name the field path",
                                      Encode_Errors_Name_The_Field'Access));
      Result.Add_Test (Caller.Create ("cdr: decode errors name path and offset",
                                      Decode_Errors_Name_Path_And_Offset'Access));
      Result.Add_Test (Caller.Create ("cdr: corrupted corpus raises only Decode_Error",
                                      Corrupted_Buffers_Are_Rejected'Access));
      Result.Add_Test (Caller.Create ("cdr: every cut request is rejected, naming its type",
                                      Request_Corpus'Access));
      Result.Add_Test (Caller.Create ("cdr: random round trip of every bundled type",
                                      Every_Bundled_Type_Round_Trips'Access));
      Result.Add_Test (ROSIDL.Dynamic_Tests.Suite);
      return Result;
   end Suite;

end ROSIDL.CDR_Tests;
