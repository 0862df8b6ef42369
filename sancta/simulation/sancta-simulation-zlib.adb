with Ada.Unchecked_Deallocation;
with Interfaces.C.Strings;
with System;

package body Sancta.Simulation.Zlib is

   use Interfaces;
   use Interfaces.C;
   use type Strings.chars_ptr;

   --  zlib.h's z_stream; inflateInit_ checks its size against the library's.
   type Z_Stream is record
      Next_In   : System.Address := System.Null_Address;
      Avail_In  : unsigned := 0;
      Total_In  : unsigned_long := 0;
      Next_Out  : System.Address := System.Null_Address;
      Avail_Out : unsigned := 0;
      Total_Out : unsigned_long := 0;
      Msg       : Strings.chars_ptr := Strings.Null_Ptr;
      State     : System.Address := System.Null_Address;
      Zalloc    : System.Address := System.Null_Address;
      Zfree     : System.Address := System.Null_Address;
      Opaque    : System.Address := System.Null_Address;
      Data_Type : int := 0;
      Adler     : unsigned_long := 0;
      Reserved  : unsigned_long := 0;
   end record
     with Convention => C;

   Z_OK         : constant := 0;
   Z_STREAM_END : constant := 1;
   Z_NEED_DICT  : constant := 2;
   Z_BUF_ERROR  : constant := -5;
   Z_FINISH     : constant := 4;
   Z_DEFAULT_COMPRESSION : constant := -1;

   function Zlib_Version return Strings.chars_ptr
     with Import, Convention => C, External_Name => "zlibVersion";

   function Inflate_Init
     (Stream : access Z_Stream; Version : Strings.chars_ptr; Size : int) return int
     with Import, Convention => C, External_Name => "inflateInit_";

   function Inflate (Stream : access Z_Stream; Flush : int) return int
     with Import, Convention => C, External_Name => "inflate";

   function Inflate_End (Stream : access Z_Stream) return int
     with Import, Convention => C, External_Name => "inflateEnd";

   function Compress_Bound (Source_Length : unsigned_long) return unsigned_long
     with Import, Convention => C, External_Name => "compressBound";

   function Compress_2
     (Dest   : System.Address; Dest_Length : access unsigned_long;
      Source : System.Address; Source_Length : unsigned_long;
      Level  : int) return int
     with Import, Convention => C, External_Name => "compress2";

   function Zlib_CRC_32
     (CRC : unsigned_long; Buffer : System.Address; Length : unsigned) return unsigned_long
     with Import, Convention => C, External_Name => "crc32";

   function Address_Of (Data : Byte_Array) return System.Address is
     (if Data'Length = 0 then System.Null_Address else Data (Data'First)'Address);

   ----------------
   -- Decompress --
   ----------------

   procedure Decompress
     (Input  : Byte_Array;
      Output : out Byte_Array;
      Last   : out Integer)
   is
      pragma Warnings (Off, Output);  --  zlib writes it through its address
      Stream : aliased Z_Stream;
      Result : int;

      procedure Refuse (Reason : String) with No_Return is
         Offset : constant String := Natural'Image (Input'Length - Natural (Stream.Avail_In));
         --  Bytes read (Total_In is not updated when a dictionary is asked for).
      begin
         Result := Inflate_End (Stream'Access);
         raise Format_Error with "zlib: byte" & Offset & ": " & Reason;
      end Refuse;
   begin
      Stream.Next_In := Address_Of (Input);
      Stream.Avail_In := unsigned (Input'Length);
      Stream.Next_Out := Address_Of (Output);
      Stream.Avail_Out := unsigned (Output'Length);
      Result := Inflate_Init (Stream'Access, Zlib_Version, Z_Stream'Size / 8);
      if Result /= Z_OK then
         raise Format_Error with "zlib: cannot start decompressing (zlib error"
           & Result'Image & ")";
      end if;
      Result := Inflate (Stream'Access, Z_FINISH);
      case Result is
         when Z_STREAM_END =>
            Last := Output'First + Integer (Stream.Total_Out) - 1;
            Result := Inflate_End (Stream'Access);
         when Z_NEED_DICT =>
            Refuse ("preset dictionary not supported");
         when Z_BUF_ERROR =>
            if Stream.Avail_Out = 0 then
               Refuse ("more data than the" & Output'Length'Image & " bytes expected");
            else
               Refuse ("stream cut short");
            end if;
         when others =>
            Refuse (if Stream.Msg = Strings.Null_Ptr
                    then "zlib error" & Result'Image
                    else Strings.Value (Stream.Msg));
      end case;
   end Decompress;

   --------------
   -- Compress --
   --------------

   function Compress (Data : Byte_Array) return Byte_Array is
      procedure Free is new Ada.Unchecked_Deallocation (Byte_Array, Byte_Array_Access);
      Length : aliased unsigned_long := Compress_Bound (Data'Length);
      Packed : Byte_Array_Access := new Byte_Array (0 .. Natural (Length) - 1);
      Result : constant int := Compress_2
        (Packed (0)'Address, Length'Access, Address_Of (Data), Data'Length,
         Z_DEFAULT_COMPRESSION);
   begin
      if Result /= Z_OK then
         Free (Packed);
         raise Storage_Error with "zlib: compress2 failed (zlib error" & Result'Image & ")";
      end if;
      return Stream : constant Byte_Array := Packed (0 .. Natural (Length) - 1) do
         Free (Packed);
      end return;
   end Compress;

   ------------
   -- CRC_32 --
   ------------

   function CRC_32
     (Data    : Byte_Array;
      Initial : Unsigned_32 := 0) return Unsigned_32
   is (Unsigned_32 (Zlib_CRC_32 (unsigned_long (Initial), Address_Of (Data), Data'Length)));

end Sancta.Simulation.Zlib;
