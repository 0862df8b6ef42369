--  Re-planning after a robot loss: the start is the current plan (frozen
--  prefixes kept, survivors' orders kept, the lost robot's tasks inserted),
--  the quality is recorded over time; budgets from 50 ms are honoured.
with AUnit.Test_Suites;

package Sancta.Allocation.Replanning.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Allocation.Replanning.Tests;
