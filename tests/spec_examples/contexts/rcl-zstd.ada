with RCL.Zstd; use RCL.Zstd;
--  DECLARATIONS
Frame : constant Byte_Array (1 .. 8) := [others => 0];
procedure Use_It (Plain : Byte_Array) is null;
