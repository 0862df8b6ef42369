--  Tests of the conversions between ROS 2 messages and SANCTA values made
--  by the bridge components (the wire side is tested by
--  tests/interop/test_runtime_bridges.py).
with AUnit.Test_Suites;

package Sancta.Standard_Components.ROS2.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Standard_Components.ROS2.Tests;
