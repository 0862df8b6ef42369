--  Zstandard frames (RFC 8878) through a thin binding to the system's
--  libzstd (Debian's libzstd-dev): what rosbag2's zstd compressor writes,
--  a whole storage file (compression_mode file: bag_0.db3.zstd) or each
--  message's data (compression_mode message). Files stream through
--  buffers of libzstd's recommended sizes (128 KiB in, 128 KiB out): never
--  whole in memory. Messages go through one context and one buffer that
--  grows to the largest message.
--  Example:
--     Decompress_File ("run/run_0.db3.zstd", "/tmp/x.db3");
--     D : Decompressor;
--     D.Decompress (Frame, Use_It'Access);   --  Use_It (Plain : Byte_Array)
--     Last := Decompress_Into (Frame, Into => Buffer);  --  Buffer (1 .. Last)
with Ada.Finalization;
with Ada.Streams;

private with System;

package RCL.Zstd is

   use type Ada.Streams.Stream_Element_Array;
   use type Ada.Streams.Stream_Element_Offset;

   Zstd_Error : exception;
   --  Input that is no whole zstd frames, with the byte offset in it where
   --  libzstd stopped (input goes to it 1 KiB at a time: the start of that
   --  KiB): "run_0.db3.zstd: byte 4096: zstd: Corrupted block detected",
   --  "...: byte 52000: truncated zstd frame (from byte 0)". Also a failure
   --  to compress (libzstd's text).

   subtype Byte_Array is Ada.Streams.Stream_Element_Array;

   Magic : constant Byte_Array := [16#28#, 16#B5#, 16#2F#, 16#FD#];
   --  A zstd frame's first four bytes.

   function Starts_Frame (Data : Byte_Array) return Boolean is
     (Data'Length >= 4 and then Data (Data'First .. Data'First + 3) = Magic);

   Max_Message_Size : constant := 2 ** 32;
   --  The largest message Decompress expands (bytes): a frame claiming or
   --  producing more is refused rather than exhausting memory.

   Interrupted : exception;
   --  Decompress_File was told to stop.

   procedure Decompress_File
     (Source, Target : String;
      Label          : String := "";
      Stop           : access function return Boolean := null);
   --  Source's frames (one or more, as the zstd tool and rosbag2 write
   --  them) decompressed into Target (created, or overwritten). Zstd_Error
   --  naming Label (Source when "") and the byte of Source when it is no
   --  zstd, corrupt or truncated (Target then holds what came before);
   --  Ada.IO_Exceptions' errors when a file cannot be opened or written.
   --  Stop (when given) is asked before each 128 KiB read: True raises
   --  Interrupted (a signal during a long decompression).

   procedure Compress_File (Source, Target : String; Level : Integer := 1);
   --  Source as one frame into Target (streamed as Decompress_File).

   function Compress_Bound (Size : Ada.Streams.Stream_Element_Offset)
                            return Ada.Streams.Stream_Element_Offset;
   --  The largest frame Compress_Into writes for Size bytes.

   function Compress_Into
     (Data : Byte_Array; Into : in out Byte_Array; Level : Integer := 1)
      return Ada.Streams.Stream_Element_Offset
     with Pre => Into'Length >= Compress_Bound (Data'Length);
   --  Data as one frame into Into (a buffer the caller keeps, as an MCAP
   --  writer's chunk buffer), returns the index of its last byte.
   --  Zstd_Error "zstd: <libzstd's text>" when libzstd fails.

   function Decompress_Into (Data : Byte_Array; Into : out Byte_Array)
                             return Ada.Streams.Stream_Element_Offset;
   --  Data's frame(s) expanded into Into (sized beforehand, as from an MCAP
   --  chunk's header), returns the index of the last byte written.
   --  Zstd_Error "zstd: <libzstd's text>" when Data is not whole zstd
   --  frames or expands past Into'Length ("Destination buffer is too
   --  small"): no byte offset, libzstd decompresses it in one call.

   type Decompressor is new Ada.Finalization.Limited_Controlled with private;

   procedure Decompress
     (This    : in out Decompressor;
      Data    : Byte_Array;
      Process : not null access procedure (Plain : Byte_Array));
   --  Data's frame(s) expanded and given to Process (valid during the call
   --  only). Zstd_Error "byte N: ..." (N counted from 0 in Data) when Data is
   --  not whole zstd frames or expands past Max_Message_Size.

   type Compressor is new Ada.Finalization.Limited_Controlled with private;

   procedure Compress
     (This    : in out Compressor;
      Data    : Byte_Array;
      Process : not null access procedure (Frame : Byte_Array);
      Level   : Integer := 1);
   --  Data as one frame (its size recorded in the frame header, as
   --  rosbag2's compressor writes it) given to Process.

   overriding procedure Finalize (This : in out Decompressor);
   overriding procedure Finalize (This : in out Compressor);

private

   type Byte_Array_Access is access Byte_Array;

   type Decompressor is new Ada.Finalization.Limited_Controlled with record
      Context : System.Address := System.Null_Address;
      Buffer  : Byte_Array_Access;
   end record;

   type Compressor is new Ada.Finalization.Limited_Controlled with record
      Context : System.Address := System.Null_Address;
      Buffer  : Byte_Array_Access;
   end record;

end RCL.Zstd;
