--  Tests of the interface parser, the search path and type support: every
--  bundled interface parses, specific definitions come out as ROS 2 has them,
--  and a corpus of malformed definitions each gives its error and position.
with AUnit.Test_Suites;

package ROSIDL.Parser.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end ROSIDL.Parser.Tests;
