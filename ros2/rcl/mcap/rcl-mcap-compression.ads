--  Chunk compression through thin bindings to the system's
--  libzstd (Zstandard frames) and liblz4 (LZ4 frames, as MCAP requires).
--  Example:
--     Last := Compress (Zstd, Chunk, Into => Buffer);  --  Buffer (1 .. Last)
private package RCL.MCAP.Compression is

   use type Ada.Streams.Stream_Element_Offset;

   Compression_Error : exception;
   --  The library's own message ("Unknown frame descriptor").

   function Bound (Kind : Compression_Kind; Size : Ada.Streams.Stream_Element_Offset)
                   return Ada.Streams.Stream_Element_Offset
     with Pre => Kind /= None;
   --  The largest compressed size of Size bytes.

   function Compress
     (Kind : Compression_Kind; Data : Byte_Array; Into : in out Byte_Array)
      return Ada.Streams.Stream_Element_Offset
     with Pre => Kind /= None and then Into'Length >= Bound (Kind, Data'Length);
   --  Compresses Data (fastest level) into Into, returns the index of the
   --  last byte written.

   procedure Decompress (Kind : Compression_Kind; Data : Byte_Array; Into : out Byte_Array)
     with Pre => Kind /= None;
   --  Decompresses Data, which must expand to exactly Into'Length bytes;
   --  Compression_Error otherwise or when Data is corrupt.

end RCL.MCAP.Compression;
