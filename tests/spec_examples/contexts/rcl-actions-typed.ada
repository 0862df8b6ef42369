with RCL.Actions.Typed;
with RCL.Actions.Servers;
with ROSIDL.Static.Example_Interfaces.Actions.Fibonacci;
with ROSIDL.Static.Sequences; use ROSIDL.Static.Sequences;
use type Interfaces.Integer_32;
