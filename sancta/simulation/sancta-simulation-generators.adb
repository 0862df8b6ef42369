with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Simulation.Generators is

   use Interfaces;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   procedure Split_Mix (X : in out Unsigned_64; Value : out Unsigned_64) is
      Z : Unsigned_64;
   begin
      X := X + 16#9E37_79B9_7F4A_7C15#;
      Z := X;
      Z := (Z xor Shift_Right (Z, 30)) * 16#BF58_476D_1CE4_E5B9#;
      Z := (Z xor Shift_Right (Z, 27)) * 16#94D0_49BB_1331_11EB#;
      Value := Z xor Shift_Right (Z, 31);
   end Split_Mix;

   function Create
     (Seed   : Unsigned_64;
      Stream : Unsigned_64 := 0) return Generator
   is
      X      : Unsigned_64 := Seed xor (Stream * 16#D1B5_4A32_D192_ED03#);
      Result : Generator;
   begin
      for I in Result.S'Range loop
         Split_Mix (X, Result.S (I));
      end loop;
      if Result.S = [0, 0, 0, 0] then
         Result.S (0) := 1;
      end if;
      return Result;
   end Create;

   procedure Next (This : in out Generator; Value : out Unsigned_64) is
      S : State renames This.S;
      T : constant Unsigned_64 := Shift_Left (S (1), 17);
   begin
      Value := Rotate_Left (S (1) * 5, 7) * 9;
      S (2) := S (2) xor S (0);
      S (3) := S (3) xor S (1);
      S (1) := S (1) xor S (2);
      S (0) := S (0) xor S (3);
      S (2) := S (2) xor T;
      S (3) := Rotate_Left (S (3), 45);
   end Next;

   function Uniform (This : in out Generator) return Real is
      V : Unsigned_64;
   begin
      Next (This, V);
      --  53 high bits scaled into [0, 1).
      return Real (Shift_Right (V, 11)) * 2.0 ** (-53);
   end Uniform;

   function Gaussian (This : in out Generator; Sigma : Real) return Real is
      U, V, S : Real;
   begin
      if Sigma <= 0.0 then
         return 0.0;
      end if;
      if This.Has_Spare then
         This.Has_Spare := False;
         return Sigma * This.Spare;
      end if;
      --  Marsaglia's polar method: two normal draws per accepted pair.
      loop
         U := 2.0 * Uniform (This) - 1.0;
         V := 2.0 * Uniform (This) - 1.0;
         S := U * U + V * V;
         exit when S > 0.0 and then S < 1.0;
      end loop;
      S := Math.Sqrt (-2.0 * Math.Log (S) / S);
      This.Spare := V * S;
      This.Has_Spare := True;
      return Sigma * U * S;
   end Gaussian;

end Sancta.Simulation.Generators;
