--  A small, fast, seeded pseudo-random generator (xoshiro256**, seeded by
--  splitmix64) with uniform and Gaussian draws. Each robot of the simulator
--  owns one, seeded from the run's seed and the robot's number, so that a
--  run is reproducible and adding a robot does not disturb the others.
--
--     G : Generator := Create (Seed => 42, Stream => 3);
--     X : constant Real := Gaussian (G, Sigma => 0.01);
with Interfaces;
with Sancta.Geometry; use Sancta.Geometry;

package Sancta.Simulation.Generators
  with Pure
is

   type Generator is private;

   function Create
     (Seed   : Interfaces.Unsigned_64;
      Stream : Interfaces.Unsigned_64 := 0) return Generator;
   --  Distinct (Seed, Stream) pairs give independent sequences.

   procedure Next (This : in out Generator; Value : out Interfaces.Unsigned_64);
   --  The next 64 raw bits.

   function Uniform (This : in out Generator) return Real
     with Post => Uniform'Result >= 0.0 and then Uniform'Result < 1.0;
   --  Uniform in [0, 1).

   function Gaussian (This : in out Generator; Sigma : Real) return Real;
   --  Normal with mean 0 and standard deviation Sigma (0 when Sigma <= 0,
   --  without consuming the sequence).

private

   type State is array (0 .. 3) of Interfaces.Unsigned_64;

   type Generator is record
      S         : State := [1, 2, 3, 4];
      Spare     : Real := 0.0;
      Has_Spare : Boolean := False;
   end record;

end Sancta.Simulation.Generators;
