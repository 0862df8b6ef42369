with Ada.Directories;
with AUnit.Assertions;        use AUnit.Assertions;
with Sancta.Allocation.Baselines;
with Sancta.Allocation.Exact;
with Sancta.Geometry;
with Suite_Support; use Suite_Support;

package body Sancta.Allocation.Test_Support.Plan_Tests is

   use type Interfaces.Unsigned_64;

   function Plan_Problem
     (Tasks, Robots : Positive; V : Variant; Seed : Interfaces.Unsigned_64)
      return Problem_Access
   is (Random_Problem (Tasks, Robots, (V with delta Plan_Trees => True), Seed));
   --  A random problem whose tasks 1 .. Tasks - 1 form one or two random
   --  AND/OR trees, task Tasks outside them.

   ---------------------------------------------------------------------------

   procedure Incremental_Equals_Recomputed (Unused : in out Fixture) is
      Variants : constant Variant_Array :=
        [Variant'(others => <>),
         (Closed => False, others => <>),
         (Asymmetric => True, Own_Factor => True, others => <>),
         (Closed => False, Own_Matrix => True, Own_Callback => True, others => <>),
         (Own_Callback => True, Infinite_Arcs => True, Heterogeneous => True, others => <>),
         (Alternatives => True, Frozen => Robot_1, Infeasible => True, others => <>),
         (Closed => False, Asymmetric => True, Heterogeneous => True, Own_Factor => True,
          Own_Matrix => True, Own_Callback => True, Infinite_Arcs => True,
          Infeasible => True, Alternatives => True, Frozen => Robot_1, others => <>)];

      procedure Check_One (P : Problem; V : Variant; C : Criterion; Seed : Interfaces.Unsigned_64)
      is
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
         O : Annealers.Options := Checked_Random_Walk (C, Seed, Iterations => 6_000);
         --  (The switch subtree's predicted costs are checked too.)
         Switched : Boolean := False;
      begin
         Assert (Check (P) = "", "bad test problem: " & Check (P));
         Annealers.Solve (P, O, A, S);
         Assert (S.Accepted > 300 or else Active_Count (P, A.Branch) < 6,
                 "too few moves applied:" & S.Accepted'Image
                 & " (seed" & Seed'Image & ", active tasks"
                 & Active_Count (P, A.Branch)'Image & ")");
         Assert (Validate (P, A) = "", "invalid: " & Validate (P, A));
         Switched := S.Switches > 0;
         Anneal_Checked (P, O, A, S);
         Assert (Switched or else V.Frozen /= None,
                 "the random walk never left the initial plan selection (seed"
                 & Seed'Image & ")");
      end Check_One;

      procedure Check_All is new For_Each_Random_Problem (Check_One);
   begin
      Check_All (Variants, Some_Criteria,
                 (Tasks => 19, Robots => 3, First_Seed => 3100, Plan_Trees => True));
   end Incremental_Equals_Recomputed;

   procedure Exact_Equals_Brute_Force (Unused : in out Fixture) is
      Variants : constant Variant_Array :=
        [Variant'(others => <>), (Closed => False, Asymmetric => True, others => <>),
         (Own_Factor => True, Own_Matrix => True, Heterogeneous => True, others => <>),
         (Alternatives => True, Frozen => Robot_1, Own_Callback => True, Min_Tasks => 1,
          others => <>)];
   begin
      Check_Exact_Equals_Brute_Force
        (Variants, (Tasks => 6, Robots => 2, First_Seed => 3500, Plan_Trees => True));
   end Exact_Equals_Brute_Force;

   procedure Annealer_Reaches_Optimum (Unused : in out Fixture) is
      Variants : constant Variant_Array :=
        [Variant'(others => <>),
         (Closed => False, Heterogeneous => True, Own_Factor => True, others => <>),
         (Asymmetric => True, Infeasible => True, Own_Matrix => True, others => <>),
         (Alternatives => True, Frozen => Robot_1, Own_Callback => True, others => <>)];
   begin
      Check_Annealer_Reaches_Optimum
        (Variants, (Tasks => 10, Robots => 3, First_Seed => 3900, Plan_Trees => True),
         Iterations => 60_000);
   end Annealer_Reaches_Optimum;

   --  One robot at (0, 0); OR: task 1 alone at (90, 0), or the compound
   --  alternative of tasks 2, 3, 4 around (60, 0). The cheapest-first
   --  estimate (one round trip per task) prefers task 1 (180 < 3 * 120), the
   --  true optimum is the compound one (about 130): the annealer must switch.
   procedure Switch_To_Compound (Unused : in out Fixture) is
      P : constant Problem_Access := Create (Locations => 5, Tasks => 4, Robots => 1);
      O, Alt : Positive;
      A : Assignment (1, 4);
      S : Annealers.Progress;
   begin
      Set_Euclidean (P.all, [1 => (0.0, 0.0), 2 => (90.0, 0.0), 3 => (60.0, 0.0),
                             4 => (60.0, 5.0), 5 => (60.0, Sancta.Geometry."-" (5.0))]);
      Set_Robot (P.all, 1, Start => 1, Closed => True);
      for T in 1 .. 4 loop
         Set_Task (P.all, T, T + 1);
      end loop;
      Add_Node (P.all, Or_Node, 0, O);
      Add_Plan_Task (P.all, O, 1);
      Add_Node (P.all, And_Node, O, Alt);
      for T in 2 .. 4 loop
         Add_Plan_Task (P.all, Alt, T);
      end loop;
      Assert (Check (P.all) = "", Check (P.all));
      Assert (Cheapest_Selection (P.all) (1) = 1, "estimate should prefer task 1");
      Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0, Iterations => 3_000,
                               Check => True, others => <>), A, S);
      Assert (Validate (P.all, A) = "", Validate (P.all, A));
      Assert (A.Branch (1) = 2 and then A.Length (1) = 3, "compound alternative not chosen");
      Assert (Evaluate (P.all, A, Min_Sum).Sum = 130,
              "cost" & Evaluate (P.all, A, Min_Sum).Sum'Image);
      Assert (Evaluate (P.all, Exact.Solve (P.all, Min_Sum), Min_Sum).Sum = 130, "exact");
      declare
         B : constant Assignment := Baselines.Solve (P.all, Baselines.Auction, Min_Sum);
      begin
         Assert (Validate (P.all, B) = "" and then B.Branch (1) = 1
                 and then Evaluate (P.all, B, Min_Sum).Sum = 180, "auction: cheapest-first");
      end;
      --  Frozen task 3 locks the OR node on the compound alternative.
      Freeze (P.all, 1, [1 => 3]);
      Assert (Is_Locked (P.all, 1) and then Default_Selection (P.all) (1) = 2, "locked");
      Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0, Iterations => 500,
                               Check => True, others => <>), A, S);
      Assert (Validate (P.all, A) = "" and then A.Tour (1, 1) = 3, "frozen prefix kept");
      Freeze (P.all, 1, [3, 1]);
      Assert (Check (P.all) /= "", "frozen tasks in exclusive alternatives accepted");
   end Switch_To_Compound;

   --  Per-robot cost functions: a slow robot, an unreachable task.
   function Blocked (R, From, To : Positive) return Cost is
     (if R = 1 and then To = 3 then Infinity else 10 * Cost (abs (From - To)));

   procedure Robot_Cost_Functions (Unused : in out Fixture) is
      P : constant Problem_Access := Create (Locations => 4, Tasks => 2, Robots => 2);
      A : Assignment (2, 2);
      S : Annealers.Progress;
   begin
      Set_Euclidean (P.all, [1 => (0.0, 0.0), 2 => (0.0, 0.0), 3 => (10.0, 0.0),
                             4 => (0.0, 20.0)]);
      Set_Robot (P.all, 1, Start => 1, Closed => True);
      Set_Robot (P.all, 2, Start => 2, Closed => True);
      Set_Task (P.all, 1, 3);
      Set_Task (P.all, 2, 4);
      Set_Robot_Factor (P.all, 2, 2.5);
      Append (A, 2, 1);
      Append (A, 1, 2);
      Assert (Tour_Cost (P.all, A, 2) = 50 and then Tour_Cost (P.all, A, 1) = 40,
              "factor: " & Tour_Cost (P.all, A, 2)'Image & Tour_Cost (P.all, A, 1)'Image);
      Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0, Iterations => 2_000,
                               Check => True, others => <>), A, S);
      Assert (Evaluate (P.all, A, Min_Sum).Sum = 52 and then A.Length (1) = 2,
              "the fast robot does both:" & Evaluate (P.all, A, Min_Sum).Sum'Image);
      --  Robot 1 cannot reach task 1's location (3): robot 2 must take it.
      Set_Robot_Costs (P.all, 1, Blocked'Access);
      Assert (Robot_Distance (P.all, 1, 1, 3) = Infinity and then Distance (P.all, 1, 3) = 10,
              "callback costs are robot 1's only");
      for C of Pure_Criteria loop
         Annealers.Solve (P.all, (Criterion => C, Time_Limit => 0.0, Iterations => 2_000,
                                  Check => True, others => <>), A, S);
         Assert (Validate (P.all, A) = ""
                 and then (for some K in 1 .. A.Length (2) => A.Tour (2, K) = 1),
                 "robot 2 must do task 1");
         Assert (Evaluate (P.all, A, C).Value = Evaluate (P.all, Exact.Solve (P.all, C), C).Value,
                 "annealer /= exact with a callback robot");
         for M in Baselines.Method loop
            Assert (not Is_Infinite (Evaluate (P.all, Baselines.Solve (P.all, M, C), C).Max),
                    M'Image & " used an unreachable arc");
         end loop;
      end loop;
   end Robot_Cost_Functions;

   procedure Mission_Plans (Unused : in out Fixture) is
      F : constant String := "obj/alloc-test-compound.xml";
      Head : constant String := "<mission scale=""10"">" & NL
        & "  <robot id=""ari"" x=""0"" y=""0""/>" & NL;
      Body_Text : constant String :=
        "  <robot id=""bo"" x=""0"" y=""0"" factor=""2"" metric=""manhattan""/>" & NL
        & "  <task id=""t1"" x=""1"" y=""0""/>" & NL
        & "  <plan>" & NL
        & "    <or id=""survey"" robots=""ari"">" & NL
        & "      <and> <task x=""2"" y=""0""/> <task x=""3"" y=""0""/> </and>" & NL
        & "      <task id=""far"" x=""50"" y=""50""/>" & NL
        & "      <or>" & NL
        & "        <and> <task x=""9"" y=""9""/>" & NL
        & "              <or> <at x=""8"" y=""0""/> <at x=""7"" y=""7""/> </or> </and>" & NL
        & "        <task x=""40"" y=""0""/>" & NL
        & "      </or>" & NL
        & "    </or>" & NL
        & "  </plan>" & NL;
   begin
      declare
         P : constant Problem_Access :=
           Mission_From (F, Head & Body_Text & "</mission>" & NL);
         E : constant Assignment := Exact.Solve (P.all, Min_Sum);
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
      begin
         Assert (P.Tasks = 7 and then Or_Count (P.all) = 2, "sizes:" & P.Tasks'Image
                 & Or_Count (P.all)'Image);
         Assert (Alternatives (P.all, 1) = 3 and then Alternatives (P.all, 2) = 2,
                 "alternatives");
         Assert (Task_Name (P.all, 3) = "survey.1.2" and then Task_Name (P.all, 4) = "far"
                 and then Task_Name (P.all, 6) = "survey.3.1.2", "names: "
                 & Task_Name (P.all, 3) & " " & Task_Name (P.all, 6));
         Assert (P.Alt_Count (6) = 2 and then P.Alt_Count (5) = 1, "flat OR in a compound");
         Assert (P.Task_Or (2) = 1 and then P.Task_Branch (2) = 1 and then P.Task_Or (5) = 2
                 and then P.Task_Branch (5) = 1 and then Or_Parent (P.all, 2) = 1
                 and then Or_Branch (P.all, 2) = 3 and then P.Task_Or (1) = 0, "tree shape");
         Assert (not P.Can_Do (2, 2) and then not P.Can_Do (2, 7) and then P.Can_Do (2, 1),
                 "robots= applies to the whole subtree");
         --  bo: Manhattan x factor 2 x scale 10; task survey.3.1.1 at (9, 9).
         Assert (Robot_Distance (P.all, 2, 2, Location_Of (P.all, 5)) = 360
                 and then Robot_Distance (P.all, 1, 1, Location_Of (P.all, 5)) = 127,
                 "own metric:" & Robot_Distance (P.all, 2, 2, Location_Of (P.all, 5))'Image);
         Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0,
                                  Iterations => 5_000, Check => True, others => <>), A, S);
         Assert (Validate (P.all, A) = "", Validate (P.all, A));
         Assert (Evaluate (P.all, A, Min_Sum).Value = Evaluate (P.all, E, Min_Sum).Value,
                 "annealer not optimal on the compound plan");
         Assert (A.Branch (1) = 1 and then E.Branch (1) = 1, "the near compound alternative");
         Assert (Evaluate (P.all, E, Min_Sum).Sum = 60, "cost"
                 & Evaluate (P.all, E, Min_Sum).Sum'Image);
      end;
      --  A task done in the nested alternative locks both OR nodes there.
      declare
         P : constant Problem_Access :=
           Mission_From (F, Head & Body_Text & "  <done robot=""ari"" tasks=""survey.3.2""/>" & NL
                         & "</mission>" & NL);
         E : constant Assignment := Exact.Solve (P.all, Min_Sum);
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
      begin
         Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0,
                                  Iterations => 5_000, Check => True, others => <>), A, S);
         Assert (Validate (P.all, A) = "" and then A.Branch (1) = 3 and then A.Branch (2) = 2
                 and then E.Branch (1) = 3, "locked by the done task");
         Assert (Evaluate (P.all, A, Min_Sum).Value = Evaluate (P.all, E, Min_Sum).Value,
                 "annealer not optimal with the lock");
      end;
      Expect_Mission_Error (F, Head & "  <or id=""e""/>" & NL & "</mission>" & NL,
                    F & ":3: <or id=""e""> has no alternative");
      Expect_Mission_Error (F, Head & "  <or id=""x"">" & NL & "    <at x=""1"" y=""1""/>" & NL
                    & "    <and/>" & NL & "  </or>" & NL & "</mission>" & NL,
                    F & ":6: alternative 2 (line 5) of <or id=""x""> has no task");
      Expect_Mission_Error (F, Head & "  <or id=""y"">" & NL & "    <at x=""1"" y=""1""/>" & NL
                    & "    <and> <task x=""1"" y=""1""/> <or> </or> </and>" & NL
                    & "  </or>" & NL & "</mission>" & NL,
                    F & ":5: <or id=""y""> has no alternative");
      Expect_Mission_Error (F, Head & "  <task id=""s.2"" x=""1"" y=""1""/>" & NL
                    & "  <or id=""s"">" & NL
                    & "    <and> <task x=""1"" y=""1""/> <task x=""2"" y=""1""/> </and>" & NL
                    & "    <task x=""5"" y=""5""/>" & NL & "  </or>" & NL & "</mission>" & NL,
                    F & ":6: task 's.2' defined twice (also line 3)");
      Expect_Mission_Error (F, Head & "  <robot id=""b"" x=""1"" y=""1"" factor=""-1""/>" & NL
                    & "</mission>" & NL,
                    F & ":3: <robot> factor='-1' is not a number in (0, 1e6]");
      Expect_Mission_Error (F, Head & "  <robot id=""b"" x=""1"" y=""1"" metric=""taxi""/>" & NL
                    & "</mission>" & NL,
                    F & ":3: <robot> metric='taxi' is not euclidean or manhattan");
      Expect_Mission_Error (F, Head & "  <plan>" & NL & "    <task id=""a"" x=""1"" y=""1"">" & NL
                    & "      <at x=""1"" y=""1""/>" & NL & "    </task>" & NL & "  </plan>" & NL
                    & "</mission>" & NL,
                    F & ":5: <at> must be inside <mission>, <and> or <or>");
      Expect_Mission_Error (F, Head & "  <or id=""d"">" & NL & "    <or> <or>" & NL
                    & "      <and> <task x=""1"" y=""1""/> <task x=""2"" y=""1""/> </and>" & NL
                    & "    </or> </or>" & NL & "  </or>" & NL & "</mission>" & NL,
                    F & ":4: more <or> nodes than tasks");
      --  Done tasks in exclusive alternatives.
      Expect_Mission_Error (F, Head & Body_Text & "  <done robot=""ari"" tasks=""far""/>" & NL
                            & "  <done robot=""bo"" tasks=""survey.1.1""/>" & NL
                            & "</mission>" & NL,
                            F & ":17: frozen task");
      Ada.Directories.Delete_File (F);
   end Mission_Plans;

   procedure Deterministic (Unused : in out Fixture) is
      P : constant Problem_Access := Plan_Problem (30, 4, (Own_Factor => True, others => <>), 77);
      A, B : Assignment (P.Robots, P.Tasks);
      S : Annealers.Progress;
      O : constant Annealers.Options :=
        (Criterion => Min_Max, Seed => 5, Time_Limit => 0.0, Iterations => 30_000,
         others => <>);
   begin
      Annealers.Solve (P.all, O, A, S);
      Annealers.Solve (P.all, O, B, S);
      Assert (A = B, "same seed, different plan-tree allocations");
      Assert (Validate (P.all, A) = "", Validate (P.all, A));
   end Deterministic;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
      procedure Add (Name : String; Proc : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("allocation plans: " & Name, Proc));
      end Add;
   begin
      Add ("incremental costs equal recomputed costs (plan trees, robot costs)",
           Incremental_Equals_Recomputed'Access);
      Add ("exact solver equals brute force over plan selections",
           Exact_Equals_Brute_Force'Access);
      Add ("annealer reaches the exact optimum; baselines valid",
           Annealer_Reaches_Optimum'Access);
      Add ("switch to a compound alternative; frozen tasks lock OR nodes",
           Switch_To_Compound'Access);
      Add ("per-robot cost functions", Robot_Cost_Functions'Access);
      Add ("mission XML: nested compound plans, robot metrics, errors", Mission_Plans'Access);
      Add ("same seed, same result with plan trees", Deterministic'Access);
      return Result;
   end Suite;

end Sancta.Allocation.Test_Support.Plan_Tests;
