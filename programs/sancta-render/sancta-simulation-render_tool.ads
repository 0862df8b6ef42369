--  The sancta-render program: draws a world (map-server YAML or wall
--  world) with trajectories, robots and points of interest to SVG and PNG,
--  optionally after simulating a team (--demo), and converts a wall world
--  to a map-server pair (--rasterize).
--
--     sancta-render share/worlds/office.yaml --demo 6 --png team.png --svg team.svg
--     sancta-render share/worlds/office.walls --rasterize share/worlds/office
--     sancta-render world.yaml --trajectories run.csv --poi 3,4,dock --png run.png
package Sancta.Simulation.Render_Tool is

   procedure Run;
   --  Reads the command line; sets the exit status (failure with a message
   --  on standard error for bad arguments or files).

end Sancta.Simulation.Render_Tool;
