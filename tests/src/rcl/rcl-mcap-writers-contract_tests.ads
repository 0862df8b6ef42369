--  The consistency rule of RCL.MCAP.Writers.Writer (its Type_Invariant):
--  kept by a run of writes, and an inconsistent writer refused.
with AUnit.Test_Suites;

package RCL.MCAP.Writers.Contract_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.MCAP.Writers.Contract_Tests;
