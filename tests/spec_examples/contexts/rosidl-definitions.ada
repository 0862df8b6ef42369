with ROSIDL.Definitions; use ROSIDL.Definitions;
with ROSIDL.Interfaces;
