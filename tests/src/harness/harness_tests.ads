--  Checks of the test harness itself: assertions must be enabled, or every
--  contract and pragma Assert in the code under test is silently skipped.
with AUnit.Test_Suites;

package Harness_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Harness_Tests;
