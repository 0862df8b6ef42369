with ROSIDL.Static.Bounded_Sequences;
