--  The zlib container and DEFLATE (RFC 1950, RFC 1951), written for the
--  image files of the simulator: a complete inflater (stored, fixed and
--  dynamic Huffman blocks), a "stored blocks only" deflater, and the two
--  checksums the formats need (Adler-32, CRC-32 as used by PNG).
--
--     Output : Byte_Array (0 .. Expected - 1);
--     Zlib_Decompress (Input, Output, Last);  --  Format_Error on bad data
with Interfaces;

package Sancta.Simulation.Deflate is

   subtype Byte is Interfaces.Unsigned_8;
   type Byte_Array is array (Natural range <>) of Byte;
   type Byte_Array_Access is access Byte_Array;

   procedure Inflate
     (Input  : Byte_Array;
      Output : out Byte_Array;
      Last   : out Integer;
      Used   : out Natural);
   --  Decompresses the raw DEFLATE stream at the start of Input into
   --  Output (Output (Output'First .. Last) is written) and tells how many
   --  input bytes it used. Raises Format_Error ("deflate: byte N: reason")
   --  on a malformed stream, a truncated one, or more output than fits.

   procedure Zlib_Decompress
     (Input  : Byte_Array;
      Output : out Byte_Array;
      Last   : out Integer);
   --  The same for a zlib stream: header, DEFLATE data, Adler-32 (checked).

   function Zlib_Store (Data : Byte_Array) return Byte_Array;
   --  A valid zlib stream holding Data in stored (uncompressed) blocks.

   function Adler_32 (Data : Byte_Array) return Interfaces.Unsigned_32;

   function CRC_32
     (Data    : Byte_Array;
      Initial : Interfaces.Unsigned_32 := 0) return Interfaces.Unsigned_32;
   --  CRC-32 (ISO 3309 / PNG); Initial continues an earlier result.

end Sancta.Simulation.Deflate;
