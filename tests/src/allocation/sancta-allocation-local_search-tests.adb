with AUnit.Assertions;        use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;
with Interfaces;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Exact;
with Sancta.Allocation.Random;
with Sancta.Allocation.TSPLIB;
with Sancta.Geometry;

package body Sancta.Allocation.Local_Search.Tests is

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;
   package Caller is new AUnit.Test_Caller (Fixture);

   --  Tasks at random points, one robot on a closed tour from point 1.
   function Scattered (Tasks : Positive; Seed : Interfaces.Unsigned_64) return Problem_Access is
      G : Random.Generator := Random.Seeded (Seed);
      P : constant Problem_Access := Create (Tasks + 1, Tasks, 1);
   begin
      Set_Euclidean (P.all, [for I in 1 .. Tasks + 1 =>
                               (Sancta.Geometry.Real (Random.Below (G, 1000)),
                                Sancta.Geometry.Real (Random.Below (G, 1000)))], 1.0);
      for T in 1 .. Tasks loop
         Set_Task (P.all, T, T + 1);
      end loop;
      return P;
   end Scattered;

   procedure Checked_Moves_And_Optima (Unused : in out Fixture) is
   begin
      for Seed in Interfaces.Unsigned_64 range 1 .. 6 loop
         declare
            P : constant Problem_Access := Scattered (10, Seed);
            A : Assignment := Annealers.Greedy_Start (P.all, Min_Sum, Seed);
            S : Statistics;
            Optimum : constant Cost :=
              Evaluate (P.all, Exact.Solve (P.all, Min_Sum), Min_Sum).Sum;
         begin
            Improve (P.all, A, 0.05, Seed, S, Check => True);
            Assert (Validate (P.all, A) = "", Validate (P.all, A));
            Assert (Evaluate (P.all, A, Min_Sum).Sum = S.After, "reported length");
            Assert (S.After <= S.Before, "longer after the search");
            Assert (S.After = Optimum, "seed" & Seed'Image & ":" & S.After'Image
                    & " /= Held-Karp" & Optimum'Image);
         end;
      end loop;
      declare
         P : constant Problem_Access := Scattered (300, 9);
         A : Assignment := Annealers.Greedy_Start (P.all, Min_Sum, 1);
         S : Statistics;
      begin
         Improve (P.all, A, 0.3, 1, S, Check => True);
         Assert (Validate (P.all, A) = "", "300 tasks: " & Validate (P.all, A));
         Assert (Evaluate (P.all, A, Min_Sum).Sum = S.After, "300 tasks: reported length");
      end;
   end Checked_Moves_And_Optima;

   procedure Near_KroA100_Optimum (Unused : in out Fixture) is
      P : constant Problem_Access :=
        TSPLIB.To_MTSP (TSPLIB.Read ("share/tsplib/kroA100.tsp").all, Robots => 1);
      A : Assignment := Annealers.Greedy_Start (P.all, Min_Sum, 1);
      S : Statistics;
   begin
      --  The optimum is 21282; a release build reaches it in well under
      --  a second, a loaded debug build at least comes within 2%.
      Improve (P.all, A, 2.0, 1, S);
      Assert (Validate (P.all, A) = "", Validate (P.all, A));
      Assert (S.After >= 21_282, "kroA100: shorter than the optimum:" & S.After'Image);
      Assert (S.After <= 21_282 * 102 / 100, "kroA100:" & S.After'Image & " > 2% above 21282");
   end Near_KroA100_Optimum;

   procedure Deterministic_Descent (Unused : in out Fixture) is
      P : constant Problem_Access := Scattered (80, 4);
      A : Assignment := Annealers.Greedy_Start (P.all, Min_Sum, 2);
      B : Assignment := A;
      S : Statistics;
   begin
      Improve (P.all, A, 0.0, 1, S);
      Improve (P.all, B, 0.0, 1, S);
      Assert (A = B, "one descent is not deterministic");
   end Deterministic_Descent;

   procedure Applies_Only_To_Tours (Unused : in out Fixture) is
      P : constant Problem_Access := Scattered (12, 1);
   begin
      Assert (Applies (P.all), "a closed symmetric tour");
      Set_Robot (P.all, 1, 1, Closed => False);
      Assert (not Applies (P.all), "an open tour");
      Set_Robot (P.all, 1, 1, Closed => True);
      Freeze (P.all, 1, [1 => 4]);
      Assert (not Applies (P.all), "a frozen prefix");
   end Applies_Only_To_Tours;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
      procedure Add (Name : String; Proc : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("local search: " & Name, Proc));
      end Add;
   begin
      Add ("checked moves; Held-Karp optima", Checked_Moves_And_Optima'Access);
      Add ("within 2% of the kroA100 optimum", Near_KroA100_Optimum'Access);
      Add ("one descent is deterministic", Deterministic_Descent'Access);
      Add ("applies to closed symmetric single tours only", Applies_Only_To_Tours'Access);
      return Result;
   end Suite;

end Sancta.Allocation.Local_Search.Tests;
