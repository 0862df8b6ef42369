--  World files and images: zlib on known streams, the checksums,
--  PNG encode/decode round trip, PGM (P5, P2) and PNG (gray, RGB, palette,
--  every filter) map loading into worlds, wall worlds, and clear errors on
--  bad files (fixtures in tests/data/simulation, made by make_fixtures.py).
with AUnit.Test_Suites;

package Sancta.Simulation.Map_Files.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Simulation.Map_Files.Tests;
