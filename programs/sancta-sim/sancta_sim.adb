--  sancta-sim: the 2D multi-robot simulator on ROS 2; see
--  Sancta.Simulation.Sim_Tool.
with Sancta.Simulation.Sim_Tool;
with Sancta.Team.Interfaces;

procedure Sancta_Sim is
begin
   Sancta.Team.Interfaces.Ensure;  --  sancta_msgs/srv/SimControl
   Sancta.Simulation.Sim_Tool.Run;
end Sancta_Sim;
