with RCL.MCAP; use RCL.MCAP;
with RCL.MCAP.Writers;
--  DECLARATIONS
S   : Schema_Id;
C   : Channel_Id;
Now : constant Interfaces.Unsigned_64 := 1_700_000_000_000_000_000;
