with ROSIDL.Static.Bundled_Types;
