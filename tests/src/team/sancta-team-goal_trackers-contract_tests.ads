--  The tracker's type invariant (only a robot sent somewhere holds a task):
--  kept by Decide, and checked -- an Assertion_Error -- on an idle tracker
--  that still names a task (the state behind the team demo's stall; this
--  child sees the private part to make it).
with AUnit.Test_Suites;

package Sancta.Team.Goal_Trackers.Contract_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Team.Goal_Trackers.Contract_Tests;
