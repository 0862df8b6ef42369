--  Context of every spec example (see ../extract.py): what a program using
--  the library typically has at hand.
with Ada.Text_IO; use Ada.Text_IO;
with Ada.Streams; use Ada.Streams;
with Ada.Strings.Unbounded; use Ada.Strings.Unbounded;
with Interfaces;
with RCL.Nodes;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport; use ROSIDL.Typesupport;
use RCL;
--  DECLARATIONS
Node    : Nodes.Node;
Msg     : ROSIDL.Dynamic.Message;
Bytes   : Stream_Element_Array (1 .. 8) := [others => 0];
