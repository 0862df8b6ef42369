--  Unbounded sequences of the ROS 2 primitive types and strings, shared by
--  every generated message (a float64[] field is a
--  ROSIDL.Static.Sequences.Float64_Sequences.Sequence).
with Ada.Strings.Unbounded;
with Interfaces;
with Ada.Strings.Wide_Wide_Unbounded;
with ROSIDL.Static.Unbounded_Sequences;

package ROSIDL.Static.Sequences is

   package Bool_Sequences is new Unbounded_Sequences (Boolean, Bool_Array, False);
   package UInt8_Sequences is new Unbounded_Sequences (UInt8, UInt8_Array, 0, Interfaces."=");
   package Byte_Sequences renames UInt8_Sequences;
   package Char_Sequences renames UInt8_Sequences;
   package Int8_Sequences is new Unbounded_Sequences (Int8, Int8_Array, 0, Interfaces."=");
   package UInt16_Sequences is new Unbounded_Sequences (UInt16, UInt16_Array, 0, Interfaces."=");
   package Int16_Sequences is new Unbounded_Sequences (Int16, Int16_Array, 0, Interfaces."=");
   package UInt32_Sequences is new Unbounded_Sequences (UInt32, UInt32_Array, 0, Interfaces."=");
   package Int32_Sequences is new Unbounded_Sequences (Int32, Int32_Array, 0, Interfaces."=");
   package UInt64_Sequences is new Unbounded_Sequences (UInt64, UInt64_Array, 0, Interfaces."=");
   package Int64_Sequences is new Unbounded_Sequences (Int64, Int64_Array, 0, Interfaces."=");
   package Float32_Sequences is new Unbounded_Sequences
     (Float32, Float32_Array, 0.0, Interfaces."=");
   package Float64_Sequences is new Unbounded_Sequences
     (Float64, Float64_Array, 0.0, Interfaces."=");
   package String_Sequences is new Unbounded_Sequences
     (Ada.Strings.Unbounded.Unbounded_String, String_Array,
      Ada.Strings.Unbounded.Null_Unbounded_String, Ada.Strings.Unbounded."=");
   package WString_Sequences is new Unbounded_Sequences
     (Ada.Strings.Wide_Wide_Unbounded.Unbounded_Wide_Wide_String, WString_Array,
      Ada.Strings.Wide_Wide_Unbounded.Null_Unbounded_Wide_Wide_String,
      Ada.Strings.Wide_Wide_Unbounded."=");

end ROSIDL.Static.Sequences;
