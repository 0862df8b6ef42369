package body Sancta.Allocation.Random is

   use Interfaces;

   function Seeded (Seed : Unsigned_64) return Generator is
      Z : Unsigned_64 := Seed + 16#9E37_79B9_7F4A_7C15#;
   begin
      Z := (Z xor Shift_Right (Z, 30)) * 16#BF58_476D_1CE4_E5B9#;
      Z := (Z xor Shift_Right (Z, 27)) * 16#94D0_49BB_1331_11EB#;
      Z := Z xor Shift_Right (Z, 31);
      return (State => (if Z = 0 then 1 else Z));
   end Seeded;

   procedure Next (This : in out Generator; Value : out Unsigned_64) is
      X : Unsigned_64 := This.State;
   begin
      X := X xor Shift_Right (X, 12);
      X := X xor Shift_Left (X, 25);
      X := X xor Shift_Right (X, 27);
      This.State := X;
      Value := X * 16#2545_F491_4F6C_DD1D#;
   end Next;

   function Below (This : in out Generator; N : Positive) return Natural is
      V : Unsigned_64;
   begin
      Next (This, V);
      return Natural (Unsigned_32 (Shift_Right (V, 32)) mod Unsigned_32 (N));
      --  The high 32 bits modulo N, in 32 bits (a shorter division than
      --  in 64, the same value).
   end Below;

   function Uniform (This : in out Generator) return Long_Float is
      V : Unsigned_64;
   begin
      Next (This, V);
      return Long_Float (Shift_Right (V, 11)) / 9_007_199_254_740_992.0;
   end Uniform;

end Sancta.Allocation.Random;
