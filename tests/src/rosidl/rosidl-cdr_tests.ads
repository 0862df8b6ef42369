--  Tests of the CDR codec (byte-exact vectors, error reports, a corpus of
--  corrupted buffers, random round trips of every bundled message type)
--  and, through ROSIDL.Dynamic.Tests, of dynamic messages.
with AUnit.Test_Suites;

package ROSIDL.CDR_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;
   --  Includes ROSIDL.Dynamic.Tests.Suite.

end ROSIDL.CDR_Tests;
