with Ada.Exceptions;
with Ada.Unchecked_Deallocation;
with RCL.MCAP.Compression;

package body RCL.MCAP.Readers is

   use Ada.Streams;
   use Interfaces;

   Record_Head   : constant := 9;   --  opcode + length
   Footer_Length : constant := Record_Head + 20;
   Largest_Chunk : constant := 2 ** 30;
   --  A larger uncompressed size is taken for corruption.

   type Byte_Array_Access is access Byte_Array;
   procedure Free is new Ada.Unchecked_Deallocation (Byte_Array, Byte_Array_Access);

   function Hex (Value : Unsigned_8) return String is
      Digits_Of : constant String := "0123456789ABCDEF";
   begin
      return "0x" & Digits_Of (Natural (Value / 16) + 1) & Digits_Of (Natural (Value mod 16) + 1);
   end Hex;

   function Image (Value : Unsigned_64) return String is
      S : constant String := Value'Image;
   begin
      return S (S'First + 1 .. S'Last);
   end Image;

   procedure Fail (This : Reader; Offset : Unsigned_64; Text : String) with No_Return;
   procedure Fail (This : Reader; Offset : Unsigned_64; Text : String) is
   begin
      raise Format_Error with To_String (This.Path) & ": byte " & Image (Offset) & ": " & Text;
   end Fail;

   --  Reading the file ---------------------------------------------------------

   procedure Read_At
     (This : in out Reader; Offset : Unsigned_64; Into : out Byte_Array; What : String) is
   begin
      if Offset > This.Size or else Unsigned_64 (Into'Length) > This.Size - Offset then
         Fail (This, Offset, What & " of " & Image (Unsigned_64 (Into'Length))
               & " bytes extends past the end of the file (" & Image (This.Size)
               & " bytes): truncated");
      end if;
      if Into'Length = 0 then
         return;
      end if;
      declare
         Last : Stream_Element_Offset;
      begin
         Stream_IO.Set_Index (This.File, Stream_IO.Positive_Count (Offset + 1));
         Stream_IO.Read (This.File, Into, Last);
         if Last /= Into'Last then
            Fail (This, Offset, What & ": the file ended early: truncated");
         end if;
      end;
   end Read_At;

   function Read_At
     (This : in out Reader; Offset, Count : Unsigned_64; What : String) return Byte_Array_Access
   is
      Result : Byte_Array_Access;
   begin
      if Offset > This.Size or else Count > This.Size - Offset then
         Fail (This, Offset, What & " of " & Image (Count)
               & " bytes extends past the end of the file (" & Image (This.Size)
               & " bytes): truncated");
      end if;
      Result := new Byte_Array (1 .. Stream_Element_Offset (Count));
      begin
         Read_At (This, Offset, Result.all, What);
      exception
         when others =>
            Free (Result);
            raise;
      end;
      return Result;
   end Read_At;

   --  Decoding fields -----------------------------------------------------------

   type Cursor is record
      Pos, First, Last : Stream_Element_Offset;
      --  The next byte, and the bounds of the record's content.
      Base             : Unsigned_64;
      --  File offset of First; in a chunk, the chunk record's offset.
      In_Chunk         : Boolean := False;
   end record;

   function Where (C : Cursor) return Unsigned_64 is
     (if C.In_Chunk then C.Base else C.Base + Unsigned_64 (C.Pos - C.First));

   procedure Need (This : Reader; C : Cursor; Count : Stream_Element_Offset; What : String) is
   begin
      if C.Pos + Count - 1 > C.Last then
         Fail (This, Where (C),
               (if C.In_Chunk
                then "in the chunk's uncompressed byte " & Image (Unsigned_64 (C.Pos - C.First))
                  & ": "
                else "")
               & What & " of " & Image (Unsigned_64 (Count)) & " bytes runs past its record ("
               & Image (Unsigned_64 (C.Last - C.Pos + 1)) & " bytes left): corrupt");
      end if;
   end Need;

   function Get_U64 (Data : Byte_Array; At_Index : Stream_Element_Offset) return Unsigned_64 is
      Result : Unsigned_64 := 0;
   begin
      for I in reverse 0 .. 7 loop
         Result := Shift_Left (Result, 8)
           or Unsigned_64 (Data (At_Index + Stream_Element_Offset (I)));
      end loop;
      return Result;
   end Get_U64;

   function U8 (This : Reader; Data : Byte_Array; C : in out Cursor; What : String)
                return Unsigned_8 is
   begin
      Need (This, C, 1, What);
      C.Pos := C.Pos + 1;
      return Unsigned_8 (Data (C.Pos - 1));
   end U8;

   function U16 (This : Reader; Data : Byte_Array; C : in out Cursor; What : String)
                 return Unsigned_16 is
   begin
      Need (This, C, 2, What);
      C.Pos := C.Pos + 2;
      return Unsigned_16 (Data (C.Pos - 2)) or Shift_Left (Unsigned_16 (Data (C.Pos - 1)), 8);
   end U16;

   function U32 (This : Reader; Data : Byte_Array; C : in out Cursor; What : String)
                 return Unsigned_32 is
      Result : Unsigned_32 := 0;
   begin
      Need (This, C, 4, What);
      for I in reverse 0 .. 3 loop
         Result := Shift_Left (Result, 8) or Unsigned_32 (Data (C.Pos + Stream_Element_Offset (I)));
      end loop;
      C.Pos := C.Pos + 4;
      return Result;
   end U32;

   function U64 (This : Reader; Data : Byte_Array; C : in out Cursor; What : String)
                 return Unsigned_64 is
   begin
      Need (This, C, 8, What);
      C.Pos := C.Pos + 8;
      return Get_U64 (Data, C.Pos - 8);
   end U64;

   procedure Next_Record
     (This   : Reader;
      Data   : Byte_Array;
      Outer  : in out Cursor;
      What   : String;
      Opcode : out Unsigned_8;
      Inner  : out Cursor)
   --  The record at Outer.Pos: its opcode, and Inner spanning its content,
   --  checked to fit in Outer (errors name "<What> opcode", "<What> length",
   --  What). Outer.Pos moves past the record.
   is
      Length : Unsigned_64;
   begin
      Opcode := U8 (This, Data, Outer, What & " opcode");
      Length := U64 (This, Data, Outer, What & " length");
      if Length > Unsigned_64 (Outer.Last - Outer.Pos + 1) then
         Need (This, Outer, Stream_Element_Offset'Last / 2, What);
      end if;
      Inner := (Outer with delta Last => Outer.Pos + Stream_Element_Offset (Length) - 1);
      Outer.Pos := Inner.Last + 1;
   end Next_Record;

   function Str (This : Reader; Data : Byte_Array; C : in out Cursor; What : String)
                 return String is
      Length : constant Unsigned_32 := U32 (This, Data, C, What & "'s length");
   begin
      if Unsigned_64 (Length) > Unsigned_64 (C.Last - C.Pos + 1) then
         Need (This, C, Stream_Element_Offset'Last / 2, What);
      end if;
      declare
         Result : String (1 .. Natural (Length));
      begin
         for I in Result'Range loop
            Result (I) := Character'Val (Data (C.Pos + Stream_Element_Offset (I) - 1));
         end loop;
         C.Pos := C.Pos + Stream_Element_Offset (Length);
         return Result;
      end;
   end Str;

   function Map (This : Reader; Data : Byte_Array; C : in out Cursor; What : String)
                 return String_Maps.Map is
      Length : constant Unsigned_32 := U32 (This, Data, C, What & "'s length");
      Result : String_Maps.Map;
      Stop   : Stream_Element_Offset;
   begin
      Need (This, C, Stream_Element_Offset (Length), What);
      Stop := C.Pos + Stream_Element_Offset (Length);
      declare
         Inner : Cursor := (C with delta Last => Stop - 1);
      begin
         while Inner.Pos < Stop loop
            declare
               Key   : constant String := Str (This, Data, Inner, What & " key");
               Value : constant String := Str (This, Data, Inner, What & " value");
            begin
               Result.Include (Key, Value);
            end;
         end loop;
      end;
      C.Pos := Stop;
      return Result;
   end Map;

   function Skip (This : Reader; C : in out Cursor; Count : Unsigned_32) return Boolean is
   begin
      Need (This, C, Stream_Element_Offset (Count), "map");
      C.Pos := C.Pos + Stream_Element_Offset (Count);
      return True;
   end Skip;

   --  Schemas and channels --------------------------------------------------------

   procedure Add_Schema (This : in out Reader; Data : Byte_Array; C : in out Cursor) is
      S     : Schema_Info;
      Start : constant Unsigned_64 := Where (C);
   begin
      S.Id := U16 (This, Data, C, "schema id");
      S.Name := To_Unbounded_String (Str (This, Data, C, "schema name"));
      S.Encoding := To_Unbounded_String (Str (This, Data, C, "schema encoding"));
      S.Data := To_Unbounded_String (Str (This, Data, C, "schema data"));
      for Known of This.Schemas loop
         if Known.Id = S.Id then
            return;
         end if;
      end loop;
      This.Schemas.Append (S);
      This.Schema_Where.Append (Start);
   end Add_Schema;

   procedure Add_Channel (This : in out Reader; Data : Byte_Array; C : in out Cursor) is
      Ch    : Channel_Info;
      Start : constant Unsigned_64 := Where (C);
   begin
      Ch.Id := U16 (This, Data, C, "channel id");
      Ch.Schema := U16 (This, Data, C, "channel schema id");
      Ch.Topic := To_Unbounded_String (Str (This, Data, C, "channel topic"));
      Ch.Message_Encoding := To_Unbounded_String (Str (This, Data, C, "channel message encoding"));
      Ch.Metadata := Map (This, Data, C, "channel metadata");
      for Known of This.Channels loop
         if Known.Id = Ch.Id then
            return;
         end if;
      end loop;
      This.Channels.Append (Ch);
      This.Channel_Where.Append (Start);
   end Add_Channel;

   procedure Check_Schemas (This : Reader) is
   --  Every channel's schema (other than 0, none) must have a schema record.
   begin
      for Index in 1 .. Natural (This.Channels.Length) loop
         declare
            Ch : Channel_Info renames This.Channels (Index);
         begin
            if Ch.Schema /= 0
              and then not (for some S of This.Schemas => S.Id = Ch.Schema)
            then
               Fail (This, This.Channel_Where (Index),
                     "channel" & Ch.Id'Image & " (topic '" & To_String (Ch.Topic)
                     & "') names schema" & Ch.Schema'Image
                     & ", which no schema record defines: corrupt");
            end if;
         end;
      end loop;
   end Check_Schemas;

   --  Record headers -------------------------------------------------------------

   procedure Read_Head
     (This : in out Reader; Offset : Unsigned_64; Opcode : out Unsigned_8;
      Length : out Unsigned_64)
   is
      Head : Byte_Array (1 .. Record_Head);
   begin
      Read_At (This, Offset, Head, "record header");
      Opcode := Unsigned_8 (Head (1));
      Length := Get_U64 (Head, 2);
   end Read_Head;

   generic
      with procedure Read_Content (Content : Byte_Array; C : in out Cursor);
   procedure Read_Record_Content
     (This : in out Reader; Offset, Length : Unsigned_64; What : String);
   --  Reads the Length bytes of a record's content at Offset (What names them
   --  in the errors), passes them to Read_Content with a cursor on their first
   --  byte, and frees them, also when Read_Content raises.

   procedure Read_Record_Content
     (This : in out Reader; Offset, Length : Unsigned_64; What : String)
   is
      Content : Byte_Array_Access := Read_At (This, Offset, Length, What);
      C       : Cursor := (Pos => 1, First => 1, Last => Content'Last, Base => Offset,
                           In_Chunk => False);
   begin
      Read_Content (Content.all, C);
      Free (Content);
   exception
      when others =>
         Free (Content);
         raise;
   end Read_Record_Content;

   --  Chunks -----------------------------------------------------------------------

   type Entry_Position is record
      Log_Time : Time_Stamp;
      Pos      : Stream_Element_Offset;
   end record;
   function "<" (L, R : Entry_Position) return Boolean is
     (L.Log_Time < R.Log_Time or else (L.Log_Time = R.Log_Time and then L.Pos < R.Pos));
   package Position_Vectors is new Ada.Containers.Vectors (Positive, Entry_Position);
   package Position_Sorting is new Position_Vectors.Generic_Sorting;

   procedure Check_Channel (This : Reader; Id : Channel_Id; C : Cursor) is
   begin
      for Known of This.Channels loop
         if Known.Id = Id then
            return;
         end if;
      end loop;
      Fail (This, Where (C), "message on channel" & Id'Image & ", which no channel record "
            & "defines: corrupt");
   end Check_Channel;

   procedure Yield_Message
     (This    : Reader; Data : Byte_Array; Pos : Stream_Element_Offset; C : Cursor;
      Process : not null access procedure (Msg : Message; Data : Byte_Array))
   is
      --  Pos: first byte of a message record's content; C bounds it.
      Inner : Cursor := (C with delta Pos => Pos);
      M     : Message;
   begin
      M.Offset := Where (Inner);
      M.In_Chunk := C.In_Chunk;
      if C.In_Chunk then
         M.Chunk_Byte := Unsigned_64 (Pos - C.First) - Record_Head;
      end if;
      M.Channel := U16 (This, Data, Inner, "message channel id");
      M.Sequence := U32 (This, Data, Inner, "message sequence");
      M.Log_Time := U64 (This, Data, Inner, "message log time");
      M.Publish_Time := U64 (This, Data, Inner, "message publish time");
      Check_Channel (This, M.Channel, Inner);
      Process (M, Data (Inner.Pos .. Inner.Last));
   end Yield_Message;

   procedure Process_Chunk
     (This     : in out Reader;
      Offset   : Unsigned_64;
      Process  : not null access procedure (Msg : Message; Data : Byte_Array);
      From, To : Time_Stamp)
   is
      Opcode       : Unsigned_8;
      Length       : Unsigned_64;
      Content      : Byte_Array_Access;
      Plain        : Byte_Array_Access;
   begin
      Read_Head (This, Offset, Opcode, Length);
      if Opcode /= Op_Chunk then
         Fail (This, Offset, "expected a chunk record (opcode 0x06), found opcode " & Hex (Opcode)
               & ": corrupt chunk index");
      end if;
      Content := Read_At (This, Offset + Record_Head, Length, "chunk record");
      declare
         C                 : Cursor := (Pos => 1, First => 1, Last => Content'Last,
                                        Base => Offset + Record_Head, In_Chunk => False);
         Start             : constant Unsigned_64 := U64 (This, Content.all, C, "chunk start");
         Stop              : constant Unsigned_64 := U64 (This, Content.all, C, "chunk end");
         Uncompressed_Size : constant Unsigned_64 := U64 (This, Content.all, C, "chunk size");
         CRC               : constant Unsigned_32 := U32 (This, Content.all, C, "chunk CRC");
         Kind_At           : constant Unsigned_64 := Where (C);
         Kind_Name         : constant String := Str (This, Content.all, C, "chunk compression");
         Records_Length    : constant Unsigned_64 := U64 (This, Content.all, C, "chunk records");
         Kind              : Compression_Kind;
         Positions         : Position_Vectors.Vector;
      begin
         if Stop < From or else Start > To then
            Free (Content);
            return;
         end if;
         begin
            Kind := Compression_Value (Kind_Name);
         exception
            when Format_Error =>
               Fail (This, Kind_At, "unknown chunk compression """ & Kind_Name & """");
         end;
         if Records_Length > Unsigned_64 (C.Last - C.Pos + 1) then
            Fail (This, Where (C), "chunk records of " & Image (Records_Length)
                  & " bytes run past the chunk record: corrupt");
         elsif Uncompressed_Size > Largest_Chunk
           or else (Kind = None and then Uncompressed_Size /= Records_Length)
           or else (Kind /= None and then Uncompressed_Size / 100_000 > Records_Length)
         then
            Fail (This, Offset, "implausible uncompressed chunk size " & Image (Uncompressed_Size)
                  & ": corrupt");
         end if;
         declare
            Packed : Byte_Array renames
              Content (C.Pos .. C.Pos + Stream_Element_Offset (Records_Length) - 1);
         begin
            if Kind = None then
               if Records_Length /= Uncompressed_Size then
                  Fail (This, Offset, "uncompressed chunk holds " & Image (Records_Length)
                        & " bytes, its header says " & Image (Uncompressed_Size) & ": corrupt");
               end if;
               Plain := new Byte_Array (1 .. Packed'Length);
               Plain.all := Packed;
            else
               Plain := new Byte_Array (1 .. Stream_Element_Offset (Uncompressed_Size));
               begin
                  RCL.MCAP.Compression.Decompress (Kind, Packed, Plain.all);
               exception
                  when E : RCL.MCAP.Compression.Compression_Error =>
                     Fail (This, Where (C), "chunk does not decompress ("
                           & Ada.Exceptions.Exception_Message (E) & "): corrupt");
               end;
            end if;
         end;
         if CRC /= 0 and then CRC32 (Plain.all) /= CRC then
            Fail (This, Offset, "chunk CRC mismatch: corrupt");
         end if;
         --  The records inside: schemas and channels are noted, messages
         --  listed, then yielded in log-time order.
         declare
            P : Cursor := (Pos => 1, First => 1, Last => Plain'Last, Base => Offset,
                           In_Chunk => True);
         begin
            while P.Pos <= P.Last loop
               declare
                  Inner_Op : Unsigned_8;
                  R        : Cursor;
               begin
                  Next_Record (This, Plain.all, P, "record", Inner_Op, R);
                  declare
                     Body_At : constant Stream_Element_Offset := R.Pos;
                  begin
                     case Inner_Op is
                        when Op_Schema => Add_Schema (This, Plain.all, R);
                        when Op_Channel => Add_Channel (This, Plain.all, R);
                        when Op_Message =>
                           declare
                              Probe : Cursor := R;
                              Ignored_Channel : constant Unsigned_16 :=
                                U16 (This, Plain.all, Probe, "message channel id");
                              Ignored_Sequence : constant Unsigned_32 :=
                                U32 (This, Plain.all, Probe, "message sequence");
                              Log_Time : constant Unsigned_64 :=
                                U64 (This, Plain.all, Probe, "message log time");
                           begin
                              if Log_Time < Start or else Log_Time > Stop then
                                 Fail (This, Offset, "message at the chunk's uncompressed byte "
                                       & Image (Unsigned_64 (Body_At - 10)) & " has log time "
                                       & Image (Log_Time) & ", outside the chunk's range "
                                       & Image (Start) & " .. " & Image (Stop) & ": corrupt");
                              end if;
                              if Log_Time >= From and then Log_Time <= To then
                                 Positions.Append (Entry_Position'(Log_Time, Body_At));
                              end if;
                           end;
                        when 16#00# =>
                           Fail (This, Offset, "invalid opcode 0x00 at the chunk's uncompressed "
                                 & "byte " & Image (Unsigned_64 (Body_At - 10)) & ": corrupt");
                        when others => null;
                     end case;
                  end;
               end;
            end loop;
            if not Position_Sorting.Is_Sorted (Positions) then
               Position_Sorting.Sort (Positions);
            end if;
            for E of Positions loop
               declare
                  Len_At : constant Stream_Element_Offset := E.Pos - 8;
                  R      : constant Cursor :=
                    (P with delta Pos => E.Pos,
                                  Last => E.Pos - 1
                                    + Stream_Element_Offset (Get_U64 (Plain.all, Len_At)));
               begin
                  Yield_Message (This, Plain.all, E.Pos, R, Process);
               end;
            end loop;
         end;
      end;
      Free (Content);
      Free (Plain);
   exception
      when others =>
         Free (Content);
         Free (Plain);
         raise;
   end Process_Chunk;

   --  The message record at Offset, its head read (content: Length bytes).
   procedure Process_Loose
     (This     : in out Reader;
      Offset   : Unsigned_64;
      Length   : Unsigned_64;
      Process  : not null access procedure (Msg : Message; Data : Byte_Array);
      From, To : Time_Stamp)
   is
      procedure Yield_In_Range (Content : Byte_Array; C : in out Cursor) is
         Probe    : Cursor := (C with delta Pos => 7);
         Log_Time : constant Unsigned_64 := U64 (This, Content, Probe, "message log time");
      begin
         if Log_Time >= From and then Log_Time <= To then
            Yield_Message (This, Content, 1, C, Process);
         end if;
      end Yield_In_Range;

      procedure Read_Message is new Read_Record_Content (Yield_In_Range);
   begin
      Read_Message (This, Offset + Record_Head, Length, "message record");
   end Process_Loose;

   --  Scanning the data section record by record --------------------------------------

   procedure Scan (This : in out Reader; From, Until_Offset : Unsigned_64; Recover : Boolean) is
      Pos    : Unsigned_64 := From;
      Opcode : Unsigned_8;
      Length : Unsigned_64;
   begin
      while Pos < Until_Offset loop
         if Until_Offset - Pos < Record_Head then
            if Recover then
               This.Recovered := True;
               return;
            end if;
            Fail (This, Pos, "record header cut short by the end of the file ("
                  & Image (This.Size) & " bytes): truncated");
         end if;
         Read_Head (This, Pos, Opcode, Length);
         if Opcode = 0 then
            Fail (This, Pos, "invalid opcode 0x00: corrupt");
         elsif Length > Until_Offset - Pos - Record_Head then
            if Recover then
               This.Recovered := True;
               return;
            end if;
            Fail (This, Pos, "record (opcode " & Hex (Opcode) & ") of " & Image (Length)
                  & " bytes extends past the end of the file (" & Image (This.Size)
                  & " bytes): truncated");
         end if;
         case Opcode is
            when Op_Schema | Op_Channel =>
               declare
                  procedure Add (Content : Byte_Array; C : in out Cursor) is
                  begin
                     if Opcode = Op_Schema then
                        Add_Schema (This, Content, C);
                     else
                        Add_Channel (This, Content, C);
                     end if;
                  end Add;

                  procedure Read_And_Add is new Read_Record_Content (Add);
               begin
                  Read_And_Add (This, Pos + Record_Head, Length, "record");
               end;
            when Op_Chunk | Op_Message =>
               declare
                  Times : Byte_Array (1 .. 16) := [others => 0];
               begin
                  if Length < (if Opcode = Op_Chunk then 16 else 22) then
                     Fail (This, Pos, "record (opcode " & Hex (Opcode) & ") too short: corrupt");
                  end if;
                  Read_At (This, Pos + Record_Head + (if Opcode = Op_Chunk then 0 else 6),
                           Times (1 .. (if Opcode = Op_Chunk then 16 else 8)), "record");
                  This.Data.Append
                    (Data_Record'(Offset => Pos,
                      Start  => Get_U64 (Times, 1),
                      Stop   => (if Opcode = Op_Chunk then Get_U64 (Times, 9)
                                 else Get_U64 (Times, 1))));
               end;
            when Op_Data_End | Op_Footer =>
               return;
            when others =>
               null;
         end case;
         Pos := Pos + Record_Head + Length;
      end loop;
      if Recover and then Pos >= This.Size then
         This.Recovered := True;
      end if;
   end Scan;

   --  The summary ------------------------------------------------------------------------

   procedure Read_Summary (This : in out Reader; From, Until_Offset : Unsigned_64) is
      Content : Byte_Array_Access := Read_At (This, From, Until_Offset - From, "summary");
      C       : Cursor := (Pos => 1, First => 1, Last => Content'Last, Base => From,
                           In_Chunk => False);
   begin
      while C.Pos <= C.Last loop
         declare
            Opcode : Unsigned_8;
            R      : Cursor;
         begin
            Next_Record (This, Content.all, C, "summary record", Opcode, R);
            case Opcode is
               when Op_Schema => Add_Schema (This, Content.all, R);
               when Op_Channel => Add_Channel (This, Content.all, R);
               when Op_Statistics =>
                  This.Statistics := True;
                  This.Message_Total := U64 (This, Content.all, R, "message count");
                  R.Pos := R.Pos + 2 + 4 + 4 + 4 + 4;
                  This.First_Time := U64 (This, Content.all, R, "message start time");
                  This.Last_Time := U64 (This, Content.all, R, "message end time");
                  declare
                     Length : constant Unsigned_32 :=
                       U32 (This, Content.all, R, "channel counts");
                     Stop   : constant Stream_Element_Offset :=
                       R.Pos + Stream_Element_Offset (Length);
                  begin
                     while R.Pos < Stop loop
                        declare
                           Id : constant Unsigned_16 := U16 (This, Content.all, R, "channel id");
                        begin
                           This.Counts.Append
                             (Count_Entry'(Id, U64 (This, Content.all, R, "count")));
                        end;
                     end loop;
                  end;
               when Op_Chunk_Index =>
                  declare
                     Index_At   : constant Unsigned_64 := Where (R);
                     Start_Time : constant Unsigned_64 := U64 (This, Content.all, R, "start");
                     End_Time   : constant Unsigned_64 := U64 (This, Content.all, R, "end");
                     Offset     : constant Unsigned_64 := U64 (This, Content.all, R, "offset");
                     Length     : constant Unsigned_64 := U64 (This, Content.all, R, "length");
                     Offsets_Length : constant Unsigned_32 :=
                       U32 (This, Content.all, R, "message index offsets");
                     Ignored    : constant Boolean := Skip (This, R, Offsets_Length);
                     Ignored_Length : constant Unsigned_64 :=
                       U64 (This, Content.all, R, "message index length");
                     Kind : constant String := Str (This, Content.all, R, "compression");
                  begin
                     if Offset > From or else Length > From - Offset then
                        Fail (This, Index_At, "chunk index points to bytes " & Image (Offset)
                              & " .. " & Image (Offset + Length) & ", past the data section "
                              & "(ends at " & Image (From) & "): corrupt");
                     end if;
                     if This.Data.Is_Empty then
                        This.Compression := To_Unbounded_String (Kind);
                     end if;
                     This.Data.Append (Data_Record'(Offset, Start_Time, End_Time));
                  end;
               when others =>
                  null;
            end case;
         end;
      end loop;
      Free (Content);
   exception
      when others =>
         Free (Content);
         raise;
   end Read_Summary;

   ----------
   -- Open --
   ----------

   function "<" (L, R : Data_Record) return Boolean is
     (L.Start < R.Start or else (L.Start = R.Start and then L.Offset < R.Offset));
   package Data_Sorting is new Record_Vectors.Generic_Sorting;

   procedure Count_Messages (This : in out Reader) is
      procedure Count (Msg : Message; Data : Byte_Array) is
         pragma Unreferenced (Data);
         Found : Boolean := False;
      begin
         This.Message_Total := This.Message_Total + 1;
         if This.Message_Total = 1 or else Msg.Log_Time < This.First_Time then
            This.First_Time := Msg.Log_Time;
         end if;
         This.Last_Time := Unsigned_64'Max (This.Last_Time, Msg.Log_Time);
         for E of This.Counts loop
            if E.Id = Msg.Channel then
               E.Count := E.Count + 1;
               Found := True;
            end if;
         end loop;
         if not Found then
            This.Counts.Append (Count_Entry'(Msg.Channel, 1));
         end if;
      end Count;
   begin
      This.Message_Total := 0;
      This.Counts.Clear;
      This.Iterate (Count'Access);
   end Count_Messages;

   procedure Open
     (This : in out Reader; Path : String; Recover : Boolean := False; Label : String := "")
   is
      Head      : Byte_Array (1 .. 8);
      Opcode    : Unsigned_8;
      Length    : Unsigned_64;
      After_Header : Unsigned_64;
      Has_Footer   : Boolean := False;
   begin
      Close (This);
      This.Path := To_Unbounded_String (if Label = "" then Path else Label);
      Stream_IO.Open (This.File, Stream_IO.In_File, Path);
      This.Size := Unsigned_64 (Stream_IO.Size (This.File));
      This.Recovered := False;
      This.Summary := False;
      This.Statistics := False;
      This.Schemas.Clear;
      This.Channels.Clear;
      This.Channel_Where.Clear;
      This.Schema_Where.Clear;
      This.Data.Clear;
      This.Counts.Clear;
      This.Message_Total := 0;
      This.First_Time := 0;
      This.Last_Time := 0;
      This.Compression := Null_Unbounded_String;
      if This.Size < 8 then
         Fail (This, 0, "not an MCAP file: " & Image (This.Size)
               & " bytes, shorter than the magic");
      end if;
      Read_At (This, 0, Head, "magic");
      if Head /= Magic then
         declare
            SQLite : constant String := "SQLite format 3" & ASCII.NUL;
            --  The header of a SQLite database: rosbag2's sqlite3 storage.
            Start  : Byte_Array (1 .. SQLite'Length) := [others => 0];
         begin
            if This.Size >= SQLite'Length then
               Read_At (This, 0, Start, "magic");
            end if;
            if (for all I in SQLite'Range =>
                  Start (Stream_Element_Offset (I)) = Character'Pos (SQLite (I)))
            then
               Fail (This, 0, "not an MCAP file but a SQLite 3 database (rosbag2's sqlite3 "
                     & "storage, .db3): only MCAP bags are read");
            end if;
         end;
         Fail (This, 0, "not an MCAP file: expected the magic 89 4D 43 41 50 30 0D 0A");
      end if;
      Read_Head (This, 8, Opcode, Length);
      if Opcode /= Op_Header then
         Fail (This, 8, "expected the header record (opcode 0x01), found opcode " & Hex (Opcode)
               & ": corrupt");
      end if;
      declare
         procedure Take_Header (Content : Byte_Array; C : in out Cursor) is
         begin
            This.Profile := To_Unbounded_String (Str (This, Content, C, "profile"));
            This.Library := To_Unbounded_String (Str (This, Content, C, "library"));
         end Take_Header;

         procedure Read_Header is new Read_Record_Content (Take_Header);
      begin
         Read_Header (This, 8 + Record_Head, Length, "header record");
      end;
      After_Header := 8 + Record_Head + Length;
      --  The footer and the closing magic.
      if This.Size >= After_Header + Footer_Length + 8 then
         Read_At (This, This.Size - 8, Head, "closing magic");
         if Head = Magic then
            Read_Head (This, This.Size - 8 - Footer_Length, Opcode, Length);
            Has_Footer := Opcode = Op_Footer and then Length = 20;
            if not Has_Footer then
               Fail (This, This.Size - 8 - Footer_Length,
                     "expected the footer record (opcode 0x02, 20 bytes) before the closing "
                     & "magic: corrupt");
            end if;
         end if;
      end if;
      if not Has_Footer then
         --  Truncated: find the record cut short (or keep what is whole).
         Scan (This, After_Header, This.Size, Recover);
         if not Recover then
            Fail (This, This.Size, "the file ends after its last complete record, without "
                  & "footer and closing magic: truncated (a recording that was stopped?)");
         end if;
         This.Recovered := True;
      else
         declare
            Footer_At : constant Unsigned_64 := This.Size - 8 - Footer_Length;
            Fields    : Byte_Array (1 .. 20);
            Summary_Start, Offsets_Start : Unsigned_64;
            Summary_CRC : Unsigned_32;
         begin
            Read_At (This, Footer_At + Record_Head, Fields, "footer");
            Summary_Start := Get_U64 (Fields, 1);
            Offsets_Start := Get_U64 (Fields, 9);
            Summary_CRC := Unsigned_32 (Fields (17)) or Shift_Left (Unsigned_32 (Fields (18)), 8)
              or Shift_Left (Unsigned_32 (Fields (19)), 16)
              or Shift_Left (Unsigned_32 (Fields (20)), 24);
            if Summary_Start /= 0
              and then (Summary_Start < After_Header or else Summary_Start > Footer_At
                        or else (Offsets_Start /= 0
                                 and then (Offsets_Start < Summary_Start
                                           or else Offsets_Start > Footer_At)))
            then
               Fail (This, Footer_At, "footer points outside the file (summary at "
                     & Image (Summary_Start) & "): corrupt");
            end if;
            if Summary_Start /= 0 and then Summary_CRC /= 0 then
               declare
                  Covered : Byte_Array_Access :=
                    Read_At (This, Summary_Start, Footer_At + Record_Head + 16 - Summary_Start,
                             "summary");
                  Actual  : constant Unsigned_32 := CRC32 (Covered.all);
               begin
                  Free (Covered);
                  if Actual /= Summary_CRC then
                     Fail (This, Summary_Start, "summary CRC mismatch: corrupt");
                  end if;
               end;
            end if;
            if Summary_Start /= 0 then
               Read_Summary (This, Summary_Start,
                             (if Offsets_Start /= 0 then Offsets_Start else Footer_At));
               This.Summary := not This.Data.Is_Empty;
            end if;
            if This.Data.Is_Empty then
               Scan (This, After_Header,
                     (if Summary_Start /= 0 then Summary_Start else Footer_At), False);
               This.Counts.Clear;
               This.Message_Total := 0;
            end if;
         end;
      end if;
      Data_Sorting.Sort (This.Data);
      if not This.Summary
        or else not This.Statistics
        or else (for some E of This.Counts =>
                   not (for some Ch of This.Channels => Ch.Id = E.Id))
      then
         --  No summary, or one without the message counts, or without the
         --  channel records of counted channels (the format only advises
         --  repeating them): every chunk is read, which finds the schema and
         --  channel records in them and counts the messages.
         Count_Messages (This);
      end if;
      Check_Schemas (This);
   exception
      when others =>
         if Stream_IO.Is_Open (This.File) then
            Stream_IO.Close (This.File);
         end if;
         raise;
   end Open;

   function Is_Open (This : Reader) return Boolean is (Stream_IO.Is_Open (This.File));
   function Profile (This : Reader) return String is (To_String (This.Profile));
   function Library (This : Reader) return String is (To_String (This.Library));
   function Recovered (This : Reader) return Boolean is (This.Recovered);
   function Has_Summary (This : Reader) return Boolean is (This.Summary);
   function Schema_Count (This : Reader) return Natural is (Natural (This.Schemas.Length));
   function Schema (This : Reader; Index : Positive) return Schema_Info is
     (This.Schemas (Index));

   function Find_Schema (This : Reader; Id : Schema_Id) return Schema_Info is
   begin
      for S of This.Schemas loop
         if S.Id = Id then
            return S;
         end if;
      end loop;
      raise Format_Error with To_String (This.Path) & ": no schema has id" & Id'Image;
   end Find_Schema;

   function Schema_Offset (This : Reader; Id : Schema_Id) return Unsigned_64 is
   begin
      for I in 1 .. Natural (This.Schemas.Length) loop
         if This.Schemas (I).Id = Id then
            return This.Schema_Where (I);
         end if;
      end loop;
      raise Program_Error;  --  Excluded by the precondition.
   end Schema_Offset;

   function Channel_Offset (This : Reader; Index : Positive) return Unsigned_64 is
     (This.Channel_Where (Index));

   function Place (Msg : Message) return String is
     ("byte " & Image (Msg.Offset)
      & (if Msg.In_Chunk then ": the chunk's uncompressed byte " & Image (Msg.Chunk_Byte)
         else ""));

   function Channel_Count (This : Reader) return Natural is (Natural (This.Channels.Length));
   function Channel (This : Reader; Index : Positive) return Channel_Info is
     (This.Channels (Index));

   function Find_Channel (This : Reader; Id : Channel_Id) return Channel_Info is
   begin
      for C of This.Channels loop
         if C.Id = Id then
            return C;
         end if;
      end loop;
      raise Format_Error with To_String (This.Path) & ": no channel has id" & Id'Image;
   end Find_Channel;

   function Message_Count (This : Reader) return Unsigned_64 is (This.Message_Total);

   function Channel_Message_Count (This : Reader; Id : Channel_Id) return Unsigned_64 is
   begin
      for E of This.Counts loop
         if E.Id = Id then
            return E.Count;
         end if;
      end loop;
      return 0;
   end Channel_Message_Count;

   function Start_Time (This : Reader) return Time_Stamp is (This.First_Time);
   function End_Time (This : Reader) return Time_Stamp is (This.Last_Time);
   function Chunk_Count (This : Reader) return Natural is (Natural (This.Data.Length));
   function Compression (This : Reader) return String is (To_String (This.Compression));

   -------------
   -- Iterate --
   -------------

   procedure Iterate
     (This    : in out Reader;
      Process : not null access procedure (Msg : Message; Data : Byte_Array);
      From    : Time_Stamp := 0;
      To      : Time_Stamp := Time_Stamp'Last)
   is
      Opcode : Unsigned_8;
      Length : Unsigned_64;
   begin
      for D of This.Data loop
         if D.Stop >= From and then D.Start <= To then
            Read_Head (This, D.Offset, Opcode, Length);
            if Opcode = Op_Message then
               Process_Loose (This, D.Offset, Length, Process, From, To);
            else
               Process_Chunk (This, D.Offset, Process, From, To);
            end if;
         end if;
      end loop;
   end Iterate;

   procedure Close (This : in out Reader) is
   begin
      if Stream_IO.Is_Open (This.File) then
         Stream_IO.Close (This.File);
      end if;
   end Close;

   overriding procedure Finalize (This : in out Reader) is
   begin
      Close (This);
   exception
      when others => null;
   end Finalize;

end RCL.MCAP.Readers;
