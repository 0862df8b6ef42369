with RCL.YAML.Messages; use RCL.YAML.Messages;
use ROSIDL.Dynamic;
--  DECLARATIONS
Support : Message_Support;
