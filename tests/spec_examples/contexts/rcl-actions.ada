with RCL.Actions; use RCL.Actions;
use ROSIDL.Dynamic;
