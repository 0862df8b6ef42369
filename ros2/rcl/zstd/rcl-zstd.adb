with Ada.Streams.Stream_IO;
with Ada.Unchecked_Deallocation;
with Interfaces.C.Strings;
with RCL.Zstd.Thin;

package body RCL.Zstd is

   use Ada.Streams;
   use Interfaces.C;
   use type System.Address;

   procedure Free is new Ada.Unchecked_Deallocation (Byte_Array, Byte_Array_Access);

   function Image (N : Long_Long_Integer) return String is
      S : constant String := N'Image;
   begin
      return S (S'First + 1 .. S'Last);
   end Image;

   procedure Fail (Name : String; Offset : Long_Long_Integer; Text : String) with No_Return;
   procedure Fail (Name : String; Offset : Long_Long_Integer; Text : String) is
   begin
      raise Zstd_Error with (if Name = "" then "" else Name & ": ") & "byte " & Image (Offset)
        & ": " & Text;
   end Fail;

   function Error_Text (Code : size_t) return String is
     ("zstd: " & Interfaces.C.Strings.Value (Thin.Error_Name (Code)));

   Slice : constant size_t := 1_024;
   --  Input given to libzstd per call: when it stops on an error, its input
   --  position has not moved since the call began, so the error's byte
   --  offset is that of the slice (at most 1 KiB before where it stopped).

   function Address_Of (Data : Byte_Array) return System.Address is
     (if Data'Length = 0 then System.Null_Address else Data (Data'First)'Address);

   function Checked (Code : size_t) return size_t is
     (if Thin.Is_Error (Code) /= 0 then raise Zstd_Error with Error_Text (Code) else Code);
   --  Code, unless libzstd says it is an error.

   --  Contexts: created (Storage_Error when libzstd cannot), freed once.

   function New_DCtx return System.Address is
     (declare
        Context : constant System.Address := Thin.Create_DCtx;
      begin
        (if Context = System.Null_Address
         then raise Storage_Error with "libzstd: no decompression context" else Context));

   function New_CCtx return System.Address is
     (declare
        Context : constant System.Address := Thin.Create_CCtx;
      begin
        (if Context = System.Null_Address
         then raise Storage_Error with "libzstd: no compression context" else Context));

   procedure Free_DCtx (Context : in out System.Address) is
      Ignored : size_t;
   begin
      if Context /= System.Null_Address then
         Ignored := Thin.Free_DCtx (Context);
         Context := System.Null_Address;
      end if;
   end Free_DCtx;

   procedure Free_CCtx (Context : in out System.Address) is
      Ignored : size_t;
   begin
      if Context /= System.Null_Address then
         Ignored := Thin.Free_CCtx (Context);
         Context := System.Null_Address;
      end if;
   end Free_CCtx;

   procedure Close_All
     (Src, Dst : in out Ada.Streams.Stream_IO.File_Type; Input, Output : in out Byte_Array_Access);
   --  What Decompress_File and Compress_File open and allocate.

   procedure Close_All
     (Src, Dst : in out Ada.Streams.Stream_IO.File_Type; Input, Output : in out Byte_Array_Access)
   is
      use Ada.Streams.Stream_IO;
   begin
      if Is_Open (Src) then
         Close (Src);
      end if;
      if Is_Open (Dst) then
         Close (Dst);
      end if;
      Free (Input);
      Free (Output);
   end Close_All;

   ---------------------
   -- Decompress_File --
   ---------------------

   procedure Decompress_File
     (Source, Target : String;
      Label          : String := "";
      Stop           : access function return Boolean := null)
   is
      use Ada.Streams.Stream_IO;
      Name     : constant String := (if Label = "" then Source else Label);
      Input    : Byte_Array_Access :=
        new Byte_Array (1 .. Stream_Element_Offset (Thin.DStream_In_Size));
      Output   : Byte_Array_Access :=
        new Byte_Array (1 .. Stream_Element_Offset (Thin.DStream_Out_Size));
      Src, Dst : File_Type;
      Context  : System.Address := System.Null_Address;
      Before   : Long_Long_Integer := 0;
      --  Bytes of Source before the ones in Input.
      Frame_At : Long_Long_Integer := 0;
      --  Where the frame being decompressed started.
      Hint     : size_t := 1;
      --  libzstd's answer: 0 when a frame ended and was fully written.
      Last     : Stream_Element_Offset;

      procedure Clean_Up is
      begin
         Close_All (Src, Dst, Input, Output);
         Free_DCtx (Context);
      end Clean_Up;
   begin
      Context := New_DCtx;
      Open (Src, In_File, Source);
      Create (Dst, Out_File, Target);
      loop
         if Stop /= null and then Stop.all then
            raise Interrupted with Name & ": byte " & Image (Before)
              & ": decompression stopped";
         end if;
         Read (Src, Input.all, Last);
         exit when Last < Input'First;
         declare
            In_Buf  : aliased Thin.In_Buffer := (Input (1)'Address, 0, 0);
            Out_Buf : aliased Thin.Out_Buffer;
         begin
            loop
               Out_Buf := (Output (1)'Address, Output'Length, 0);
               In_Buf.Size := size_t'Min (size_t (Last), In_Buf.Pos + Slice);
               Hint := Thin.Decompress_Stream (Context, Out_Buf'Access, In_Buf'Access);
               if Thin.Is_Error (Hint) /= 0 then
                  Fail (Name, Before + Long_Long_Integer (In_Buf.Pos), Error_Text (Hint));
               end if;
               if Out_Buf.Pos > 0 then
                  Write (Dst, Output (1 .. Stream_Element_Offset (Out_Buf.Pos)));
               end if;
               if Hint = 0 then
                  Frame_At := Before + Long_Long_Integer (In_Buf.Pos);
               end if;
               exit when In_Buf.Pos = size_t (Last)
                 and then (Out_Buf.Pos < Out_Buf.Size or else Hint = 0);
            end loop;
         end;
         Before := Before + Long_Long_Integer (Last);
      end loop;
      if Before = 0 then
         Fail (Name, 0, "empty file: no zstd frame");
      elsif Hint /= 0 then
         Fail (Name, Before, "truncated zstd frame (from byte " & Image (Frame_At) & ")");
      end if;
      Clean_Up;
   exception
      when others =>
         Clean_Up;
         raise;
   end Decompress_File;

   -------------------
   -- Compress_File --
   -------------------

   procedure Compress_File (Source, Target : String; Level : Integer := 1) is
      use Ada.Streams.Stream_IO;
      Input    : Byte_Array_Access :=
        new Byte_Array (1 .. Stream_Element_Offset (Thin.CStream_In_Size));
      Output   : Byte_Array_Access :=
        new Byte_Array (1 .. Stream_Element_Offset (Thin.CStream_Out_Size));
      Src, Dst : File_Type;
      Context  : System.Address := System.Null_Address;
      Result   : size_t;
      Last     : Stream_Element_Offset;

      procedure Clean_Up is
      begin
         Close_All (Src, Dst, Input, Output);
         Free_CCtx (Context);
      end Clean_Up;

      procedure Feed (Count : Stream_Element_Offset; Directive : int) is
         In_Buf  : aliased Thin.In_Buffer := (Input (1)'Address, size_t (Count), 0);
         Out_Buf : aliased Thin.Out_Buffer;
      begin
         loop
            Out_Buf := (Output (1)'Address, Output'Length, 0);
            Result := Thin.Compress_Stream2 (Context, Out_Buf'Access, In_Buf'Access, Directive);
            if Thin.Is_Error (Result) /= 0 then
               raise Zstd_Error with Source & ": " & Error_Text (Result);
            end if;
            if Out_Buf.Pos > 0 then
               Write (Dst, Output (1 .. Stream_Element_Offset (Out_Buf.Pos)));
            end if;
            exit when (if Directive = Thin.ZSTD_e_end then Result = 0
                       else In_Buf.Pos = In_Buf.Size);
         end loop;
      end Feed;
   begin
      Context := New_CCtx;
      Result := Thin.CCtx_Set_Parameter (Context, Thin.ZSTD_c_compressionLevel, int (Level));
      if Thin.Is_Error (Result) /= 0 then
         raise Zstd_Error with "level" & Level'Image & ": " & Error_Text (Result);
      end if;
      Open (Src, In_File, Source);
      Create (Dst, Out_File, Target);
      loop
         Read (Src, Input.all, Last);
         exit when Last < Input'First;
         Feed (Last, Thin.ZSTD_e_continue);
      end loop;
      Feed (0, Thin.ZSTD_e_end);
      Clean_Up;
   exception
      when others =>
         Clean_Up;
         raise;
   end Compress_File;

   --------------------
   -- Compress_Bound --
   --------------------

   function Compress_Bound (Size : Stream_Element_Offset) return Stream_Element_Offset is
     (Stream_Element_Offset (Thin.Compress_Bound (size_t (Size))));

   -------------------
   -- Compress_Into --
   -------------------

   function Compress_Into
     (Data : Byte_Array; Into : in out Byte_Array; Level : Integer := 1)
      return Stream_Element_Offset
   is
      Written : constant size_t :=
        Checked (Thin.Compress (Into (Into'First)'Address, Into'Length, Address_Of (Data),
                                Data'Length, int (Level)));
   begin
      return Into'First + Stream_Element_Offset (Written) - 1;
   end Compress_Into;

   ---------------------
   -- Decompress_Into --
   ---------------------

   pragma Warnings (Off, "formal parameter ""Into"" is read but never assigned");
   function Decompress_Into (Data : Byte_Array; Into : out Byte_Array)
                             return Stream_Element_Offset
   is
      Written : constant size_t :=
        Checked (Thin.Decompress (Address_Of (Into), Into'Length, Address_Of (Data),
                                  Data'Length));
   begin
      return Into'First + Stream_Element_Offset (Written) - 1;
   end Decompress_Into;
   pragma Warnings (On, "formal parameter ""Into"" is read but never assigned");

   ----------------
   -- Decompress --
   ----------------

   procedure Decompress
     (This    : in out Decompressor;
      Data    : Byte_Array;
      Process : not null access procedure (Plain : Byte_Array))
   is
      In_Buf   : aliased Thin.In_Buffer := (Address_Of (Data), 0, 0);
      Out_Buf  : aliased Thin.Out_Buffer;
      Produced : Stream_Element_Offset := 0;
      Hint     : size_t := 1;
      Frame_At : size_t := 0;
      Ignored  : size_t;

      procedure Grow (To : Stream_Element_Offset) is
         Bigger : constant Byte_Array_Access := new Byte_Array (1 .. To);
      begin
         if This.Buffer /= null then
            Bigger (1 .. Produced) := This.Buffer (1 .. Produced);
            Free (This.Buffer);
         end if;
         This.Buffer := Bigger;
      end Grow;
   begin
      if This.Context = System.Null_Address then
         This.Context := New_DCtx;
      else
         Ignored := Thin.DCtx_Reset (This.Context, Thin.ZSTD_reset_session_only);
      end if;
      if Data'Length = 0 then
         Fail ("", 0, "empty: no zstd frame");
      end if;
      declare
         --  The size the header records, believed only up to what a frame of
         --  this length can hold (a block of 128 KiB per 4 bytes, as an RLE
         --  block): a corrupt header allocates no more than that.
         Said  : constant unsigned_long_long :=
           Thin.Get_Frame_Content_Size (Address_Of (Data), Data'Length);
         Limit : constant unsigned_long_long :=
           unsigned_long_long'Min (Max_Message_Size,
                                   unsigned_long_long (Data'Length) * 32_768 + 131_072);
         Want  : constant Stream_Element_Offset :=
           (if Said >= Thin.Content_Size_Error then 65_536
            else Stream_Element_Offset (unsigned_long_long'Min (Said, Limit)) + 1);
      begin
         if This.Buffer = null or else This.Buffer'Length < Want then
            Free (This.Buffer);
            Grow (Stream_Element_Offset'Max (Want, 65_536));
         end if;
      end;
      loop
         if Produced = This.Buffer'Length then
            if Produced > Max_Message_Size then
               Fail ("", Long_Long_Integer (In_Buf.Pos), "expands past"
                     & Long_Long_Integer'Image (Max_Message_Size) & " bytes: not read");
            end if;
            Grow (2 * This.Buffer'Length);
         end if;
         Out_Buf := (This.Buffer (Produced + 1)'Address,
                     size_t (This.Buffer'Length - Produced), 0);
         In_Buf.Size := size_t'Min (Data'Length, In_Buf.Pos + Slice);
         Hint := Thin.Decompress_Stream (This.Context, Out_Buf'Access, In_Buf'Access);
         if Thin.Is_Error (Hint) /= 0 then
            Fail ("", Long_Long_Integer (In_Buf.Pos), Error_Text (Hint));
         end if;
         Produced := Produced + Stream_Element_Offset (Out_Buf.Pos);
         if Hint = 0 then
            Frame_At := In_Buf.Pos;
         end if;
         exit when In_Buf.Pos = Data'Length
           and then (Out_Buf.Pos < Out_Buf.Size or else Hint = 0);
      end loop;
      if Hint /= 0 then
         Fail ("", Data'Length, "truncated zstd frame (from byte "
               & Image (Long_Long_Integer (Frame_At)) & ")");
      end if;
      Process (This.Buffer (1 .. Produced));
   end Decompress;

   --------------
   -- Compress --
   --------------

   procedure Compress
     (This    : in out Compressor;
      Data    : Byte_Array;
      Process : not null access procedure (Frame : Byte_Array);
      Level   : Integer := 1)
   is
      Need   : constant Stream_Element_Offset :=
        Stream_Element_Offset (Thin.Compress_Bound (Data'Length));
      Result : size_t;
   begin
      if This.Context = System.Null_Address then
         This.Context := New_CCtx;
      end if;
      if This.Buffer = null or else This.Buffer'Length < Need then
         Free (This.Buffer);
         This.Buffer := new Byte_Array (1 .. Stream_Element_Offset'Max (Need, 4_096));
      end if;
      Result := Checked (Thin.Compress_CCtx (This.Context, This.Buffer (1)'Address,
                                             This.Buffer'Length, Address_Of (Data), Data'Length,
                                             int (Level)));
      Process (This.Buffer (1 .. Stream_Element_Offset (Result)));
   end Compress;

   --------------
   -- Finalize --
   --------------

   overriding procedure Finalize (This : in out Decompressor) is
   begin
      Free_DCtx (This.Context);
      Free (This.Buffer);
   end Finalize;

   overriding procedure Finalize (This : in out Compressor) is
   begin
      Free_CCtx (This.Context);
      Free (This.Buffer);
   end Finalize;

end RCL.Zstd;
