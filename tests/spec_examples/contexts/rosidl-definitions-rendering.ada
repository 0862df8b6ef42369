with ROSIDL.Definitions.Rendering; use ROSIDL.Definitions.Rendering;
with ROSIDL.Interfaces;
