with ROSIDL.Static.Storage; use ROSIDL.Static.Storage;
with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
with GNAT.Debug_Pools;
--  DECLARATIONS
My_Pool : aliased GNAT.Debug_Pools.Debug_Pool;
Scan    : ROSIDL.Static.Sensor_Msgs.Messages.LaserScan.Message;
