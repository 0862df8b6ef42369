with ROSIDL.Dynamic; use ROSIDL.Dynamic;
use type Interfaces.IEEE_Float_32;
--  DECLARATIONS
Scan : constant ROSIDL.Dynamic.Float32_Array (1 .. 720) := [others => 1.0];
