--  The embedded 2D multi-robot simulator: worlds (occupancy grids from ROS
--  map-server files or wall lists), differential-drive robots with lasers,
--  odometry and GPS, a simulation clock, and image files for rendering.
--
--     W : constant Worlds.World := Map_Files.Load ("share/worlds/office.yaml");
--     S : Simulators.Simulator;
--     S.Initialize (W, Seed => 42);
--     R := S.Add_Robot (Simulators.Default_Robot, Start => (1.0, 1.0, 0.0));
--     S.Set_Command (R, (Linear_X => 0.5, Angular_Z => 0.0));
--     S.Step (0.1);
package Sancta.Simulation
  with Pure
is

   Format_Error : exception;
   --  A world, map or image file is malformed. The message starts with
   --  "file:line: " (text files) or "file: byte N: " (binary files) and
   --  says what was expected.

end Sancta.Simulation;
