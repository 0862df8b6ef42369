--  Tests of the robot components (Navigation, Localization) and their
--  message conversions (Robot_Messages), without processes: a
--  configuration (tests/data/config/robot-closed-loop.xml) wires them in a
--  node on a manual clock, and the test closes the loop with an in-process
--  simulator (sensor readings stored as the ROS 2 bridges would store them,
--  cmd_vel read back). Also the robot lists of sancta-sim.
with AUnit.Test_Suites;

package Sancta.Standard_Components.Navigation.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Standard_Components.Navigation.Tests;
