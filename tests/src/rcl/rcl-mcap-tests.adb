with Ada.Directories;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Streams;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with AUnit.Assertions; use AUnit.Assertions;
with RCL.Bags;
with RCL.MCAP.Buffers;
with RCL.MCAP.Readers;
with RCL.MCAP.Writers;
with RCL.QoS;
with Suite_Support; use Suite_Support;

package body RCL.MCAP.Tests is

   use Ada.Streams;
   use Ada.Strings.Unbounded;
   use type Interfaces.Unsigned_16;
   use type Interfaces.Unsigned_64;

   function Getpid return Integer with Import, Convention => C, External_Name => "getpid";

   function Temp (Name : String) return String is
     ("/tmp/rclada_mcap_test_" & Ada.Strings.Fixed.Trim (Getpid'Image, Ada.Strings.Left)
      & "_" & Name);

   function Payload (I : Natural) return Byte_Array is
      --  CDR-like bytes whose length and contents depend on I.
      Result : Byte_Array (1 .. Stream_Element_Offset (4 + I mod 37));
   begin
      for K in Result'Range loop
         Result (K) := Stream_Element ((I * 7 + Natural (K)) mod 256);
      end loop;
      return Result;
   end Payload;

   Base : constant Time_Stamp := 1_700_000_000_000_000_000;

   function Time_Of (I : Natural) return Time_Stamp is
     --  Increasing, except every 10th message which comes 3 ms "late".
     (Base + Time_Stamp (I) * 1_000_000 - (if I mod 10 = 9 then 3_000_000 else 0));

   procedure Write_Sample
     (Path       : String;
      Kind       : Compression_Kind;
      Count      : Natural;
      Chunk_Size : Positive;
      Background : Boolean := False;
      Late       : Natural := Natural'Last)
   is
      --  Late: after that many messages, a fourth channel is added and
      --  gets every 4th message from then on.
      W  : Writers.Writer;
      S1 : Schema_Id;
      C  : array (0 .. 2) of Channel_Id;
      C4 : Channel_Id := 0;
      M  : String_Maps.Map;
   begin
      W.Create (Path, Compression => Kind, Chunk_Size => Chunk_Size, Background => Background);
      S1 := W.Add_Schema ("std_msgs/msg/String", "ros2msg", "string data");
      M.Include ("offered_qos_profiles", "- history: 1" & ASCII.LF);
      for K in C'Range loop
         C (K) := W.Add_Channel ("/topic" & Ada.Strings.Fixed.Trim (K'Image, Ada.Strings.Left),
                                 S1, "cdr", M);
      end loop;
      for I in 0 .. Count - 1 loop
         if I = Late then
            C4 := W.Add_Channel ("/late", W.Add_Schema ("std_msgs/msg/Empty", "ros2msg", ""),
                                 "cdr", M);
         end if;
         W.Write ((if C4 /= 0 and then I mod 4 = 0 then C4 else C (I mod 3)), Time_Of (I),
                  Payload (I), Sequence => Interfaces.Unsigned_32 (I));
      end loop;
      W.Close;
   end Write_Sample;

   procedure Round_Trip (Unused : in out Fixture) is
   begin
      for Kind in Compression_Kind loop
         declare
            Path  : constant String := Temp ("round_trip.mcap");
            R     : Readers.Reader;
            Seen  : Natural := 0;
            Last  : Time_Stamp := 0;
            Chunk_Order_Ok : Boolean := True;

            procedure Check (Msg : Readers.Message; Data : Byte_Array) is
               I : constant Natural := Natural (Msg.Sequence);
            begin
               Assert (Data = Payload (I), "payload of message" & I'Image);
               Assert (Msg.Log_Time = Time_Of (I) and then Msg.Publish_Time = Time_Of (I),
                       "times of message" & I'Image);
               Assert (Natural (Msg.Channel) = 1 + I mod 3, "channel of message" & I'Image);
               if Msg.Log_Time < Last then
                  Chunk_Order_Ok := False;
               end if;
               Last := Msg.Log_Time;
               Seen := Seen + 1;
            end Check;
         begin
            Write_Sample (Path, Kind, 600, Chunk_Size => 2048);
            R.Open (Path);
            Assert (R.Profile = "ros2" and then R.Library = "rclada", "header");
            Assert (R.Has_Summary, "summary with chunk indexes");
            Assert (R.Chunk_Count > 5, "several chunks:" & R.Chunk_Count'Image);
            Assert (R.Compression = Image (Kind), "compression " & R.Compression);
            Assert (R.Message_Count = 600, "statistics: message count");
            Assert (R.Channel_Count = 3 and then R.Schema_Count = 1, "channels and schemas");
            Assert (R.Channel_Message_Count (2) = 200, "per-channel count");
            Assert (To_String (R.Find_Channel (3).Topic) = "/topic2", "channel topic");
            Assert (R.Find_Channel (1).Metadata.Element ("offered_qos_profiles")
                    = "- history: 1" & ASCII.LF, "channel metadata");
            Assert (To_String (R.Find_Schema (1).Data) = "string data", "schema data");
            R.Iterate (Check'Access);
            Assert (Seen = 600, "messages read back:" & Seen'Image);
            --  Messages within a chunk come in log-time order; the chunks
            --  overlap by the late messages only, so some step back may
            --  remain between chunks: count what a time range selects.
            pragma Unreferenced (Chunk_Order_Ok);
            Seen := 0;
            R.Iterate (Check'Access, From => Time_Of (100), To => Time_Of (199) + 3_000_000);
            Assert (Seen in 100 .. 101, "time range: " & Seen'Image);
            R.Close;
            Ada.Directories.Delete_File (Path);
         end;
      end loop;
   end Round_Trip;

   procedure Background_Writer (Unused : in out Fixture) is
   begin
      for Kind in Compression_Kind loop
         declare
            Plain : constant String := Temp ("plain.mcap");
            Tasked : constant String := Temp ("tasked.mcap");
         begin
            Write_Sample (Plain, Kind, 3000, Chunk_Size => 2048, Late => 1500);
            Write_Sample (Tasked, Kind, 3000, Chunk_Size => 2048, Background => True,
                          Late => 1500);
            declare
               A : constant Byte_Array := Read_All (Plain);
               B : constant Byte_Array := Read_All (Tasked);
            begin
               Assert (A'Length > 20_000 or else Kind /= None, "several chunks written");
               Assert (A = B, Image (Kind) & ": the background writer's file differs ("
                       & A'Length'Image & " /" & B'Length'Image & " bytes)");
            end;
            Ada.Directories.Delete_File (Plain);
            Ada.Directories.Delete_File (Tasked);
         end;
      end loop;
      --  A write error in the task comes back to the writer's caller.
      declare
         W      : Writers.Writer;
         C      : Channel_Id;
         Raised : Boolean := False;
      begin
         W.Create ("/dev/full", Compression => None, Chunk_Size => 2048, Background => True);
         C := W.Add_Channel ("/t", 0, "cdr", Empty_Metadata);
         begin
            for I in 0 .. 20_000 loop
               W.Write (C, Time_Of (I), Payload (I));
            end loop;
            W.Close;
         exception
            when Ada.IO_Exceptions.Device_Error =>
               Raised := True;
         end;
         Assert (Raised, "no error writing to /dev/full");
      end;
   end Background_Writer;

   procedure Open_And_Read (Path : String; Recover : Boolean; Count : out Natural) is
      R : Readers.Reader;
      procedure Each (Msg : Readers.Message; Data : Byte_Array) is
         pragma Unreferenced (Msg, Data);
      begin
         Count := Count + 1;
      end Each;
   begin
      Count := 0;
      R.Open (Path, Recover);
      R.Iterate (Each'Access);
   end Open_And_Read;

   function Names_Offset (Message : String) return Boolean is
     (Contains (Message, ": byte "));

   procedure Assert_Refused (Path, Fault, Part : String) is
      --  Reading Path (no recovery) must raise Format_Error with a byte
      --  offset and Part in its message. Fault: what the file has wrong.
      Count : Natural;
   begin
      Open_And_Read (Path, False, Count);
      Assert (False, Fault & " was accepted");
   exception
      when E : Format_Error =>
         Assert (Names_Offset (Ada.Exceptions.Exception_Message (E))
                 and then Contains (Ada.Exceptions.Exception_Message (E), Part),
                 Ada.Exceptions.Exception_Message (E));
   end Assert_Refused;

   procedure Truncated_Files (Unused : in out Fixture) is
      Path  : constant String := Temp ("whole.mcap");
      Cut   : constant String := Temp ("cut.mcap");
      Count : Natural;
   begin
      for Kind in Compression_Kind loop
         Write_Sample (Path, Kind, 60, Chunk_Size => 256);
         declare
            Whole : constant Byte_Array := Read_All (Path);
         begin
            for Length in 0 .. Whole'Length - 1 loop
               Write_All (Cut, Whole (1 .. Stream_Element_Offset (Length)));
               begin
                  Open_And_Read (Cut, False, Count);
                  Assert (False, "a file cut at" & Length'Image & " bytes was accepted");
               exception
                  when E : Format_Error =>
                     Assert (Names_Offset (Ada.Exceptions.Exception_Message (E)),
                             "no offset: " & Ada.Exceptions.Exception_Message (E));
               end;
               --  Recovering keeps the complete chunks (none before the header).
               if Length >= 8 + 9 + 4 + 4 + 4 + 6 then
                  Open_And_Read (Cut, True, Count);
                  Assert (Count <= 60, "recovered" & Count'Image);
               end if;
            end loop;
            Write_All (Cut, Whole (1 .. Whole'Length / 3));
            Open_And_Read (Cut, True, Count);
            Assert (Count > 0 and then Count < 60, "a third recovered:" & Count'Image);
         end;
      end loop;
      Ada.Directories.Delete_File (Path);
      Ada.Directories.Delete_File (Cut);
   end Truncated_Files;

   procedure Corrupt_Files (Unused : in out Fixture) is
      --  Every single-byte corruption is either refused with an offset or
      --  harmless (a byte no reader needs: message indexes, the data
      --  section's copies of schemas and channels): the messages read back
      --  are then exactly those written. Never wrong data, never a crash.
      Path    : constant String := Temp ("whole.mcap");
      Bad     : constant String := Temp ("bad.mcap");
      Refused : Natural := 0;

      function In_Order (I : Natural) return Time_Stamp is (Base + Time_Stamp (I) * 1_000_000);

      function Reads_Back_Exactly return Boolean is
         R    : Readers.Reader;
         Seen : Natural := 0;
         Good : Boolean := True;
         procedure Each (Msg : Readers.Message; Data : Byte_Array) is
            I : constant Natural := Natural (Msg.Sequence);
         begin
            Good := Good and then I = Seen and then Data = Payload (I)
              and then Msg.Log_Time = In_Order (I) and then Natural (Msg.Channel) = 1 + I mod 3;
            Seen := Seen + 1;
         end Each;
      begin
         R.Open (Bad);
         R.Iterate (Each'Access);
         return Good and then Seen = 40 and then R.Message_Count = 40;
      end Reads_Back_Exactly;
   begin
      --  Messages in time order here (the late ones would reorder).
      declare
         W  : Writers.Writer;
         S1 : Schema_Id;
         C  : array (0 .. 2) of Channel_Id;
      begin
         W.Create (Path, Compression => Zstd, Chunk_Size => 256);
         S1 := W.Add_Schema ("std_msgs/msg/String", "ros2msg", "string data");
         for K in C'Range loop
            C (K) := W.Add_Channel ("/t" & K'Image, S1, "cdr", Empty_Metadata);
         end loop;
         for I in 0 .. 39 loop
            W.Write (C (I mod 3), In_Order (I), Payload (I),
                     Sequence => Interfaces.Unsigned_32 (I));
         end loop;
         W.Close;
      end;
      declare
         Whole : constant Byte_Array := Read_All (Path);
         Copy  : Byte_Array := Whole;
      begin
         for I in Whole'Range loop
            Copy (I) := Whole (I) xor 16#5A#;
            Write_All (Bad, Copy);
            begin
               Assert (Reads_Back_Exactly, "byte" & I'Image & " corrupted: wrong data read");
            exception
               when E : Format_Error =>
                  Refused := Refused + 1;
                  Assert (Names_Offset (Ada.Exceptions.Exception_Message (E)),
                          "no offset: " & Ada.Exceptions.Exception_Message (E));
            end;
            Copy (I) := Whole (I);
         end loop;
         Assert (Refused > Whole'Length / 2,
                 "corruptions refused:" & Refused'Image & " of" & Whole'Length'Image);
      end;
      Ada.Directories.Delete_File (Path);
      Ada.Directories.Delete_File (Bad);
   end Corrupt_Files;

   procedure Not_MCAP (Unused : in out Fixture) is
      Path  : constant String := Temp ("text.mcap");
      Count : Natural;
   begin
      Write_All (Path, [104, 105, 10, 0, 0, 0, 0, 0, 0, 0]);  --  "hi" LF
      Open_And_Read (Path, False, Count);
      Assert (False, "a text file was accepted");
   exception
      when E : Format_Error =>
         Assert (Ada.Exceptions.Exception_Message (E) = Path
                 & ": byte 0: not an MCAP file: expected the magic 89 4D 43 41 50 30 0D 0A",
                 Ada.Exceptions.Exception_Message (E));
         Ada.Directories.Delete_File (Path);
   end Not_MCAP;

   procedure Write_Orphan_Channel (Path : String) is
      --  Path: magic, header, a channel naming schema 9 with no schema record,
      --  one message, data end, a footer without summary, magic (written by
      --  hand: the writer refuses such a channel).
      File : Buffers.Buffer;

      procedure Put_Record (Opcode : Interfaces.Unsigned_8; Fields : Buffers.Buffer) is
      begin
         File.Put_U8 (Opcode);
         File.Put_U64 (Interfaces.Unsigned_64 (Fields.Length));
         File.Put_Bytes (Fields.Data (1 .. Fields.Length));
      end Put_Record;

      Header, Channel, Message, Data_End, Footer : Buffers.Buffer;
   begin
      File.Put_Bytes (Magic);
      Header.Put_String ("ros2");
      Header.Put_String ("rclada tests");
      Put_Record (Op_Header, Header);
      Channel.Put_U16 (1);
      Channel.Put_U16 (9);
      Channel.Put_String ("/orphan");
      Channel.Put_String ("cdr");
      Channel.Put_Map (Empty_Metadata);
      Put_Record (Op_Channel, Channel);
      Message.Put_U16 (1);
      Message.Put_U32 (0);
      Message.Put_U64 (Base);
      Message.Put_U64 (Base);
      Message.Put_Bytes (Payload (0));
      Put_Record (Op_Message, Message);
      Data_End.Put_U32 (0);
      Put_Record (Op_Data_End, Data_End);
      Footer.Put_U64 (0);
      Footer.Put_U64 (0);
      Footer.Put_U32 (0);
      Put_Record (Op_Footer, Footer);
      File.Put_Bytes (Magic);
      Write_All (Path, File.Data (1 .. File.Length));
   end Write_Orphan_Channel;

   procedure Channel_Without_Schema (Unused : in out Fixture) is
      --  The writer refuses a channel naming a schema it never added (the
      --  file would be refused by every reader). A file with such a channel
      --  is refused at open, with the channel record's offset (the fuzzer
      --  found the bare "no schema has id N" of a later lookup).
      Path  : constant String := Temp ("no-schema.mcap");
   begin
      declare
         W : Writers.Writer;
         C : Channel_Id;
      begin
         W.Create (Path);
         C := W.Add_Channel ("/no_schema", 0, "cdr", Empty_Metadata);  --  0: none, allowed
         Assert (C = 1, "channel ids count from 1");
         C := W.Add_Channel ("/orphan", 9, "cdr", Empty_Metadata);
         Assert (False, "a channel naming schema 9 of none was written");
      exception
         when E : Constraint_Error =>
            Assert (Contains (Ada.Exceptions.Exception_Message (E),
                              "schema 9 was never added (schemas added so far: 0)")
                    and then Contains (Ada.Exceptions.Exception_Message (E), "/orphan"),
                    Ada.Exceptions.Exception_Message (E));
      end;
      Write_Orphan_Channel (Path);
      Assert_Refused (Path, "a channel without its schema",
                      "channel 1 (topic '/orphan') names schema 9, which no schema record "
                      & "defines");
      Ada.Directories.Delete_File (Path);
   end Channel_Without_Schema;

   procedure Message_Outside_Its_Chunk (Unused : in out Fixture) is
      --  A chunk whose start time is later than one of its messages (a
      --  corrupt header; iterating From/To would silently skip the message)
      --  is refused with the chunk's offset.
      Path  : constant String := Temp ("range.mcap");

      function Le_64 (Bytes : Byte_Array) return Interfaces.Unsigned_64 is
         Result : Interfaces.Unsigned_64 := 0;
      begin
         for B of reverse Bytes loop
            Result := Interfaces.Shift_Left (Result, 8) or Interfaces.Unsigned_64 (B);
         end loop;
         return Result;
      end Le_64;
   begin
      Write_Sample (Path, None, 20, Chunk_Size => 100_000);
      declare
         Bytes   : Byte_Array := Read_All (Path);
         At_Op   : Stream_Element_Offset := Bytes'First + 8;   --  after the magic
         Patched : Boolean := False;
      begin
         while not Patched and then At_Op + 8 <= Bytes'Last loop
            if Bytes (At_Op) = 6 then
               --  Chunk content: start time, end time, ... ; start := Base + 1.
               Bytes (At_Op + 9) := Bytes (At_Op + 9) + 1;
               Patched := True;
            else
               At_Op := At_Op + 9
                 + Stream_Element_Offset (Le_64 (Bytes (At_Op + 1 .. At_Op + 8)));
            end if;
         end loop;
         Assert (Patched, "no chunk record found");
         Write_All (Path, Bytes);
      end;
      Assert_Refused (Path, "a message before its chunk's start time", "outside the chunk's range");
      Ada.Directories.Delete_File (Path);
   end Message_Outside_Its_Chunk;

   procedure Ros2_Profile (Unused : in out Fixture) is
      Twist : constant String := RCL.Bags.Message_Definition_Text ("geometry_msgs/msg/Twist");
      Delimiter : constant String := [1 .. 80 => '='];
      Offered : constant String :=
        RCL.Bags.Offered_QoS_Text ([RCL.QoS.Sensor_Data, RCL.QoS.Default]);
      Latched_Profile : constant RCL.QoS.Profile :=
        (RCL.QoS.Default with delta Durability => RCL.QoS.Transient_Local, Depth => 1);
      Latched : constant String := RCL.Bags.Offered_QoS_Text ([Latched_Profile]);
      use type RCL.QoS.Reliability_Policy;
      use type RCL.QoS.Durability_Policy;
      use type RCL.QoS.Profile;
   begin
      Assert (Ada.Strings.Fixed.Index (Twist, "Vector3") = Twist'First
              or else Contains (Twist, "Vector3  linear")
              or else Contains (Twist, "Vector3 linear"), Twist);
      Assert (Ada.Strings.Fixed.Count (Twist, "MSG: geometry_msgs/msg/Vector3") = 1,
              "the nested type once: " & Twist);
      Assert (Contains (Twist, Delimiter & ASCII.LF & "MSG: "), Twist);
      Assert (Contains (Twist, "float64 x"), Twist);
      Assert (Ada.Strings.Fixed.Count (Offered, "- history: 1") = 2, Offered);
      Assert (Contains (Offered, "  reliability: 2"), Offered);
      Assert (RCL.Bags.Playback_QoS (Offered).Reliability = RCL.QoS.Best_Effort,
              "best effort when one publisher was");
      Assert (RCL.Bags.Playback_QoS (Offered).Durability = RCL.QoS.Volatile, "volatile");
      Assert (RCL.Bags.Playback_QoS (Latched).Durability = RCL.QoS.Transient_Local
              and then RCL.Bags.Playback_QoS (Latched).Reliability = RCL.QoS.Reliable,
              "transient local when every publisher was");
      Assert (RCL.Bags.Playback_QoS ("{not: [a list") = RCL.QoS.Default, "unreadable: default");
   end Ros2_Profile;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("mcap: round trip (none, zstd, lz4)", Round_Trip'Access));
      Result.Add_Test (Caller.Create ("mcap: every truncation refused with its offset",
                                      Truncated_Files'Access));
      Result.Add_Test (Caller.Create ("mcap: single-byte corruptions refused",
                                      Corrupt_Files'Access));
      Result.Add_Test (Caller.Create ("mcap: not an MCAP file", Not_MCAP'Access));
      Result.Add_Test (Caller.Create ("mcap: a channel naming a missing schema",
                                      Channel_Without_Schema'Access));
      Result.Add_Test (Caller.Create ("mcap: a message outside its chunk's time range",
                                      Message_Outside_Its_Chunk'Access));
      Result.Add_Test (Caller.Create ("mcap: background chunk writer, same bytes, errors",
                                      Background_Writer'Access));
      Result.Add_Test (Caller.Create ("mcap: ros2 profile schema and QoS text",
                                      Ros2_Profile'Access));
      return Result;
   end Suite;

end RCL.MCAP.Tests;
