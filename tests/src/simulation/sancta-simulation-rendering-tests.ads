--  Rendering: the PNG picture (walls, trajectories, robots at the right
--  pixels), the SVG text, trajectories CSV round trip and errors, and the
--  map-server pair written from a world reading back the same world.
with AUnit.Test_Suites;

package Sancta.Simulation.Rendering.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Simulation.Rendering.Tests;
