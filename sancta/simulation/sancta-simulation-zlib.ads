--  The zlib format (RFC 1950 around DEFLATE, RFC 1951) and CRC-32 for the
--  simulator's PNG images: a thin binding to the system's zlib (Debian's
--  zlib1g), which does the work.
--
--     Output : Byte_Array (0 .. Expected - 1);
--     Decompress (Input, Output, Last);  --  Format_Error on bad data
--     Packed : constant Byte_Array := Compress (Output (0 .. Last));
with Interfaces;

package Sancta.Simulation.Zlib is

   subtype Byte is Interfaces.Unsigned_8;
   type Byte_Array is array (Natural range <>) of Byte;
   type Byte_Array_Access is access Byte_Array;

   Max_Length : constant := 2 ** 31 - 1;
   --  Longest input or output one call takes (zlib counts in 32 bits).

   procedure Decompress
     (Input  : Byte_Array;
      Output : out Byte_Array;
      Last   : out Integer)
     with Pre => Input'Length <= Max_Length and then Output'Length <= Max_Length;
   --  Decompresses the zlib stream at the start of Input (header, DEFLATE
   --  data, Adler-32 checked) into Output (Output'First .. Last); bytes
   --  after the stream's end are not read. Raises Format_Error
   --  ("zlib: byte N: reason", N counted from Input'First) on a malformed or
   --  truncated stream, a preset dictionary, or more output than fits.

   function Compress (Data : Byte_Array) return Byte_Array
     with Pre => Data'Length <= Max_Length;
   --  A zlib stream holding Data (zlib's default compression level).

   function CRC_32
     (Data    : Byte_Array;
      Initial : Interfaces.Unsigned_32 := 0) return Interfaces.Unsigned_32
     with Pre => Data'Length <= Max_Length;
   --  CRC-32 (ISO 3309 / PNG); Initial continues an earlier result:
   --  CRC_32 ("6789", CRC_32 ("12345")) = CRC_32 ("123456789").

end Sancta.Simulation.Zlib;
