--  Tests of the ROS-time scheduler clock: a periodic component scheduled on
--  it is activated as the /clock messages published by the test advance the
--  time, not as the wall clock does.
with AUnit.Test_Suites;

package Sancta.Standard_Components.ROS_Clocks.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Standard_Components.ROS_Clocks.Tests;
