with ROSIDL.Type_Hashes; use ROSIDL.Type_Hashes;
with ROSIDL.Interfaces;
