--  The type invariant of Scan_Points (one index entry per beam, each
--  naming that beam's point): kept by To_Points, and checked -- an
--  Assertion_Error -- on an index that no longer matches its points (as
--  only a bug in the package could make: this child sees the private part).
with AUnit.Test_Suites;

package Sancta.Robot.Scan_Matchers.Contract_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Robot.Scan_Matchers.Contract_Tests;
