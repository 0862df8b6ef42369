--  The few functions of zstd.h (libzstd 1.4 and later) that RCL.Zstd uses.
--  Not for users.
with Interfaces.C;
with Interfaces.C.Strings;
with System;

private package RCL.Zstd.Thin is

   use Interfaces.C;

   type In_Buffer is record
      Src  : System.Address;
      Size : size_t;
      Pos  : size_t;
   end record
     with Convention => C;
   --  ZSTD_inBuffer.

   type Out_Buffer is record
      Dst  : System.Address;
      Size : size_t;
      Pos  : size_t;
   end record
     with Convention => C;
   --  ZSTD_outBuffer.

   ZSTD_e_continue : constant := 0;
   ZSTD_e_end      : constant := 2;
   ZSTD_c_compressionLevel : constant := 100;
   ZSTD_reset_session_only : constant := 1;

   function Create_DCtx return System.Address
     with Import, Convention => C, External_Name => "ZSTD_createDCtx";
   function Free_DCtx (Context : System.Address) return size_t
     with Import, Convention => C, External_Name => "ZSTD_freeDCtx";
   function DCtx_Reset (Context : System.Address; Directive : int) return size_t
     with Import, Convention => C, External_Name => "ZSTD_DCtx_reset";
   function Decompress_Stream
     (Context : System.Address; Output : access Out_Buffer; Input : access In_Buffer)
      return size_t
     with Import, Convention => C, External_Name => "ZSTD_decompressStream";
   function DStream_In_Size return size_t
     with Import, Convention => C, External_Name => "ZSTD_DStreamInSize";
   function DStream_Out_Size return size_t
     with Import, Convention => C, External_Name => "ZSTD_DStreamOutSize";

   function Create_CCtx return System.Address
     with Import, Convention => C, External_Name => "ZSTD_createCCtx";
   function Free_CCtx (Context : System.Address) return size_t
     with Import, Convention => C, External_Name => "ZSTD_freeCCtx";
   function CCtx_Set_Parameter (Context : System.Address; Parameter, Value : int) return size_t
     with Import, Convention => C, External_Name => "ZSTD_CCtx_setParameter";
   function Compress_Stream2
     (Context : System.Address; Output : access Out_Buffer; Input : access In_Buffer;
      End_Op : int) return size_t
     with Import, Convention => C, External_Name => "ZSTD_compressStream2";
   function CStream_In_Size return size_t
     with Import, Convention => C, External_Name => "ZSTD_CStreamInSize";
   function CStream_Out_Size return size_t
     with Import, Convention => C, External_Name => "ZSTD_CStreamOutSize";
   function Compress_Bound (Size : size_t) return size_t
     with Import, Convention => C, External_Name => "ZSTD_compressBound";
   function Compress_CCtx
     (Context : System.Address; Dst : System.Address; Capacity : size_t;
      Src : System.Address; Size : size_t; Level : int) return size_t
     with Import, Convention => C, External_Name => "ZSTD_compressCCtx";

   function Compress
     (Dst : System.Address; Capacity : size_t; Src : System.Address; Size : size_t;
      Level : int) return size_t
     with Import, Convention => C, External_Name => "ZSTD_compress";
   function Decompress
     (Dst : System.Address; Capacity : size_t; Src : System.Address; Size : size_t)
      return size_t
     with Import, Convention => C, External_Name => "ZSTD_decompress";
   --  One shot, each with a context of its own.

   function Get_Frame_Content_Size (Src : System.Address; Size : size_t)
                                    return Interfaces.C.unsigned_long_long
     with Import, Convention => C, External_Name => "ZSTD_getFrameContentSize";
   --  The size a frame's header records, or one of the two below.
   Content_Size_Unknown : constant Interfaces.C.unsigned_long_long :=
     Interfaces.C.unsigned_long_long'Last;
   Content_Size_Error   : constant Interfaces.C.unsigned_long_long :=
     Interfaces.C.unsigned_long_long'Last - 1;

   function Is_Error (Code : size_t) return unsigned
     with Import, Convention => C, External_Name => "ZSTD_isError";
   function Error_Name (Code : size_t) return Interfaces.C.Strings.chars_ptr
     with Import, Convention => C, External_Name => "ZSTD_getErrorName";

end RCL.Zstd.Thin;
