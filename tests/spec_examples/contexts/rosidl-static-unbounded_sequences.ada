with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
--  DECLARATIONS
Scan : ROSIDL.Static.Sensor_Msgs.Messages.LaserScan.Message;
