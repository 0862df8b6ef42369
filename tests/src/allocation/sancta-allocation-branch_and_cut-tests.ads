--  Tests of the branch-and-cut solver: equal to Held-Karp (Exact) on
--  random small TSP, ATSP, open and multi-robot MinSum problems, proven
--  TSPLIB optima, what it refuses, the gap at a time limit.
with AUnit.Test_Suites;

package Sancta.Allocation.Branch_And_Cut.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Allocation.Branch_And_Cut.Tests;
