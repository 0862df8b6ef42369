--  MCAP, the container format of ROS 2 bags (rosbag2's default storage):
--  shared types of the writer (RCL.MCAP.Writers) and the reader
--  (RCL.MCAP.Readers). A file is the magic, a Header record, a data section
--  of schemas, channels and chunks (compressed groups of messages, each
--  followed by its message indexes), Data End, a summary (schemas,
--  channels, statistics, one chunk index per chunk), summary offsets, the
--  Footer and the magic again; readers seek through the chunk indexes.
--  The ros2 profile (RCL.Bags) fills schemas with .msg text ("ros2msg")
--  and messages with CDR.
--  Example:
--     W : RCL.MCAP.Writers.Writer;
--     W.Create ("run.mcap", Profile => "ros2", Compression => RCL.MCAP.Zstd);
--     S := W.Add_Schema ("std_msgs/msg/String", "ros2msg", "string data");
--     C := W.Add_Channel ("/chatter", S, "cdr", Empty_Metadata);
--     W.Write (C, Log_Time => Now, Data => Bytes);
--     W.Close;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Streams;
with Ada.Strings.Unbounded;
with Interfaces;

package RCL.MCAP is


   Format_Error : exception;
   --  A file that is not MCAP, is truncated or corrupt. The message names
   --  the file and the byte offset: "run.mcap: byte 4242: chunk record
   --  extends past the end of the file (4100 bytes): truncated".

   subtype Byte_Array is Ada.Streams.Stream_Element_Array;

   subtype Time_Stamp is Interfaces.Unsigned_64;
   --  Nanoseconds since the Unix epoch.

   subtype Schema_Id is Interfaces.Unsigned_16;
   --  0 means "no schema".
   subtype Channel_Id is Interfaces.Unsigned_16;

   type Compression_Kind is (None, Zstd, LZ4);
   --  Chunk compression: none, Zstandard, LZ4 frames (the names MCAP uses:
   --  "", "zstd", "lz4").

   function Image (Kind : Compression_Kind) return String;
   --  "", "zstd" or "lz4", as written in the file.

   function Compression_Value (Name : String) return Compression_Kind;
   --  The inverse of Image ("none" also means None). Raises Format_Error
   --  naming the unknown compression.

   package String_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, String);
   Empty_Metadata : constant String_Maps.Map := String_Maps.Empty_Map;

   type Schema_Info is record
      Id       : Schema_Id := 0;
      Name     : Ada.Strings.Unbounded.Unbounded_String;  --  "std_msgs/msg/String"
      Encoding : Ada.Strings.Unbounded.Unbounded_String;  --  "ros2msg"
      Data     : Ada.Strings.Unbounded.Unbounded_String;  --  The definition text
   end record;

   type Channel_Info is record
      Id               : Channel_Id := 0;
      Schema           : Schema_Id := 0;
      Topic            : Ada.Strings.Unbounded.Unbounded_String;
      Message_Encoding : Ada.Strings.Unbounded.Unbounded_String;  --  "cdr"
      Metadata         : String_Maps.Map;
   end record;

   Magic : constant Byte_Array := [16#89#, 16#4D#, 16#43#, 16#41#, 16#50#, 16#30#, 16#0D#, 16#0A#];
   --  Opens and closes every MCAP file ("\x89MCAP0\r\n").

   function CRC32
     (Data : Byte_Array; Previous : Interfaces.Unsigned_32 := 0) return Interfaces.Unsigned_32;
   --  The CRC-32 MCAP uses (zlib's, ISO-HDLC), continuing Previous:
   --  CRC32 (B, CRC32 (A)) = CRC32 (A & B).

private

   --  The record opcodes of the MCAP format (version 0), for the reader
   --  and the writer.
   Op_Header         : constant := 16#01#;
   Op_Footer         : constant := 16#02#;
   Op_Schema         : constant := 16#03#;
   Op_Channel        : constant := 16#04#;
   Op_Message        : constant := 16#05#;
   Op_Chunk          : constant := 16#06#;
   Op_Message_Index  : constant := 16#07#;
   Op_Chunk_Index    : constant := 16#08#;
   Op_Statistics     : constant := 16#0B#;
   Op_Summary_Offset : constant := 16#0E#;
   Op_Data_End       : constant := 16#0F#;

end RCL.MCAP;
