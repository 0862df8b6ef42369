with Ada.Unchecked_Deallocation;
with RCL.MCAP.Compression;

package body RCL.MCAP.Writers is

   use Ada.Exceptions;
   use Ada.Streams;
   use Interfaces;

   procedure Emit (This : in out Writer; Data : Byte_Array) is
   begin
      Stream_IO.Write (This.File, Data);
      This.Position := This.Position + Unsigned_64 (Data'Length);
   end Emit;

   procedure Emit (This : in out Writer; B : Buffers.Buffer) is
   begin
      if B.Length > 0 then
         Emit (This, B.Data (1 .. B.Length));
      end if;
   end Emit;

   procedure Wait_Finished (This : in out Writer);
   --  Background: waits until the Finisher is idle and raises its error,
   --  if any. Then the writer may touch the file again.

   procedure Begin_Record (B : in out Buffers.Buffer; Opcode : Unsigned_8;
                           Length_At : out Stream_Element_Offset) is
   begin
      B.Put_U8 (Opcode);
      Length_At := B.Length + 1;
      B.Put_U64 (0);
   end Begin_Record;

   procedure End_Record (B : in out Buffers.Buffer; Length_At : Stream_Element_Offset) is
   begin
      B.Patch_U64 (Length_At, Unsigned_64 (B.Length - (Length_At + 7)));
   end End_Record;

   ------------
   -- Create --
   ------------

   procedure Create
     (This        : in out Writer;
      Path        : String;
      Profile     : String := "ros2";
      Library     : String := "rclada";
      Compression : Compression_Kind := Zstd;
      Chunk_Size  : Positive := Default_Chunk_Size;
      Background  : Boolean := False)
   is
      At_Length : Stream_Element_Offset;
   begin
      Stream_IO.Create (This.File, Stream_IO.Out_File, Path);
      This.Path := To_Unbounded_String (Path);
      This.Position := 0;
      This.Compression := Compression;
      This.Chunk_Size := Chunk_Size;
      This.Chunk.Clear;
      This.Chunk.Reserve (Stream_Element_Offset (Chunk_Size) + 64 * 1024);
      This.Chunk_Start := Time_Stamp'Last;
      This.Chunk_End := 0;
      This.Chunk_Messages := 0;
      This.Channels.Clear;
      This.Schema_Count := 0;
      This.Message_Total := 0;
      This.First_Time := Time_Stamp'Last;
      This.Last_Time := 0;
      This.Chunk_Count := 0;
      This.Schema_Records.Clear;
      This.Channel_Records.Clear;
      This.Chunk_Indexes.Clear;
      Emit (This, Magic);
      This.Scratch.Clear;
      Begin_Record (This.Scratch, Op_Header, At_Length);
      This.Scratch.Put_String (Profile);
      This.Scratch.Put_String (Library);
      End_Record (This.Scratch, At_Length);
      Emit (This, This.Scratch);
      This.Jobs.Set_Written (This.Position);
      if Background and then This.Worker = null then
         This.Worker := new Finisher (This'Unchecked_Access);
      end if;
   end Create;

   function Is_Open (This : Writer) return Boolean is (Stream_IO.Is_Open (This.File));

   ----------------
   -- Add_Schema --
   ----------------

   function Add_Schema
     (This : in out Writer; Name, Encoding, Data : String) return Schema_Id
   is
      At_Length : Stream_Element_Offset;
      Start     : constant Stream_Element_Offset := This.Schema_Records.Length;
   begin
      Wait_Finished (This);
      This.Schema_Count := This.Schema_Count + 1;
      Begin_Record (This.Schema_Records, Op_Schema, At_Length);
      This.Schema_Records.Put_U16 (This.Schema_Count);
      This.Schema_Records.Put_String (Name);
      This.Schema_Records.Put_String (Encoding);
      This.Schema_Records.Put_String (Data);  --  uint32 length + bytes, as a string
      End_Record (This.Schema_Records, At_Length);
      Emit (This, This.Schema_Records.Data (Start + 1 .. This.Schema_Records.Length));
      This.Jobs.Set_Written (This.Position);
      return This.Schema_Count;
   end Add_Schema;

   -----------------
   -- Add_Channel --
   -----------------

   function Last_Schema (This : Writer) return Schema_Id is (This.Schema_Count);

   function Add_Channel
     (This             : in out Writer;
      Topic            : String;
      Schema           : Schema_Id;
      Message_Encoding : String;
      Metadata         : String_Maps.Map) return Channel_Id
   is
      At_Length : Stream_Element_Offset;
      Start     : constant Stream_Element_Offset := This.Channel_Records.Length;
      Id        : constant Channel_Id := Channel_Id (Natural (This.Channels.Length) + 1);
      New_State : Channel_State;
   begin
      Wait_Finished (This);
      This.Channels.Append (New_State);
      Begin_Record (This.Channel_Records, Op_Channel, At_Length);
      This.Channel_Records.Put_U16 (Id);
      This.Channel_Records.Put_U16 (Schema);
      This.Channel_Records.Put_String (Topic);
      This.Channel_Records.Put_String (Message_Encoding);
      This.Channel_Records.Put_Map (Metadata);
      End_Record (This.Channel_Records, At_Length);
      Emit (This, This.Channel_Records.Data (Start + 1 .. This.Channel_Records.Length));
      This.Jobs.Set_Written (This.Position);
      return Id;
   end Add_Channel;

   ----------------
   -- Finish_Job --
   ----------------

   --  Writes the chunk in the Job fields: its record (CRC'd, compressed),
   --  its message indexes, and its chunk index kept for the summary.
   procedure Finish_Job (This : in out Writer) is
      Chunk_Start_Offset : constant Unsigned_64 := This.Position;
      Uncompressed       : Byte_Array renames This.Job_Chunk.Data (1 .. This.Job_Chunk.Length);
      CRC                : constant Unsigned_32 := CRC32 (Uncompressed);
      Name               : constant String := Image (This.Compression);
      Compressed_Last    : Stream_Element_Offset;
      Head               : Buffers.Buffer renames This.Scratch;
      At_Length          : Stream_Element_Offset;
      Chunk_Length       : Unsigned_64;
      Index_Start        : Unsigned_64;
      Offsets            : Buffers.Buffer;
      Offsets_Count      : Unsigned_32 := 0;
   begin
      if This.Compression /= None then
         This.Compressed.Clear;
         This.Compressed.Reserve (Compression.Bound (This.Compression, Uncompressed'Length));
         Compressed_Last := Compression.Compress
           (This.Compression, Uncompressed, This.Compressed.Data.all);
      else
         Compressed_Last := Uncompressed'Length;
      end if;
      --  The chunk record: its fixed fields, then the records.
      Head.Clear;
      Begin_Record (Head, Op_Chunk, At_Length);
      Head.Put_U64 (This.Job_Start);
      Head.Put_U64 (This.Job_End);
      Head.Put_U64 (Unsigned_64 (Uncompressed'Length));
      Head.Put_U32 (CRC);
      Head.Put_String (Name);
      Head.Put_U64 (Unsigned_64 (Compressed_Last));
      Head.Patch_U64 (At_Length, Unsigned_64 (Head.Length - 9 + Compressed_Last));
      Emit (This, Head);
      if This.Compression /= None then
         Emit (This, This.Compressed.Data (1 .. Compressed_Last));
      else
         Emit (This, Uncompressed);
      end if;
      Chunk_Length := This.Position - Chunk_Start_Offset;
      --  One message index per channel with messages in the chunk.
      Index_Start := This.Position;
      for Id in 1 .. Natural (This.Job_Indexes.Length) loop
         declare
            Index : Index_Vectors.Vector renames This.Job_Indexes (Id);
         begin
            if not Index.Is_Empty then
               Offsets.Put_U16 (Channel_Id (Id));
               Offsets.Put_U64 (This.Position);
               Offsets_Count := Offsets_Count + 1;
               Head.Clear;
               Begin_Record (Head, Op_Message_Index, At_Length);
               Head.Put_U16 (Channel_Id (Id));
               Head.Put_U32 (Unsigned_32 (Index.Length) * 16);
               for E of Index loop
                  Head.Put_U64 (E.Time);
                  Head.Put_U64 (E.Offset);
               end loop;
               End_Record (Head, At_Length);
               Emit (This, Head);
               Index.Clear;
            end if;
         end;
      end loop;
      --  Its chunk index, kept for the summary.
      declare
         B : Buffers.Buffer renames This.Chunk_Indexes;
      begin
         Begin_Record (B, Op_Chunk_Index, At_Length);
         B.Put_U64 (This.Job_Start);
         B.Put_U64 (This.Job_End);
         B.Put_U64 (Chunk_Start_Offset);
         B.Put_U64 (Chunk_Length);
         B.Put_U32 (Offsets_Count * 10);
         if Offsets.Length > 0 then
            B.Put_Bytes (Offsets.Data (1 .. Offsets.Length));
         end if;
         B.Put_U64 (This.Position - Index_Start);
         B.Put_String (Name);
         B.Put_U64 (Unsigned_64 (Compressed_Last));
         B.Put_U64 (Unsigned_64 (Uncompressed'Length));
         End_Record (B, At_Length);
      end;
      This.Chunk_Count := This.Chunk_Count + 1;
      This.Job_Chunk.Clear;
   end Finish_Job;

   --------------
   -- Finisher --
   --------------

   task body Finisher is
   begin
      loop
         select
            accept Start;
         or
            accept Quit;
            exit;
         or
            terminate;
         end select;
         begin
            Finish_Job (Owner.all);
            Owner.Jobs.Done (Owner.Position, Null_Occurrence);
         exception
            when E : others =>
               Owner.Jobs.Done (Owner.Position, E);
         end;
      end loop;
   end Finisher;

   protected body Handoff is

      procedure Submit (Length : Unsigned_64) is
      begin
         Queued := Length;
         Busy := True;
      end Submit;

      procedure Done (Position : Unsigned_64; Error : Exception_Occurrence) is
      begin
         Written := Position;
         Queued := 0;
         if Exception_Identity (Error) /= Null_Id then
            Save_Occurrence (Failure, Error);
         end if;
         Busy := False;
      end Done;

      entry Wait_Idle when not Busy is
      begin
         null;
      end Wait_Idle;

      procedure Take_Error (Error : out Exception_Occurrence) is
      begin
         Save_Occurrence (Error, Failure);
         Save_Occurrence (Failure, Null_Occurrence);
      end Take_Error;

      function Bytes_Written return Unsigned_64 is (Written + Queued);

      procedure Set_Written (Position : Unsigned_64) is
      begin
         Written := Position;
         Queued := 0;
         Save_Occurrence (Failure, Null_Occurrence);
      end Set_Written;

   end Handoff;

   procedure Wait_Finished (This : in out Writer) is
      Error : Exception_Occurrence;
   begin
      if This.Worker /= null then
         This.Jobs.Wait_Idle;
         This.Jobs.Take_Error (Error);
         Reraise_Occurrence (Error);  --  Nothing for Null_Occurrence.
      end if;
   end Wait_Finished;

   procedure Stop_Worker (This : in out Writer) is
      procedure Free is new Ada.Unchecked_Deallocation (Finisher, Finisher_Access);
   begin
      if This.Worker /= null then
         This.Jobs.Wait_Idle;
         This.Worker.Quit;
         while not This.Worker'Terminated loop
            delay 0.001;
         end loop;
         Free (This.Worker);
      end if;
   end Stop_Worker;

   -----------------
   -- Flush_Chunk --
   -----------------

   --  Hands the open chunk over as the job (no copy) and finishes it, in
   --  the Finisher when Background.
   procedure Flush_Chunk (This : in out Writer) is
   begin
      if This.Chunk_Messages = 0 then
         return;
      end if;
      Wait_Finished (This);
      Buffers.Swap (This.Chunk, This.Job_Chunk);
      This.Chunk.Clear;
      This.Job_Start := This.Chunk_Start;
      This.Job_End := This.Chunk_End;
      if Natural (This.Job_Indexes.Length) < Natural (This.Channels.Length) then
         This.Job_Indexes.Set_Length (This.Channels.Length);
      end if;
      for Id in 1 .. Natural (This.Channels.Length) loop
         declare
            Spare : Index_Vectors.Vector;
         begin
            --  Exchanged, so that both vectors keep their capacity.
            Index_Vectors.Move (Target => Spare, Source => This.Job_Indexes (Id));
            Index_Vectors.Move (Target => This.Job_Indexes (Id),
                                Source => This.Channels (Id).Index);
            Index_Vectors.Move (Target => This.Channels (Id).Index, Source => Spare);
            This.Channels (Id).Index.Clear;
         end;
      end loop;
      This.Chunk_Messages := 0;
      This.Chunk_Start := Time_Stamp'Last;
      This.Chunk_End := 0;
      if This.Worker /= null then
         This.Jobs.Submit (Unsigned_64 (This.Job_Chunk.Length));
         This.Worker.Start;
      else
         Finish_Job (This);
      end if;
   end Flush_Chunk;

   -----------
   -- Write --
   -----------

   procedure Write
     (This         : in out Writer;
      Channel      : Channel_Id;
      Log_Time     : Time_Stamp;
      Data         : Byte_Array;
      Publish_Time : Time_Stamp := 0;
      Sequence     : Unsigned_32 := 0)
   is
      State : Channel_State renames This.Channels (Positive (Channel));
      C     : Buffers.Buffer renames This.Chunk;
   begin
      State.Index.Append (Index_Entry'(Time => Log_Time, Offset => Unsigned_64 (C.Length)));
      C.Reserve (1 + 8 + 22 + Data'Length);
      C.Put_U8 (Op_Message);
      C.Put_U64 (22 + Unsigned_64 (Data'Length));
      C.Put_U16 (Channel);
      C.Put_U32 (Sequence);
      C.Put_U64 (Log_Time);
      C.Put_U64 (if Publish_Time = 0 then Log_Time else Publish_Time);
      C.Put_Bytes (Data);
      State.Count := State.Count + 1;
      This.Chunk_Messages := This.Chunk_Messages + 1;
      This.Message_Total := This.Message_Total + 1;
      This.Chunk_Start := Time_Stamp'Min (This.Chunk_Start, Log_Time);
      This.Chunk_End := Time_Stamp'Max (This.Chunk_End, Log_Time);
      This.First_Time := Time_Stamp'Min (This.First_Time, Log_Time);
      This.Last_Time := Time_Stamp'Max (This.Last_Time, Log_Time);
      if C.Length >= Stream_Element_Offset (This.Chunk_Size) then
         Flush_Chunk (This);
      end if;
   end Write;

   function Bytes_Written (This : Writer) return Unsigned_64 is
     ((if This.Worker /= null then This.Jobs.Bytes_Written else This.Position)
      + Unsigned_64 (This.Chunk.Length));

   function Message_Count (This : Writer) return Unsigned_64 is (This.Message_Total);

   -----------
   -- Close --
   -----------

   procedure Close (This : in out Writer) is
      Summary       : Buffers.Buffer;
      At_Length     : Stream_Element_Offset;
      Summary_Start : Unsigned_64;
      Offsets_Start : Unsigned_64;

      procedure Group (Opcode : Unsigned_8; Records : Buffers.Buffer;
                       Offsets : in out Buffers.Buffer) is
         Start : constant Unsigned_64 := Summary_Start + Unsigned_64 (Summary.Length);
      begin
         if Records.Length > 0 then
            Summary.Put_Bytes (Records.Data (1 .. Records.Length));
            Offsets.Put_U8 (Op_Summary_Offset);
            Offsets.Put_U64 (17);
            Offsets.Put_U8 (Opcode);
            Offsets.Put_U64 (Start);
            Offsets.Put_U64 (Unsigned_64 (Records.Length));
         end if;
      end Group;

      Statistics : Buffers.Buffer;
      Offsets    : Buffers.Buffer;
   begin
      if not This.Is_Open then
         return;
      end if;
      begin
         Flush_Chunk (This);
         Wait_Finished (This);
      exception
         when others =>
            Stop_Worker (This);
            raise;
      end;
      Stop_Worker (This);
      This.Scratch.Clear;
      Begin_Record (This.Scratch, Op_Data_End, At_Length);
      This.Scratch.Put_U32 (0);  --  No data section CRC.
      End_Record (This.Scratch, At_Length);
      Emit (This, This.Scratch);
      Summary_Start := This.Position;
      --  Statistics.
      Begin_Record (Statistics, Op_Statistics, At_Length);
      Statistics.Put_U64 (This.Message_Total);
      Statistics.Put_U16 (This.Schema_Count);
      Statistics.Put_U32 (Unsigned_32 (This.Channels.Length));
      Statistics.Put_U32 (0);  --  attachments
      Statistics.Put_U32 (0);  --  metadata
      Statistics.Put_U32 (This.Chunk_Count);
      Statistics.Put_U64 (if This.Message_Total = 0 then 0 else This.First_Time);
      Statistics.Put_U64 (This.Last_Time);
      Statistics.Put_U32 (Unsigned_32 (This.Channels.Length) * 10);
      for Id in 1 .. Natural (This.Channels.Length) loop
         Statistics.Put_U16 (Channel_Id (Id));
         Statistics.Put_U64 (This.Channels (Id).Count);
      end loop;
      End_Record (Statistics, At_Length);
      Group (Op_Schema, This.Schema_Records, Offsets);
      Group (Op_Channel, This.Channel_Records, Offsets);
      Group (Op_Statistics, Statistics, Offsets);
      Group (Op_Chunk_Index, This.Chunk_Indexes, Offsets);
      Offsets_Start := Summary_Start + Unsigned_64 (Summary.Length);
      Summary.Put_Bytes (Offsets.Data (1 .. Offsets.Length));
      --  Footer; its CRC covers the summary up to its own CRC field.
      Summary.Put_U8 (Op_Footer);
      Summary.Put_U64 (20);
      Summary.Put_U64 (Summary_Start);
      Summary.Put_U64 (Offsets_Start);
      Summary.Put_U32 (CRC32 (Summary.Data (1 .. Summary.Length)));
      Summary.Put_Bytes (Magic);
      Emit (This, Summary);
      Stream_IO.Close (This.File);
   end Close;

   overriding procedure Finalize (This : in out Writer) is
   begin
      Close (This);
   exception
      when others =>
         begin
            Stop_Worker (This);
         exception
            when others => null;
         end;
         if This.Is_Open then
            begin
               Stream_IO.Close (This.File);
            exception
               when others => null;
            end;
         end if;
   end Finalize;

end RCL.MCAP.Writers;
