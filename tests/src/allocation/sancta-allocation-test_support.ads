--  What the allocation test suites share: random problems (optionally with
--  AND/OR plan trees and per-robot costs), a brute-force optimum to check the
--  exact solver against, and helpers writing test files and expecting a
--  reader's Format_Error.
with Interfaces;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Test_Support is

   type Frozen_Prefixes is (None, Robot_1, Robots_1_And_2);
   --  Robot_1: robot 1 starts with task 1 done; Robots_1_And_2: robot 2
   --  also with tasks 2 and 4 (when there are two robots and four tasks).

   type Variant is record
      Closed        : Boolean := True;
      Asymmetric    : Boolean := False;
      Heterogeneous : Boolean := False;
      Own_Factor    : Boolean := False;
      --  Robot 1 is 1.7 times slower (its own matrix).
      Own_Matrix    : Boolean := False;
      --  Robot 2 has an explicit asymmetric matrix of its own.
      Own_Callback  : Boolean := False;
      --  The last robot's costs come from a callback ...
      Infinite_Arcs : Boolean := False;
      --  ... with some unreachable arcs.
      Infeasible    : Boolean := False;
      Alternatives  : Boolean := False;
      Frozen        : Frozen_Prefixes := None;
      Min_Tasks     : Natural := 0;
      End_Depot     : Boolean := False;
      --  Each robot ends at the next robot's start (the last one: open).
      Plan_Trees    : Boolean := False;
      --  Tasks 1 .. Tasks - 1 form one or two random AND/OR trees.
   end record;

   function Random_Problem
     (Tasks, Robots : Positive; V : Variant; Seed : Interfaces.Unsigned_64)
      return Problem_Access;
   --  Robots start at their own locations, tasks at random points (with a
   --  second alternative location for even tasks when V.Alternatives); with
   --  V.Plan_Trees, tasks 1 .. Tasks - 1 form random AND/OR trees (OR
   --  alternatives are single tasks or subtrees of several: compound tasks).
   --  The same arguments give the same problem.
   --  Example: P := Random_Problem (5, 2, (Closed => False, others => <>), 501);

   function Scattered
     (Tasks  : Positive;
      Seed   : Interfaces.Unsigned_64;
      Robots : Positive := 1) return Problem_Access;
   --  Tasks at random points (integer coordinates below 1000), Robots robots
   --  on closed tours from point 1, Euclidean costs.

   function Brute_Force (P : Problem; C : Criterion) return Long_Float;
   --  The optimum of P under C by enumeration: every plan selection, every
   --  order of its active tasks cut into robot tours, every choice of
   --  alternative locations. For a handful of tasks only.

   function Img (X : Long_Float) return String is (X'Image);

   type Criterion_Array is array (Positive range <>) of Criterion;
   Pure_Criteria : constant Criterion_Array := [Min_Sum, Min_Max, Min_Ave];
   Some_Criteria : constant Criterion_Array :=
     [Min_Sum, Min_Max, Min_Ave, Min_Mix, (0.5, 0.25, 2.0)];
   --  The pure ones and two mixes.

   function Checked_Random_Walk
     (C : Criterion; Seed : Interfaces.Unsigned_64; Iterations : Long_Long_Integer)
      return Annealers.Options
   is ((Criterion => C, Seed => Seed, Time_Limit => 0.0, Iterations => Iterations,
        Check => True, Start_Temperature => 1.0E15, End_Temperature => 1.0E14,
        Polish => False, Adaptive => False, others => <>));
   --  A near random walk (a huge temperature: most moves apply) with the
   --  expensive check after every move.

   procedure Solve_Checked
     (P    : Problem;
      O    : Annealers.Options;
      A    : in out Assignment;
      S    : out Annealers.Progress;
      What : String := "");
   --  Annealers.Solve (P, O, A, S), then what every annealer test checks of
   --  the result: A is valid and S.Best, the reported best, is A's value
   --  under O.Criterion recomputed (within 1.0E-6). A failure's message
   --  starts with What.
   --  Example: Solve_Checked (P.all, O, B, T, What => "in reheats");

   procedure Anneal_Checked
     (P : Problem; O : in out Annealers.Options; A : in out Assignment;
      S : out Annealers.Progress);
   --  A real annealing run from A (no temperature, polish), with O's checks:
   --  A must stay valid and the reported best equal the recomputed cost.

   type Variant_Array is array (Positive range <>) of Variant;

   type Random_Problems is record
      Tasks, Robots : Positive;
      First_Seed    : Interfaces.Unsigned_64;
      Plan_Trees    : Boolean;
   end record;
   --  The random problems a check makes: Tasks tasks and Robots robots
   --  each, seeds First_Seed + 1, + 2, ..., tasks 1 .. Tasks - 1 in AND/OR
   --  plan trees or not.
   --  Example: (Tasks => 5, Robots => 2, First_Seed => 500, Plan_Trees => False)

   generic
      with procedure Check (P : Problem; V : Variant; C : Criterion; Seed : Interfaces.Unsigned_64);
   procedure For_Each_Random_Problem
     (Variants : Variant_Array;
      Criteria : Criterion_Array;
      Problems : Random_Problems);
   --  Check, for every variant V and every criterion C in turn, the next
   --  of Problems (P, made with seed Seed).

   procedure Check_Annealer_Reaches_Optimum
     (Variants   : Variant_Array;
      Problems   : Random_Problems;
      Iterations : Long_Long_Integer);
   --  For_Each_Random_Problem with the pure criteria: the annealer's result
   --  after Iterations moves is valid and reaches the exact solver's optimum
   --  (else both tours of each robot are printed and the test fails); every
   --  baseline's result is valid and no better.

   procedure Check_Exact_Equals_Brute_Force
     (Variants : Variant_Array; Problems : Random_Problems);
   --  For_Each_Random_Problem with the pure criteria (with plan trees, each
   --  problem has an OR node): the exact solver's result is valid and as
   --  good as Brute_Force's optimum.

   NL : constant String := [1 => ASCII.LF];

   procedure Write (File, Text : String);
   --  Creates (or replaces) File holding Text.

   generic
      with function Read (File : String) return Problem_Access;
   procedure Expect_Read_Error (File, Text, Expect : String);
   --  Writes Text to File; Read must raise Format_Error with a message
   --  containing Expect (else the test fails).

   function Mission_From (File, Text : String) return Problem_Access;
   --  Writes Text to File and reads it as a mission (Problem_Files.Read).

   procedure Expect_Mission_Error (File, Text, Expect : String);
   --  Expect_Read_Error for mission files (Problem_Files.Read).

end Sancta.Allocation.Test_Support;
