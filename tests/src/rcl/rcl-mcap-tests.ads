--  Tests of RCL.MCAP: writer and reader round trips (each compression,
--  several chunks, time ranges), and every truncation and single-byte
--  corruption of a small file giving Format_Error with a byte offset.
with AUnit.Test_Suites;

package RCL.MCAP.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.MCAP.Tests;
