--  Tests of the task allocation engine: incremental costs against full
--  recomputation (all criteria and problem variants), annealer against the
--  exact solver, exact solver against brute force, baselines' validity,
--  TSPLIB readers against the published optimal tours, mission files,
--  determinism.
with AUnit.Test_Suites;

package Sancta.Allocation.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Allocation.Tests;
