--  Every suite of the simulator and of the robot algorithms, registered in
--  All_Suites by one line.
with AUnit.Test_Suites;

package Simulation_Suites is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Simulation_Suites;
