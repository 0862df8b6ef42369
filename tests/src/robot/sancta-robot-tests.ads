--  Robot algorithms, alone and in closed loop with the simulator (no ROS):
--  path costs (A*, inflation, 4/8 connectivity), the executor, the
--  controller's free distances, a robot reaching a goal through a corridor
--  without collision, the mapper's agreement with the world, scan matching
--  beating drifting odometry, the aligner and GPS fusion.
with AUnit.Test_Suites;

package Sancta.Robot.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Robot.Tests;
