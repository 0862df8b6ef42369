--  Reading MCAP files. Open checks both magics and reads the summary
--  (schemas, channels, statistics, chunk indexes); Iterate then seeks to the
--  chunks whose time range it needs, decompresses them and yields their
--  messages in log-time order. A file without a summary is scanned record
--  by record instead; a truncated file (a recording that was killed) is
--  refused unless Open is told to recover what it can. Every defect raises
--  Format_Error with the byte offset: the reader never reads past a record
--  or the file.
--  Example:
--     R : Reader;
--     R.Open ("run.mcap");
--     R.Iterate (Print'Access);   --  Print (Msg : Message; Data : Byte_Array)
with Ada.Finalization;

private with Ada.Containers.Vectors;
private with Ada.Streams.Stream_IO;
private with Ada.Strings.Unbounded;

package RCL.MCAP.Readers is

   type Reader is new Ada.Finalization.Limited_Controlled with private;

   procedure Open
     (This : in out Reader; Path : String; Recover : Boolean := False; Label : String := "");
   --  Format_Error (with the byte offset) when Path is not MCAP, truncated
   --  or corrupt; with Recover, a truncated file is read up to its last
   --  complete record instead. Ada.IO_Exceptions.Name_Error when Path
   --  cannot be opened. Errors name the file Label (Path when ""): a
   --  temporary file decompressed from "run_0.mcap.zstd" is named so.

   function Is_Open (This : Reader) return Boolean;

   function Profile (This : Reader) return String;
   function Library (This : Reader) return String;

   function Recovered (This : Reader) return Boolean;
   --  Open read a truncated file up to its last complete record.

   function Has_Summary (This : Reader) return Boolean;
   --  The file has a summary with chunk indexes (seekable).

   function Schema_Count (This : Reader) return Natural;
   function Schema (This : Reader; Index : Positive) return Schema_Info;
   function Find_Schema (This : Reader; Id : Schema_Id) return Schema_Info;
   --  Format_Error when no schema has this id.
   function Schema_Offset (This : Reader; Id : Schema_Id) return Interfaces.Unsigned_64
     with Pre => (for some I in 1 .. This.Schema_Count => Interfaces."=" (This.Schema (I).Id, Id));
   --  Where the schema's record (its content) was read: a file offset; in a
   --  chunk, the chunk record's. For the errors about what it holds.

   function Channel_Count (This : Reader) return Natural;
   function Channel (This : Reader; Index : Positive) return Channel_Info;
   function Find_Channel (This : Reader; Id : Channel_Id) return Channel_Info;
   function Channel_Offset (This : Reader; Index : Positive) return Interfaces.Unsigned_64
     with Pre => Index <= This.Channel_Count;
   --  Where Channel (Index)'s record was read, as Schema_Offset.

   function Message_Count (This : Reader) return Interfaces.Unsigned_64;
   function Channel_Message_Count (This : Reader; Id : Channel_Id) return Interfaces.Unsigned_64;
   function Start_Time (This : Reader) return Time_Stamp;
   function End_Time (This : Reader) return Time_Stamp;
   --  Of the messages (0 when there are none).
   function Chunk_Count (This : Reader) return Natural;
   function Compression (This : Reader) return String;
   --  Of the first chunk ("" when none or uncompressed).

   type Message is record
      Channel      : Channel_Id;
      Sequence     : Interfaces.Unsigned_32;
      Log_Time     : Time_Stamp;
      Publish_Time : Time_Stamp;
      Offset       : Interfaces.Unsigned_64 := 0;
      --  Where the message record's content is in the file; in a chunk,
      --  where the chunk record is.
      In_Chunk     : Boolean := False;
      Chunk_Byte   : Interfaces.Unsigned_64 := 0;
      --  In a chunk: where the message record is in its uncompressed records.
   end record;

   function Place (Msg : Message) return String;
   --  Where Msg is, for an error about it: "byte 1234", or "byte 1234: the
   --  chunk's uncompressed byte 56".

   procedure Iterate
     (This    : in out Reader;
      Process : not null access procedure (Msg : Message; Data : Byte_Array);
      From    : Time_Stamp := 0;
      To      : Time_Stamp := Time_Stamp'Last)
     with Pre => This.Is_Open;
   --  Every message with From <= Log_Time <= To, in log-time order within
   --  each chunk and chunks in start-time order (rosbag2's order). Data is
   --  valid during the call only. Format_Error on a corrupt chunk.

   procedure Close (This : in out Reader);

   overriding procedure Finalize (This : in out Reader);

private

   use Ada.Strings.Unbounded;

   type Data_Record is record
      Offset     : Interfaces.Unsigned_64;
      --  Of a chunk record, or of a message record outside chunks.
      Start, Stop : Time_Stamp;
   end record;
   package Record_Vectors is new Ada.Containers.Vectors (Positive, Data_Record);
   package Schema_Vectors is new Ada.Containers.Vectors (Positive, Schema_Info);
   package Channel_Vectors is new Ada.Containers.Vectors (Positive, Channel_Info);
   package Offset_Vectors is new Ada.Containers.Vectors
     (Positive, Interfaces.Unsigned_64, Interfaces."=");

   type Count_Entry is record
      Id    : Channel_Id;
      Count : Interfaces.Unsigned_64;
   end record;
   package Count_Vectors is new Ada.Containers.Vectors (Positive, Count_Entry);

   type Reader is new Ada.Finalization.Limited_Controlled with record
      File          : Ada.Streams.Stream_IO.File_Type;
      Path          : Unbounded_String;
      Size          : Interfaces.Unsigned_64 := 0;
      Profile       : Unbounded_String;
      Library       : Unbounded_String;
      Recovered     : Boolean := False;
      Summary       : Boolean := False;
      Statistics    : Boolean := False;
      --  The summary has a statistics record.
      Schemas       : Schema_Vectors.Vector;
      Channels      : Channel_Vectors.Vector;
      Channel_Where : Offset_Vectors.Vector;
      --  Where each of Channels was read (file offset; in a chunk, the chunk's)
      Schema_Where  : Offset_Vectors.Vector;
      --  The same for Schemas.
      Data          : Record_Vectors.Vector;
      Counts        : Count_Vectors.Vector;
      Message_Total : Interfaces.Unsigned_64 := 0;
      First_Time    : Time_Stamp := 0;
      Last_Time     : Time_Stamp := 0;
      Compression   : Unbounded_String;
   end record;

end RCL.MCAP.Readers;
