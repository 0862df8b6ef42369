--  sancta-sim: the 2D multi-robot simulator on ROS 2; see
--  Sancta.Simulation.Sim_Tool.
with Sancta.Simulation.Sim_Tool;
with Sancta.Team.Interface_Paths;

procedure Sancta_Sim is
begin
   Sancta.Team.Interface_Paths.Ensure;  --  sancta_msgs/srv/SimControl
   Sancta.Simulation.Sim_Tool.Run;
end Sancta_Sim;
