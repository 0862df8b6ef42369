--  Tests of team missions over DDS (loopback): the team network's
--  destinations, channels and presence; the replicated database's
--  convergence under concurrent writes, late joiner and cut-off/rejoin;
--  mission files; plans; the team demo end to end with a robot lost, by
--  the annealer and by auctions (every task done exactly once).
with AUnit.Test_Suites;

package Sancta.Team.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Team.Tests;
