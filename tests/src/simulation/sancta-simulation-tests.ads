--  Simulator core: ray casting and kinematics against analytic cases,
--  acceleration limits, collisions with walls and robots, robots seen by
--  lasers, kill/revive, odometry drift and determinism for a seed.
with AUnit.Test_Suites;

package Sancta.Simulation.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Simulation.Tests;
