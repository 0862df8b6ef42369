--  Tests of hierarchical AND/OR plans (compound alternatives) and per-robot
--  cost functions in the task allocation engine: incremental costs against
--  full recomputation with the switch subtree move, exact solver against
--  brute force over plan selections, annealer against the exact solver,
--  baselines' validity, mission files with nested compound plans. A child
--  of Test_Support: its random problems, checks and context.
with AUnit.Test_Suites;

package Sancta.Allocation.Test_Support.Plan_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Allocation.Test_Support.Plan_Tests;
