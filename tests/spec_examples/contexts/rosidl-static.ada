with ROSIDL.Static;
