--  Writing MCAP files: messages are gathered in chunks (compressed when
--  asked), each chunk followed by one message index per channel; Close
--  writes the summary (schemas, channels, statistics, chunk indexes) and the
--  footer so that readers can seek. Not task-safe: one task writes.
--  With Background, a task of the writer's own compresses and writes each
--  full chunk while the next one fills (Write then only copies messages).
--  Example:
--     W : Writer;
--     W.Create ("run.mcap", Profile => "ros2", Compression => Zstd);
--     S : constant Schema_Id := W.Add_Schema ("std_msgs/msg/String", "ros2msg",
--                                            "string data");
--     C : constant Channel_Id := W.Add_Channel ("/chatter", S, "cdr", Empty_Metadata);
--     W.Write (C, Log_Time => 1_700_000_000_000_000_000, Data => Cdr_Bytes);
--     W.Close;   --  also done by finalization
with Ada.Finalization;

private with Ada.Containers.Vectors;
private with Ada.Exceptions;
private with System;
private with Ada.Streams.Stream_IO;
private with Ada.Strings.Unbounded;
private with RCL.MCAP.Buffers;

package RCL.MCAP.Writers is

   use type Schema_Id;

   type Writer is new Ada.Finalization.Limited_Controlled with private;
   --  Its time ranges stay consistent (a Type_Invariant): the open chunk's
   --  range covers the chunk's messages and lies within the file's.

   Default_Chunk_Size : constant := 768 * 1024;
   --  Uncompressed bytes per chunk (rosbag2's MCAP default).

   procedure Create
     (This        : in out Writer;
      Path        : String;
      Profile     : String := "ros2";
      Library     : String := "rclada";
      Compression : Compression_Kind := Zstd;
      Chunk_Size  : Positive := Default_Chunk_Size;
      Background  : Boolean := False)
     with Pre => not This.Is_Open, Post => This.Is_Open;
   --  Creates (or replaces) Path and writes the magic and the header.
   --  Ada.IO_Exceptions.Name_Error/Use_Error when it cannot be created.
   --  Background: full chunks are CRC'd, compressed and written by a task
   --  (one chunk at a time: a Write that fills the next chunk first waits
   --  for the previous one); the file is the same byte for byte. An error
   --  of that task (disk full) is raised by the next Write, Add_Schema,
   --  Add_Channel or Close.

   function Is_Open (This : Writer) return Boolean;

   function Add_Schema
     (This : in out Writer; Name, Encoding, Data : String) return Schema_Id
     with Pre => This.Is_Open;
   --  Ids count from 1.

   function Add_Channel
     (This             : in out Writer;
      Topic            : String;
      Schema           : Schema_Id;
      Message_Encoding : String;
      Metadata         : String_Maps.Map) return Channel_Id
     with Pre => This.Is_Open
                 and then (Schema <= This.Last_Schema
                           or else raise Constraint_Error
                             with "Add_Channel: schema" & Schema'Image & " was never added "
                                  & "(schemas added so far:" & This.Last_Schema'Image
                                  & "), for topic '" & Topic & "'");
   --  Ids count from 1. Schema: one returned by Add_Schema (or 0, none): a
   --  channel naming a schema the file does not define would make every
   --  reader refuse the file.

   function Last_Schema (This : Writer) return Schema_Id;
   --  The last id Add_Schema returned (0 before any).

   procedure Write
     (This         : in out Writer;
      Channel      : Channel_Id;
      Log_Time     : Time_Stamp;
      Data         : Byte_Array;
      Publish_Time : Time_Stamp := 0;
      Sequence     : Interfaces.Unsigned_32 := 0)
     with Pre => This.Is_Open;
   --  Appends a message to the current chunk, closing the chunk when it
   --  reaches the chunk size. Publish_Time 0 means Log_Time. Constraint_Error
   --  for a channel that was not added.

   function Bytes_Written (This : Writer) return Interfaces.Unsigned_64;
   --  The file's size so far plus the open chunk's uncompressed size (for
   --  splitting bags by size); Background: plus the uncompressed size of
   --  the chunk its task is writing.

   function Message_Count (This : Writer) return Interfaces.Unsigned_64;

   procedure Close (This : in out Writer)
     with Post => not This.Is_Open;
   --  Writes the last chunk, the summary and the footer, and closes the
   --  file (and ends the Background task). Nothing when not open.

   overriding procedure Finalize (This : in out Writer);
   --  Close, errors ignored.

private

   use Ada.Strings.Unbounded;
   use type Interfaces.Unsigned_32;
   use type Interfaces.Unsigned_64;

   type Index_Entry is record
      Time, Offset : Time_Stamp;
   end record;
   package Index_Vectors is new Ada.Containers.Vectors (Positive, Index_Entry);

   type Channel_State is record
      Count : Interfaces.Unsigned_64 := 0;
      Index : Index_Vectors.Vector;
      --  The open chunk's messages of this channel.
   end record;
   package Channel_Vectors is new Ada.Containers.Vectors (Positive, Channel_State);
   package Chunk_Index_Vectors is new Ada.Containers.Vectors
     (Positive, Index_Vectors.Vector, Index_Vectors."=");

   protected type Handoff is
      procedure Submit (Length : Interfaces.Unsigned_64);
      --  The writer's Job fields hold a chunk of Length bytes that its
      --  Finisher is about to finish.
      procedure Done (Position : Interfaces.Unsigned_64;
                      Error    : Ada.Exceptions.Exception_Occurrence);
      --  The job is written (Error: Null_Occurrence, or what went wrong).
      entry Wait_Idle;
      procedure Take_Error (Error : out Ada.Exceptions.Exception_Occurrence);
      --  The error of a finished job, if any (then forgotten).
      function Bytes_Written return Interfaces.Unsigned_64;
      --  The file's size after the last finished job plus the pending
      --  chunk's size.
      procedure Set_Written (Position : Interfaces.Unsigned_64);
      --  After the writer itself wrote (no job under way, no error kept).
   private
      Busy     : Boolean := False;
      Written  : Interfaces.Unsigned_64 := 0;
      Queued   : Interfaces.Unsigned_64 := 0;
      Failure  : Ada.Exceptions.Exception_Occurrence;
   end Handoff;

   type Writer_Access is access all Writer;

   task type Finisher (Owner : not null Writer_Access)
     with Priority => System.Default_Priority
   is
      entry Start;
      --  Finishes Owner's job (then Owner.Jobs.Done).
      entry Quit;
   end Finisher;
   --  Terminates on Quit, or with its master when nobody can call it.
   type Finisher_Access is access Finisher;

   type Writer is new Ada.Finalization.Limited_Controlled with record
      File           : Ada.Streams.Stream_IO.File_Type;
      Path           : Unbounded_String;
      Position       : Interfaces.Unsigned_64 := 0;
      Compression    : Compression_Kind := Zstd;
      Chunk_Size     : Positive := Default_Chunk_Size;
      Chunk          : Buffers.Buffer;
      Chunk_Start    : Time_Stamp := Time_Stamp'Last;
      Chunk_End      : Time_Stamp := 0;
      Chunk_Messages : Natural := 0;
      Scratch        : Buffers.Buffer;
      Compressed     : Buffers.Buffer;
      Channels       : Channel_Vectors.Vector;
      Schema_Count   : Interfaces.Unsigned_16 := 0;
      Message_Total  : Interfaces.Unsigned_64 := 0;
      First_Time     : Time_Stamp := Time_Stamp'Last;
      Last_Time      : Time_Stamp := 0;
      Chunk_Count    : Interfaces.Unsigned_32 := 0;
      Schema_Records : Buffers.Buffer;
      Channel_Records : Buffers.Buffer;
      Chunk_Indexes  : Buffers.Buffer;
      --  The chunk being finished: while Background's task works on it,
      --  only that task touches these fields and File, Position, Scratch,
      --  Compressed, Chunk_Indexes and Chunk_Count.
      Job_Chunk      : Buffers.Buffer;
      Job_Indexes    : Chunk_Index_Vectors.Vector;
      Job_Start      : Time_Stamp := 0;
      Job_End        : Time_Stamp := 0;
      Jobs           : Handoff;
      Worker         : Finisher_Access;
   end record
     with Type_Invariant =>
       --  The time ranges the chunk and statistics records state: the open
       --  chunk's covers its messages and lies within the file's.
       Interfaces.Unsigned_64 (Writer.Chunk_Messages) <= Writer.Message_Total
       and then (Writer.Message_Total = 0 or else Writer.First_Time <= Writer.Last_Time)
       and then (Writer.Chunk_Messages = 0
                 or else (Writer.First_Time <= Writer.Chunk_Start
                          and then Writer.Chunk_Start <= Writer.Chunk_End
                          and then Writer.Chunk_End <= Writer.Last_Time));

end RCL.MCAP.Writers;
