--  sancta-sim: the 2D multi-robot simulator on ROS 2; see
--  Sancta.Simulation.Sim_Tool.
with Sancta.Simulation.Sim_Tool;

procedure Sancta_Sim is
begin
   Sancta.Simulation.Sim_Tool.Run;
end Sancta_Sim;
