--  Chunk compression: Zstandard frames through RCL.Zstd (the system's
--  libzstd), LZ4 frames (as MCAP requires) through a thin binding to liblz4.
--  Example:
--     Last := Compress (Zstd, Chunk, Into => Buffer);  --  Buffer (1 .. Last)
private package RCL.MCAP.Compression is

   use type Ada.Streams.Stream_Element_Offset;

   Compression_Error : exception;
   --  The library's own message ("Unknown frame descriptor").

   subtype Compressing_Kind is Compression_Kind range Zstd .. LZ4;
   --  A kind that compresses (not None).

   function Bound (Kind : Compressing_Kind; Size : Ada.Streams.Stream_Element_Offset)
                   return Ada.Streams.Stream_Element_Offset;
   --  The largest compressed size of Size bytes.

   function Compress
     (Kind : Compressing_Kind; Data : Byte_Array; Into : in out Byte_Array)
      return Ada.Streams.Stream_Element_Offset
     with Pre => Into'Length >= Bound (Kind, Data'Length);
   --  Compresses Data (fastest level) into Into, returns the index of the
   --  last byte written.

   procedure Decompress (Kind : Compressing_Kind; Data : Byte_Array; Into : out Byte_Array);
   --  Decompresses Data, which must expand to exactly Into'Length bytes;
   --  Compression_Error otherwise or when Data is corrupt.

end RCL.MCAP.Compression;
