--  Generated (static) message types: the Ada records that the generator
--  (bin/rosidl_generate, ros2/generator) writes for every interface type,
--  and the array and sequence types their fields use. A message
--  <pkg>/msg/<Type> becomes the package ROSIDL.Static.<Pkg>.Messages.<Type>
--  holding the record Message, its constants and its CDR codec; a service
--  <pkg>/srv/<Srv> becomes ROSIDL.Static.<Pkg>.Services.<Srv> with nested
--  packages Request and Response (see the README, "Generated types"):
--  Example:
--     with ROSIDL.Static.Geometry_Msgs.Messages.Twist;
--     package Twist renames ROSIDL.Static.Geometry_Msgs.Messages.Twist;
--     Cmd   : Twist.Message := (Linear => (X => 0.5, others => <>), others => <>);
--     Bytes : constant Stream_Element_Array := Twist.Encode (Cmd);
--
--  Field types: ROS 2 primitives are the subtypes of package ROSIDL; string
--  is Unbounded_String and string<=N an instance of
--  Ada.Strings.Bounded.Generic_Bounded_Length (N) (wstring: the
--  Wide_Wide_ versions); T[N] is a constrained <T>_Array (0 .. N - 1); T[]
--  an Unbounded_Sequences instance, T[<=N] a Bounded_Sequences instance.
--  Indices start at 0, as in ROS 2.
with Ada.Strings.Unbounded;
with Ada.Strings.Wide_Wide_Unbounded;

package ROSIDL.Static is

   type Bool_Array is array (Natural range <>) of aliased Boolean;
   type UInt8_Array is array (Natural range <>) of aliased UInt8;
   subtype Byte_Array is UInt8_Array;
   subtype Char_Array is UInt8_Array;
   --  ROS 2 byte, char and uint8 are all Interfaces.Unsigned_8.
   type Int8_Array is array (Natural range <>) of aliased Int8;
   type Int16_Array is array (Natural range <>) of aliased Int16;
   type UInt16_Array is array (Natural range <>) of aliased UInt16;
   type Int32_Array is array (Natural range <>) of aliased Int32;
   type UInt32_Array is array (Natural range <>) of aliased UInt32;
   type Int64_Array is array (Natural range <>) of aliased Int64;
   type UInt64_Array is array (Natural range <>) of aliased UInt64;
   type Float32_Array is array (Natural range <>) of aliased Float32;
   type Float64_Array is array (Natural range <>) of aliased Float64;
   type String_Array is array (Natural range <>)
     of aliased Ada.Strings.Unbounded.Unbounded_String;
   type WString_Array is array (Natural range <>)
     of aliased Ada.Strings.Wide_Wide_Unbounded.Unbounded_Wide_Wide_String;

   function Infinity return Float64;
   function Infinity return Float32;
   function NaN return Float64;
   function NaN return Float32;
   --  For default values written "inf", "-inf" or "nan" in a definition.

end ROSIDL.Static;
