with RCL.Zstd; use RCL.Zstd;
--  DECLARATIONS
Frame  : constant Byte_Array (1 .. 8) := [others => 0];
Buffer : Byte_Array (1 .. 64);
Last   : Stream_Element_Offset;
procedure Use_It (Plain : Byte_Array) is null;
