--  Tests of the periodic scheduler on a manual clock: the logical order of
--  calls, drift-free periods, overruns and "cannot keep up", failure
--  policies (retry / stop) and event-driven components.
with AUnit.Test_Suites;

package Sancta.Runtime.Schedulers.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Runtime.Schedulers.Tests;
