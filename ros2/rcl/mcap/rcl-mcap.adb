with Interfaces.C;
with System;

package body RCL.MCAP is

   function Image (Kind : Compression_Kind) return String is
     (case Kind is
         when None => "",
         when Zstd => "zstd",
         when LZ4  => "lz4");

   function Compression_Value (Name : String) return Compression_Kind is
   begin
      if Name = "" or else Name = "none" then
         return None;
      elsif Name = "zstd" then
         return Zstd;
      elsif Name = "lz4" then
         return LZ4;
      end if;
      raise Format_Error with "unknown compression """ & Name & """ (expected none, zstd or lz4)";
   end Compression_Value;

   function CRC32
     (Data : Byte_Array; Previous : Interfaces.Unsigned_32 := 0) return Interfaces.Unsigned_32
   is
      --  zlib's crc32 (table-driven, several bytes per step).
      function C_CRC32
        (Crc : Interfaces.C.unsigned_long; Buf : System.Address; Len : Interfaces.C.unsigned)
         return Interfaces.C.unsigned_long
        with Import, Convention => C, External_Name => "crc32";
      Result : Interfaces.C.unsigned_long := Interfaces.C.unsigned_long (Previous);
      First  : Ada.Streams.Stream_Element_Offset := Data'First;
      use type Ada.Streams.Stream_Element_Offset;
      Step   : constant Ada.Streams.Stream_Element_Offset := 2 ** 30;
   begin
      while First <= Data'Last loop
         declare
            Last : constant Ada.Streams.Stream_Element_Offset :=
              Ada.Streams.Stream_Element_Offset'Min (Data'Last, First + Step - 1);
         begin
            Result := C_CRC32 (Result, Data (First)'Address,
                               Interfaces.C.unsigned (Last - First + 1));
            First := Last + 1;
         end;
      end loop;
      return Interfaces.Unsigned_32 (Result);
   end CRC32;

end RCL.MCAP;
