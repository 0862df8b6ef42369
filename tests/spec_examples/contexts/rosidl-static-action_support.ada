with ROSIDL.Static.Example_Interfaces.Actions.Fibonacci;
