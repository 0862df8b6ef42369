with Ada.Characters.Latin_1; use Ada.Characters.Latin_1;
with ROSIDL.Parser;
with ROSIDL.Definitions; use ROSIDL.Definitions;
