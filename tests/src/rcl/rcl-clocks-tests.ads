--  Tests of RCL.Clocks: steady/system clocks and ROS time following /clock.
with AUnit.Test_Suites;

package RCL.Clocks.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Clocks.Tests;
