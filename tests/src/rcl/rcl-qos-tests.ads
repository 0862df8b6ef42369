--  Tests of RCL.QoS: the ROS 2 profiles and custom settings on DDS.
with AUnit.Test_Suites;

package RCL.QoS.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.QoS.Tests;
