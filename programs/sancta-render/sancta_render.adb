--  sancta-render: pictures of worlds and robot trajectories (SVG, PNG);
--  see Sancta.Simulation.Render_Tool.
with Sancta.Simulation.Render_Tool;

procedure Sancta_Render is
begin
   Sancta.Simulation.Render_Tool.Run;
end Sancta_Render;
