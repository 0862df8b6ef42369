with ROSIDL.Interfaces; use ROSIDL.Interfaces;
with ROSIDL.Definitions; use ROSIDL.Definitions;
