with Ada.Directories;
with Ada.Exceptions;
with Ada.Streams;
with Ada.Strings.Fixed;
with AUnit.Assertions; use AUnit.Assertions;
with GNAT.OS_Lib;
with Suite_Support; use Suite_Support;

package body RCL.Zstd.Tests is

   use Ada.Streams;

   function Sample (Length : Stream_Element_Offset) return Byte_Array is
      --  Text-like bytes (compressible, not trivially): a word list walked
      --  by a linear congruential generator.
      Words  : constant String := "robot scan pose map task goal odom laser 12.5 -0.75 ";
      Result : Byte_Array (1 .. Length);
      State  : Natural := 7;
   begin
      for I in Result'Range loop
         if I mod 6 = 1 then
            State := (State * 1_103 + 12_345) mod 65_536;
         end if;
         Result (I) := Character'Pos (Words (Words'First + (State + Natural (I mod 6))
                                             mod Words'Length));
      end loop;
      return Result;
   end Sample;

   function Folder return String is
     ("/tmp/rclada-zstd-test-" & Ada.Strings.Fixed.Trim
        (Integer'Image (GNAT.OS_Lib.Pid_To_Integer (GNAT.OS_Lib.Current_Process_Id)),
         Ada.Strings.Left));
   --  One per process.

   function Expand (Data : Byte_Array) return Byte_Array is
      --  Decompress's result, copied out.
      D      : Decompressor;
      Length : Stream_Element_Offset := 0;
      Copy   : Byte_Array (1 .. 4 * Data'Length + 2_000_000);
      procedure Keep (Plain : Byte_Array) is
      begin
         Length := Plain'Length;
         Copy (1 .. Length) := Plain;
      end Keep;
   begin
      D.Decompress (Data, Keep'Access);
      return Copy (1 .. Length);
   end Expand;

   function Error_Of (Data : Byte_Array) return String is
   begin
      declare
         Ignored : constant Byte_Array := Expand (Data);
      begin
         return "(no error)";
      end;
   exception
      when E : Zstd_Error =>
         return Ada.Exceptions.Exception_Message (E);
   end Error_Of;

   procedure Files_Round_Trip (Unused : in out Fixture) is
      Dir   : constant String := Folder;
      Plain : constant Byte_Array := Sample (700_000);
   begin
      Ada.Directories.Create_Path (Dir);
      Write_All (Dir & "/plain", Plain);
      Compress_File (Dir & "/plain", Dir & "/packed.zst");
      Decompress_File (Dir & "/packed.zst", Dir & "/back");
      declare
         Packed : constant Byte_Array := Read_All (Dir & "/packed.zst");
      begin
         Assert (Starts_Frame (Packed), "a zstd frame");
         Assert (Packed'Length < Plain'Length / 2,
                 "compressed to" & Packed'Length'Image & " bytes");
         Assert (Read_All (Dir & "/back") = Plain, "the file back");
         --  Compress_File streams: the frame does not record its size, so
         --  Decompress grows its buffer (65536 bytes first) to 700000.
         Assert (Expand (Packed) = Plain, "the same frame as a message");
         --  Truncated: the file's length, and where its frame began.
         Write_All (Dir & "/cut.zst", Packed (1 .. Packed'Length - 10));
         begin
            Decompress_File (Dir & "/cut.zst", Dir & "/back", Label => "cut.zst");
            Assert (False, "a truncated file was read");
         exception
            when E : Zstd_Error =>
               Assert (Ada.Exceptions.Exception_Message (E) = "cut.zst: byte"
                       & Stream_Element_Offset'Image (Packed'Length - 10)
                       & ": truncated zstd frame (from byte 0)",
                       Ada.Exceptions.Exception_Message (E));
         end;
         declare
            function Always return Boolean is (True);
         begin
            Decompress_File (Dir & "/packed.zst", Dir & "/back", Stop => Always'Access);
            Assert (False, "not stopped");
         exception
            when E : Interrupted =>
               Assert (Contains (Ada.Exceptions.Exception_Message (E),
                                 "byte 0: decompression stopped"),
                       Ada.Exceptions.Exception_Message (E));
         end;
      end;
      Ada.Directories.Delete_Tree (Dir);
   exception
      when others =>
         if Ada.Directories.Exists (Dir) then
            Ada.Directories.Delete_Tree (Dir);
         end if;
         raise;
   end Files_Round_Trip;

   procedure Messages (Unused : in out Fixture) is
      C     : Compressor;
      One   : constant Byte_Array := Sample (100);
      Large : constant Byte_Array := Sample (300_000);
      Frame_One, Frame_Large : Byte_Array (1 .. 400_000);
      Last_One, Last_Large   : Stream_Element_Offset := 0;
      procedure Keep_One (Frame : Byte_Array) is
      begin
         Last_One := Frame'Length;
         Frame_One (1 .. Last_One) := Frame;
      end Keep_One;
      procedure Keep_Large (Frame : Byte_Array) is
      begin
         Last_Large := Frame'Length;
         Frame_Large (1 .. Last_Large) := Frame;
      end Keep_Large;
   begin
      C.Compress (One, Keep_One'Access);
      C.Compress (Large, Keep_Large'Access);
      Assert (Expand (Frame_One (1 .. Last_One)) = One, "a small message");
      Assert (Expand (Frame_Large (1 .. Last_Large)) = Large, "a large message");
      Assert (Expand (Frame_One (1 .. Last_One) & Frame_Large (1 .. Last_Large)) = One & Large,
              "two frames one after the other");
      Assert (Error_Of (Frame_One (1 .. Last_One - 1)) = "byte"
              & Stream_Element_Offset'Image (Last_One - 1)
              & ": truncated zstd frame (from byte 0)",
              Error_Of (Frame_One (1 .. Last_One - 1)));
      Assert (Error_Of (Frame_One (1 .. Last_One) & Frame_One (1 .. 6)) = "byte"
              & Stream_Element_Offset'Image (Last_One + 6)
              & ": truncated zstd frame (from byte" & Stream_Element_Offset'Image (Last_One)
              & ")", Error_Of (Frame_One (1 .. Last_One) & Frame_One (1 .. 6)));
      Assert (Error_Of (Frame_One (1 .. Last_One) & [1 .. 8 => 16#41#]) = "byte"
              & Stream_Element_Offset'Image (Last_One) & ": zstd: Unknown frame descriptor",
              Error_Of (Frame_One (1 .. Last_One) & [1 .. 8 => 16#41#]));
      Assert (Error_Of ([1 .. 0 => 0]) = "byte 0: empty: no zstd frame",
              Error_Of ([1 .. 0 => 0]));
   end Messages;

   procedure Buffers (Unused : in out Fixture) is
      --  Compress_Into / Decompress_Into, as MCAP chunks use them.
      Plain  : constant Byte_Array := Sample (50_000);
      Packed : Byte_Array (11 .. 10 + Compress_Bound (Plain'Length));
      Last   : constant Stream_Element_Offset := Compress_Into (Plain, Packed);
      Back   : Byte_Array (1 .. Plain'Length + 10);

      function Message_Of (Data : Byte_Array; Room : Stream_Element_Offset) return String is
         Into : Byte_Array (1 .. Room);
      begin
         return "(no error:" & Decompress_Into (Data, Into)'Image & " bytes)";
      exception
         when E : Zstd_Error =>
            return Ada.Exceptions.Exception_Message (E);
      end Message_Of;
   begin
      Assert (Starts_Frame (Packed (11 .. Last)) and then Last - 10 < Plain'Length / 2,
              "one frame of" & Stream_Element_Offset'Image (Last - 10) & " bytes");
      Assert (Decompress_Into (Packed (11 .. Last), Back) = Plain'Length
              and then Back (1 .. Plain'Length) = Plain, "the data back (shorter than Into)");
      Assert (Expand (Packed (11 .. Last)) = Plain, "the frame as a message");
      Assert (Message_Of (Packed (11 .. Last), Plain'Length - 1)
              = "zstd: Destination buffer is too small",
              Message_Of (Packed (11 .. Last), Plain'Length - 1));
      Assert (Message_Of ([1 .. 16 => 16#41#], 100) = "zstd: Unknown frame descriptor",
              Message_Of ([1 .. 16 => 16#41#], 100));
   end Buffers;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("zstd: files round trip, truncated, stopped",
                                      Files_Round_Trip'Access));
      Result.Add_Test (Caller.Create ("zstd: messages, concatenated frames, errors",
                                      Messages'Access));
      Result.Add_Test (Caller.Create ("zstd: one shot into caller's buffers",
                                      Buffers'Access));
      return Result;
   end Suite;

end RCL.Zstd.Tests;
