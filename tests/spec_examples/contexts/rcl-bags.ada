with RCL.Bags; use RCL.Bags;
with RCL.MCAP;
with RCL.QoS;
--  DECLARATIONS
Receive_Time : constant Time_Stamp := 0;
Cdr_Bytes    : constant RCL.MCAP.Byte_Array (1 .. 8) := [others => 0];
procedure Play (Topic : Topic_Index; Receive_Time : Time_Stamp;
                Data : RCL.MCAP.Byte_Array) is null;
