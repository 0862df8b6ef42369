--  For generated code: the support the packages written by rosidl_generate
--  (ros2/generator) call, and nothing a hand-written program needs. Its
--  children are the XCDR1 primitives (Wire, Wire.Primitives) and the codec
--  of each ROS 2 primitive type (Codecs); the body codec of every generated
--  message (Size_Body, Write_Body, Read_Body, the actuals of its Handling
--  package) and Unbounded_Sequences.Storage are the other parts of this
--  contract. Programs use the generated types' Encode / Decode and
--  ROSIDL.Static.Message_Support instead; these packages may change with the
--  generator.
package ROSIDL.Static.Impl is
end ROSIDL.Static.Impl;
