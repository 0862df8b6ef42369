--  The filter's type invariant (a variance never negative, a gain a share):
--  kept by a run of predictions and corrections, and checked -- an
--  Assertion_Error -- when the state breaks it (as only a bug in the
--  package could: this child sees the private part).
with AUnit.Test_Suites;

package Sancta.Robot.GPS_Fusion.Contract_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Robot.GPS_Fusion.Contract_Tests;
