with RCL.MCAP.Buffers; use RCL.MCAP.Buffers;
--  DECLARATIONS
B      : Buffer;
Length : constant Interfaces.Unsigned_64 := 8;
