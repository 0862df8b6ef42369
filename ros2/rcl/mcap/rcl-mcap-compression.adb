with Ada.Exceptions;
with Interfaces.C.Strings;
with System;
with RCL.Zstd;

package body RCL.MCAP.Compression is

   use Interfaces.C;

   --  libzstd: through RCL.Zstd (one binding); its Zstd_Error texts
   --  ("zstd: Unknown frame descriptor") become Compression_Error.

   --  liblz4 (frame API) ------------------------------------------------------

   LZ4F_Version : constant unsigned := 100;

   function LZ4F_compressFrameBound (Size : size_t; Prefs : System.Address) return size_t
     with Import, Convention => C, External_Name => "LZ4F_compressFrameBound";
   function LZ4F_compressFrame
     (Dst : System.Address; Capacity : size_t; Src : System.Address; Size : size_t;
      Prefs : System.Address) return size_t
     with Import, Convention => C, External_Name => "LZ4F_compressFrame";
   function LZ4F_createDecompressionContext
     (Context : access System.Address; Version : unsigned) return size_t
     with Import, Convention => C, External_Name => "LZ4F_createDecompressionContext";
   function LZ4F_freeDecompressionContext (Context : System.Address) return size_t
     with Import, Convention => C, External_Name => "LZ4F_freeDecompressionContext";
   function LZ4F_decompress
     (Context : System.Address; Dst : System.Address; Dst_Size : access size_t;
      Src : System.Address; Src_Size : access size_t; Options : System.Address) return size_t
     with Import, Convention => C, External_Name => "LZ4F_decompress";
   function LZ4F_isError (Code : size_t) return unsigned
     with Import, Convention => C, External_Name => "LZ4F_isError";
   function LZ4F_getErrorName (Code : size_t) return Strings.chars_ptr
     with Import, Convention => C, External_Name => "LZ4F_getErrorName";

   function Address_Of (Data : Byte_Array) return System.Address is
     (if Data'Length = 0 then System.Null_Address else Data (Data'First)'Address);

   -----------
   -- Bound --
   -----------

   function Bound (Kind : Compressing_Kind; Size : Ada.Streams.Stream_Element_Offset)
                   return Ada.Streams.Stream_Element_Offset is
   begin
      case Kind is
         when Zstd =>
            return RCL.Zstd.Compress_Bound (Size);
         when LZ4 =>
            return Ada.Streams.Stream_Element_Offset
              (LZ4F_compressFrameBound (size_t (Size), System.Null_Address));
      end case;
   end Bound;

   --------------
   -- Compress --
   --------------

   function Compress
     (Kind : Compressing_Kind; Data : Byte_Array; Into : in out Byte_Array)
      return Ada.Streams.Stream_Element_Offset
   is
      Result : size_t;
   begin
      case Kind is
         when Zstd =>
            return RCL.Zstd.Compress_Into (Data, Into, Level => 1);
         when LZ4 =>
            Result := LZ4F_compressFrame (Into (Into'First)'Address, Into'Length,
                                          Address_Of (Data), Data'Length, System.Null_Address);
            if LZ4F_isError (Result) /= 0 then
               raise Compression_Error with "lz4: " & Strings.Value (LZ4F_getErrorName (Result));
            end if;
            return Into'First + Ada.Streams.Stream_Element_Offset (Result) - 1;
      end case;
   exception
      when E : RCL.Zstd.Zstd_Error =>
         raise Compression_Error with Ada.Exceptions.Exception_Message (E);
   end Compress;

   ----------------
   -- Decompress --
   ----------------

   pragma Warnings (Off, "formal parameter ""Into"" is read but never assigned");
   procedure Decompress (Kind : Compressing_Kind; Data : Byte_Array; Into : out Byte_Array) is
      Result : size_t;
   begin
      case Kind is
         when Zstd =>
            declare
               Last : constant Ada.Streams.Stream_Element_Offset :=
                 RCL.Zstd.Decompress_Into (Data, Into);
            begin
               if Last /= Into'Last then
                  raise Compression_Error with "zstd: expands to"
                    & Ada.Streams.Stream_Element_Offset'Image (Last - Into'First + 1)
                    & " bytes, the chunk says" & Into'Length'Image;
               end if;
            end;
         when LZ4 =>
            declare
               Context  : aliased System.Address := System.Null_Address;
               Dst_Size : aliased size_t := Into'Length;
               Src_Size : aliased size_t := Data'Length;
               Ignored  : size_t;
            begin
               Result := LZ4F_createDecompressionContext (Context'Access, LZ4F_Version);
               if LZ4F_isError (Result) /= 0 then
                  raise Compression_Error with "lz4: "
                    & Strings.Value (LZ4F_getErrorName (Result));
               end if;
               Result := LZ4F_decompress (Context, Address_Of (Into), Dst_Size'Access,
                                          Address_Of (Data), Src_Size'Access,
                                          System.Null_Address);
               Ignored := LZ4F_freeDecompressionContext (Context);
               if LZ4F_isError (Result) /= 0 then
                  raise Compression_Error with "lz4: "
                    & Strings.Value (LZ4F_getErrorName (Result));
               elsif Result /= 0 or else Dst_Size /= Into'Length then
                  raise Compression_Error with "lz4: expands to" & Dst_Size'Image
                    & " bytes or more, the chunk says" & Into'Length'Image;
               end if;
            end;
      end case;
   exception
      when E : RCL.Zstd.Zstd_Error =>
         raise Compression_Error with Ada.Exceptions.Exception_Message (E);
   end Decompress;
   pragma Warnings (On, "formal parameter ""Into"" is read but never assigned");

end RCL.MCAP.Compression;
