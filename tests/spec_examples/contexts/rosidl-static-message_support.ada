with ROSIDL.Static.Geometry_Msgs.Messages.Twist;
--  DECLARATIONS
Cmd : ROSIDL.Static.Geometry_Msgs.Messages.Twist.Message;
