--  Tests of RCL.Timers: the drift-free grid, cancel and reset.
with AUnit.Test_Suites;

package RCL.Timers.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Timers.Tests;
