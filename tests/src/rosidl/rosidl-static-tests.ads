--  Tests of the generated message types (ROSIDL.Static.*): for every type
--  of share/ros2_interfaces, tests/interfaces and the user package
--  tests/data/user_interfaces, the generated codec against the dynamic one
--  byte for byte on random values in both byte orders, round trips,
--  defaults, type hashes; malformed input; the records as a user writes
--  them.
with AUnit.Test_Suites;

package ROSIDL.Static.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end ROSIDL.Static.Tests;
