with RCL.MCAP; use RCL.MCAP;
with RCL.MCAP.Writers; use RCL.MCAP.Writers;
--  DECLARATIONS
Cdr_Bytes : constant Byte_Array (1 .. 8) := [others => 0];
