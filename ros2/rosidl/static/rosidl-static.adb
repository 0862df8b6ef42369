pragma Validity_Checks (Off);
--  Floats may be NaN or infinite (ROS 2 data, definitions).
with Ada.Unchecked_Conversion;

package body ROSIDL.Static is

   function To_64 is new Ada.Unchecked_Conversion (UInt64, Float64);
   function To_32 is new Ada.Unchecked_Conversion (UInt32, Float32);

   function Infinity return Float64 is (To_64 (16#7FF0_0000_0000_0000#));
   function Infinity return Float32 is (To_32 (16#7F80_0000#));
   function NaN return Float64 is (To_64 (16#7FF8_0000_0000_0000#));
   function NaN return Float32 is (To_32 (16#7FC0_0000#));

end ROSIDL.Static;
