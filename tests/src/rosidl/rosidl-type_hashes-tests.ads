--  Tests of the REP 2011 type hashes against the values ROS 2 Jazzy
--  publishes for standard messages.
with AUnit.Test_Suites;

package ROSIDL.Type_Hashes.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end ROSIDL.Type_Hashes.Tests;
