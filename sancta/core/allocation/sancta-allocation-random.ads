--  The allocator's own pseudo-random generator (xorshift64*, seeded through
--  splitmix64): runs are reproducible for a seed on every platform, and the
--  state is a plain value (no hidden global state, one per annealer).
with Interfaces;

package Sancta.Allocation.Random
  with Pure
is

   type Generator is record
      State : Interfaces.Unsigned_64 := 16#9E37_79B9_7F4A_7C15#;
   end record;

   function Seeded (Seed : Interfaces.Unsigned_64) return Generator;

   procedure Next (This : in out Generator; Value : out Interfaces.Unsigned_64)
     with Inline;

   function Below (This : in out Generator; N : Positive) return Natural
     with Inline, Post => Below'Result < N;
   --  Uniform in 0 .. N - 1 (up to a negligible bias).

   function Uniform (This : in out Generator) return Long_Float
     with Inline, Post => Uniform'Result >= 0.0 and then Uniform'Result < 1.0;

end Sancta.Allocation.Random;
