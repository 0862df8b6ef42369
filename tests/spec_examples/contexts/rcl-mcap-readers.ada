with RCL.MCAP; use RCL.MCAP;
with RCL.MCAP.Readers; use RCL.MCAP.Readers;
--  DECLARATIONS
procedure Print (Msg : Message; Data : Byte_Array) is null;
