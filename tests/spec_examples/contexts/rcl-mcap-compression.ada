with RCL.MCAP.Compression; use RCL.MCAP.Compression;
--  DECLARATIONS
Chunk  : constant Byte_Array (1 .. 64) := [others => 0];
Buffer : Byte_Array (1 .. 256);
Last   : Stream_Element_Offset;
