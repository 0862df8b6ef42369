--  Tests of the iterated local search: the incremental tour length equals
--  the recomputed one after every move (expensive check), the optimum of
--  small instances (Held-Karp) is reached, kroA100 within 2%; one descent is
--  deterministic, what it does not apply to.
with AUnit.Test_Suites;

package Sancta.Allocation.Local_Search.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Allocation.Local_Search.Tests;
