with Ada.Directories;
with Ada.Exceptions;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with AUnit.Assertions;        use AUnit.Assertions;
with Interfaces;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Baselines;
with Sancta.Allocation.Exact;
with Sancta.Allocation.Giant_Tours;
with Sancta.Allocation.Problem_Files;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;
with Sancta.Allocation.Random;
with Sancta.Allocation.Test_Support; use Sancta.Allocation.Test_Support;
with Sancta.Allocation.TSPLIB;
with Sancta.Geometry;
with Suite_Support; use Suite_Support;

package body Sancta.Allocation.Tests is

   use type Interfaces.Unsigned_64;

   Data : constant String := "share/tsplib/";

   ---------------------------------------------------------------------------

   procedure Incremental_Equals_Recomputed (Unused : in out Fixture) is
      Variants : constant Variant_Array :=
        [Variant'(others => <>), (End_Depot => True, Asymmetric => True, others => <>),
         (Closed => False, others => <>),
         (Asymmetric => True, others => <>),
         (Heterogeneous => True, Closed => False, others => <>),
         (Infeasible => True, others => <>),
         (Alternatives => True, others => <>),
         (Frozen => Robots_1_And_2, Min_Tasks => 1, others => <>),
         (Closed => False, Asymmetric => True, Heterogeneous => True, Infeasible => True,
          Alternatives => True, Frozen => Robots_1_And_2, Min_Tasks => 1, others => <>)];

      procedure Check_One (P : Problem; V : Variant; C : Criterion; Seed : Interfaces.Unsigned_64)
      is
         pragma Unreferenced (V);
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
         O : Annealers.Options := Checked_Random_Walk (C, Seed, Iterations => 3_000);
      begin
         Annealers.Solve (P, O, A, S);
         Assert (S.Accepted > 1_000, "too few moves applied:" & S.Accepted'Image);
         Assert (Validate (P, A) = "", "invalid: " & Validate (P, A));
         --  Then a real annealing run, still checked.
         Anneal_Checked (P, O, A, S);
      end Check_One;

      procedure Check_All is new For_Each_Random_Problem (Check_One);
   begin
      Check_All (Variants, Some_Criteria,
                 (Tasks => 18, Robots => 3, First_Seed => 100, Plan_Trees => False));
   end Incremental_Equals_Recomputed;

   procedure Exact_Equals_Brute_Force (Unused : in out Fixture) is
      Variants : constant Variant_Array :=
        [Variant'(others => <>), (Closed => False, Asymmetric => True, others => <>),
         (End_Depot => True, Heterogeneous => True, others => <>),
         (Alternatives => True, Heterogeneous => True, others => <>),
         (Infeasible => True, Min_Tasks => 1, others => <>)];
   begin
      Check_Exact_Equals_Brute_Force
        (Variants, (Tasks => 5, Robots => 2, First_Seed => 500, Plan_Trees => False));
   end Exact_Equals_Brute_Force;

   procedure Annealer_Reaches_Optimum (Unused : in out Fixture) is
      Variants : constant Variant_Array :=
        [Variant'(others => <>), (Closed => False, Heterogeneous => True, others => <>),
         (End_Depot => True, Infeasible => True, others => <>),
         (Asymmetric => True, Infeasible => True, Min_Tasks => 1, others => <>),
         (Alternatives => True, Frozen => Robots_1_And_2, others => <>)];
   begin
      Check_Annealer_Reaches_Optimum
        (Variants, (Tasks => 9, Robots => 3, First_Seed => 900, Plan_Trees => False),
         Iterations => 40_000);
   end Annealer_Reaches_Optimum;

   procedure Baselines_Valid_On_Larger (Unused : in out Fixture) is
      P : constant Problem_Access :=
        Random_Problem (60, 5, (Infeasible => True, Frozen => Robots_1_And_2, Min_Tasks => 2,
                                Closed => False, others => <>), 77);
   begin
      for M in Baselines.Method loop
         declare
            B : constant Assignment := Baselines.Solve (P.all, M, Min_Max);
         begin
            Assert (Validate (P.all, B) = "", M'Image & " invalid: " & Validate (P.all, B));
         end;
      end loop;
   end Baselines_Valid_On_Larger;

   procedure Anytime_Box (Unused : in out Fixture) is
      P : constant Problem_Access := TSPLIB.To_MTSP (TSPLIB.Read (Data & "eil51.tsp").all, 2);
      Box : aliased Annealers.Best_Box (P.Robots, P.Tasks);
      A : Assignment (P.Robots, P.Tasks);
      S : Annealers.Progress;
   begin
      Assert (not Box.Has_Value, "box filled before the run");
      Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0, Iterations => 5_000,
                               Box => Box'Unchecked_Access, others => <>), A, S);
      Assert (Box.Has_Value and then Box.Best = A and then Box.Value = S.Best,
              "the box does not hold the final best");
   end Anytime_Box;

   procedure Deterministic (Unused : in out Fixture) is
      P : constant Problem_Access := TSPLIB.To_MTSP (TSPLIB.Read (Data & "eil51.tsp").all, 3);
      O : constant Annealers.Options :=
        (Criterion => Min_Max, Seed => 42, Time_Limit => 0.0, Iterations => 10_000,
         others => <>);
      A, B : Assignment (P.Robots, P.Tasks);
      S : Annealers.Progress;
   begin
      Annealers.Solve (P.all, O, A, S);
      Annealers.Solve (P.all, O, B, S);
      Assert (A = B, "two runs with the same seed differ");
      Assert (Validate (P.all, A) = "", Validate (P.all, A));
   end Deterministic;

   --  The route search inside the anneal (every Route_Search_Interval x
   --  tasks moves) and the makespan search's squared-cost term, under the
   --  expensive check (recomputed costs and sum of squares after every
   --  move and every route search): run, applied, deterministic.
   procedure Route_Search_In_Anneal (Unused : in out Fixture) is
      P : constant Problem_Access := TSPLIB.To_MTSP (TSPLIB.Read (Data & "eil51.tsp").all, 3);
      Moves : constant := 20_000;
      use Annealers;
   begin
      for C of Criterion_Array'[Min_Sum, Min_Max] loop
         declare
            O : constant Options :=
              (Criterion => C, Seed => 5, Time_Limit => 0.0, Iterations => Moves,
               Check => True, Square_Balance => 0.1, others => <>);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            Off : Options := O;
         begin
            Solve_Checked (P.all, O, A, S);
            Assert (S.Kinds (Route_Search).Tries
                      >= Long_Long_Integer (Moves / (Route_Search_Interval * P.Tasks) - 1),
                    "route searches:" & S.Kinds (Route_Search).Tries'Image);
            Assert (S.Kinds (Route_Search).Improving > 0, "no route search shortened a route");
            Solve (P.all, O, B, T);
            Assert (A = B, "two runs with the same seed differ");
            Off.Enabled (Route_Search) := False;
            Solve (P.all, Off, B, T);
            Assert (T.Kinds (Route_Search).Tries = 0, "route search ran while disabled");
         end;
      end loop;
   end Route_Search_In_Anneal;

   --  The hybrid schedule (geometric, then reheats from the best) under the
   --  expensive check, for the makespan and the total: valid, the reported
   --  best is the allocation's value, deterministic for a seed; it is not
   --  the geometric run (same seed and moves) from the start (its own cooling).
   procedure Hybrid_Schedule (Unused : in out Fixture) is
      P : constant Problem_Access := TSPLIB.To_MTSP (TSPLIB.Read (Data & "eil76.tsp").all, 3);
      use Annealers;
   begin
      for C of Criterion_Array'[Min_Max, Min_Sum] loop
         declare
            O : constant Options :=
              (Criterion => C, Seed => 11, Time_Limit => 0.0, Iterations => 60_000,
               Schedule => Hybrid, Geometric_Share => 0.3, Check => True, others => <>);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            Plain : Options := O;
         begin
            Solve_Checked (P.all, O, A, S);
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "two runs with the same seed differ");
            Plain.Schedule := Geometric;
            Solve (P.all, Plain, B, T);
            Assert (A /= B, "the hybrid run equals the geometric one");
            Plain.Schedule := Hybrid;
            Plain.Geometric_Share := 1.5;
            begin
               Solve (P.all, Plain, B, T);
               Assert (False, "a geometric share of 1.5 was accepted");
            exception
               when E : Constraint_Error =>
                  Assert (Ada.Exceptions.Exception_Message (E)
                            = "annealer: Geometric_Share 1.50000000000000E+00 is not in 0 .. 1",
                          Ada.Exceptions.Exception_Message (E));
            end;
         end;
      end loop;
   end Hybrid_Schedule;

   ---------------------------------------------------------------------------

   procedure Optimal_Tours (Unused : in out Fixture) is
      type Case_Info is record
         Name : String (1 .. 8);
         Opt  : Cost;
      end record;
      Cases : constant array (1 .. 5) of Case_Info :=
        [Case_Info'("eil51   ", 426), ("berlin52", 7542), ("eil76   ", 538), ("kroA100 ", 21282),
         ("eil101  ", 629)];
   begin
      for C of Cases loop
         declare
            N : constant String := Ada.Strings.Fixed.Trim (C.Name, Ada.Strings.Right);
            P : constant Problem_Access := TSPLIB.Read (Data & N & ".tsp");
            T : constant Location_Array := TSPLIB.Read_Tour (Data & N & ".opt.tour");
         begin
            Assert (T'Length = P.Locations, N & ": tour length /= dimension");
            Assert (TSPLIB.Tour_Length (P.all, T) = C.Opt,
                    N & ":" & TSPLIB.Tour_Length (P.all, T)'Image & " /=" & C.Opt'Image);
         end;
      end loop;
      --  ATSP explicit full matrix.
      declare
         P : constant Problem_Access := TSPLIB.Read (Data & "br17.atsp");
      begin
         Assert (P.Locations = 17, "br17 dimension");
         Assert (Distance (P.all, 1, 2) = 3 and then Distance (P.all, 4, 1) = 48, "br17 matrix");
      end;
   end Optimal_Tours;

   procedure Explicit_Formats (Unused : in out Fixture) is
      --  The symmetric matrix d(i,j) = 10 i + 10 j for i /= j, 4 nodes.
      function Header (F : String) return String is
        ("NAME: t" & NL & "TYPE: TSP" & NL & "DIMENSION: 4" & NL
         & "EDGE_WEIGHT_TYPE: EXPLICIT" & NL & "EDGE_WEIGHT_FORMAT: " & F & NL
         & "EDGE_WEIGHT_SECTION" & NL);
      type Body_Info is record
         Format : String (1 .. 14);
         Values : String (1 .. 48);
      end record;
      Cases : constant array (1 .. 5) of Body_Info :=
        [Body_Info'("FULL_MATRIX   ", "0 30 40 50 30 0 50 60 40 50 0 70 50 60 70       "),
         ("UPPER_ROW     ", "30 40 50 50 60 70                               "),
         ("LOWER_ROW     ", "30 40 50 50 60 70                               "),
         ("UPPER_DIAG_ROW", "0 30 40 50 0 50 60 0 70 0                       "),
         ("LOWER_DIAG_ROW", "0 30 0 40 50 0 50 60 70 0                       ")];
      File : constant String := "obj/alloc-test-explicit.tsp";
   begin
      for C of Cases loop
         declare
            F : constant String := Ada.Strings.Fixed.Trim (C.Format, Ada.Strings.Right);
            Extra : constant String := (if F = "FULL_MATRIX" then " 0" else "");
         begin
            Write (File, Header (F) & C.Values & Extra & NL & "EOF" & NL);
            declare
               P : constant Problem_Access := TSPLIB.Read (File);
            begin
               for I in 1 .. 4 loop
                  for J in 1 .. 4 loop
                     Assert (Distance (P.all, I, J) = (if I = J then 0 else Cost (10 * (I + J))),
                             F & ": d (" & I'Image & "," & J'Image & ") ="
                             & Distance (P.all, I, J)'Image);
                  end loop;
               end loop;
            end;
         end;
      end loop;
   end Explicit_Formats;

   procedure Pseudo_Euclidean_And_Geo (Unused : in out Fixture) is
      File : constant String := "obj/alloc-test-att.tsp";
   begin
      --  ATT: r = sqrt ((dx^2 + dy^2) / 10), rounded up when nint (r) < r.
      Write (File, "NAME: a" & NL & "TYPE: TSP" & NL & "DIMENSION: 3" & NL
             & "EDGE_WEIGHT_TYPE: ATT" & NL & "NODE_COORD_SECTION" & NL
             & "1 0 0" & NL & "2 10 0" & NL & "3 0 40" & NL & "EOF" & NL);
      declare
         P : constant Problem_Access := TSPLIB.Read (File);
      begin
         Assert (Distance (P.all, 1, 2) = 4, "ATT sqrt (10) -> 4:" & Distance (P.all, 1, 2)'Image);
         Assert (Distance (P.all, 1, 3) = 13,
                 "ATT sqrt (160) -> 13:" & Distance (P.all, 1, 3)'Image);
      end;
      --  GEO: DDD.MM coordinates; one degree of latitude along a meridian
      --  is 111.3 km on TSPLIB's sphere (int (6378.388 * pi / 180 + 1) = 112).
      Write (File, "NAME: g" & NL & "TYPE: TSP" & NL & "DIMENSION: 2" & NL
             & "EDGE_WEIGHT_TYPE: GEO" & NL & "NODE_COORD_SECTION" & NL
             & "1 10.00 20.00" & NL & "2 11.00 20.00" & NL & "EOF" & NL);
      declare
         P : constant Problem_Access := TSPLIB.Read (File);
      begin
         Assert (Distance (P.all, 1, 2) = 112, "GEO one degree:" & Distance (P.all, 1, 2)'Image);
      end;
   end Pseudo_Euclidean_And_Geo;

   function Read_TSPLIB (File : String) return Problem_Access is (TSPLIB.Read (File));
   procedure Expect_Error is new Expect_Read_Error (Read_TSPLIB);

   procedure Bad_Files (Unused : in out Fixture) is
      F : constant String := "obj/alloc-test-bad.tsp";
   begin
      Expect_Error (F, "NAME: x" & NL & "DIMENSION: 3" & NL & "EDGE_WEIGHT_TYPE: EUC_2D" & NL
                    & "NODE_COORD_SECTION" & NL & "1 0 0" & NL & "2 1 x" & NL,
                    F & ":6: expected a number for y");
      Expect_Error (F, "NAME: x" & NL & "DIMENSION: 3" & NL & "EDGE_WEIGHT_TYPE: EUC_2D" & NL
                    & "NODE_COORD_SECTION" & NL & "1 0 0" & NL & "2 1 1" & NL,
                    "end of file");
      Expect_Error (F, "DIMENSION: 3" & NL & "BOGUS: 1" & NL, F & ":2: unknown keyword");
      Expect_Error (F, "DIMENSION: 3" & NL & "EDGE_WEIGHT_TYPE: EUC_2D" & NL
                    & "NODE_COORD_SECTION" & NL & "1 0 0" & NL & "7 1 1" & NL
                    & "3 1 1" & NL,
                    F & ":5: node number 7 outside");
      if Ada.Directories.Exists ("obj/no-such-file.tsp") then
         Ada.Directories.Delete_File ("obj/no-such-file.tsp");
      end if;
      begin
         declare
            P : constant Problem_Access := TSPLIB.Read ("obj/no-such-file.tsp");
            pragma Unreferenced (P);
         begin
            Assert (False, "no error for a missing file");
         end;
      exception
         when E : Format_Error =>
            Assert (Ada.Exceptions.Exception_Message (E) = "obj/no-such-file.tsp:1: no such file",
                    Ada.Exceptions.Exception_Message (E));
      end;
   exception
      when Ada.Text_IO.Use_Error | Ada.Text_IO.Name_Error =>
         null;
   end Bad_Files;

   procedure Mission_File (Unused : in out Fixture) is
      F : constant String := "obj/alloc-test-mission.xml";
   begin
      declare
         P : constant Problem_Access :=
           Mission_From (F, "<?xml version=""1.0""?>" & NL
                         & "<mission scale=""10"">" & NL
                         & "  <robot id=""ari"" x=""0"" y=""0""/>" & NL
                         & "  <robot id=""ben"" x=""10"" y=""0"" return=""false"" cost=""2""/>"
                         & NL
                         & "  <task id=""t1"" x=""1"" y=""0""/>" & NL
                         & "  <task id=""t2"" x=""9"" y=""0"" robots=""ben""/>" & NL
                         & "  <or id=""door""><at x=""100"" y=""100""/><at x=""2"" y=""0""/></or>"
                         & NL
                         & "  <done robot=""ari"" tasks=""t1""/>" & NL
                         & "</mission>" & NL);
         E : constant Assignment := Exact.Solve (P.all, Min_Sum);
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
      begin
         Assert (P.Robots = 2 and then P.Tasks = 3, "sizes");
         Assert (P.Alt_Count (3) = 2 and then not P.Can_Do (1, 2), "OR node / restriction");
         Assert (P.Frozen_Length (1) = 1 and then P.Frozen (1, 1) = 1, "frozen prefix");
         Assert (Distance (P.all, 1, 3) = 10, "scaled distance:" & Distance (P.all, 1, 3)'Image);
         Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0,
                                  Iterations => 5_000, Check => True, others => <>), A, S);
         Assert (Evaluate (P.all, A, Min_Sum).Value = Evaluate (P.all, E, Min_Sum).Value,
                 "annealer not optimal on the mission");
         Assert (A.Choice (3) = 2, "the near door alternative must be chosen");
      end;
      Expect_Mission_Error (F, "<mission>" & NL & "  <robot id=""a"" x=""0""/>" & NL
                            & "</mission>" & NL,
                            F & ":2: <robot> needs attribute 'y'");
      Write (F, "<mission>" & NL & "  <robot id=""a"" x=""0"" y=""0"">" & NL & "</mission>" & NL);
      begin
         declare
            P : constant Problem_Access := Problem_Files.Read (F);
            pragma Unreferenced (P);
         begin
            Assert (False, "malformed XML not reported");
         end;
      exception
         when E : Format_Error =>
            Assert (Ada.Strings.Fixed.Index (Ada.Exceptions.Exception_Message (E), F & ":") = 1,
                    "message: " & Ada.Exceptions.Exception_Message (E));
      end;
      Ada.Directories.Delete_File (F);
   end Mission_File;

   procedure Nested_Plans (Unused : in out Fixture) is
      F : constant String := "obj/alloc-test-plan.xml";
      Head : constant String := "<mission scale=""10"">" & NL
        & "  <robot id=""ari"" x=""0"" y=""0""/>" & NL;
   begin
      declare
         P : constant Problem_Access :=
           Mission_From (F, Head
                         & "  <plan>" & NL
                         & "    <task id=""t1"" x=""1"" y=""0""/>" & NL
                         & "    <and>" & NL
                         & "      <or id=""door"" robots=""ari"">" & NL
                         & "        <or><at x=""100"" y=""100""/><task x=""50"" y=""50""/></or>"
                         & NL
                         & "        <and><task x=""2"" y=""0""/></and>" & NL
                         & "      </or>" & NL
                         & "      <and><task id=""t3"" x=""5"" y=""0""/></and>" & NL
                         & "    </and>" & NL
                         & "  </plan>" & NL
                         & "</mission>" & NL);
         E : constant Assignment := Exact.Solve (P.all, Min_Sum);
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
      begin
         Assert (P.Robots = 1 and then P.Tasks = 3, "sizes:" & P.Tasks'Image);
         Assert (P.Alt_Count (1) = 1 and then P.Alt_Count (2) = 3
                 and then P.Alt_Count (3) = 1, "nested OR alternatives flattened");
         Assert (Distance (P.all, 1, Location_Of (P.all, 2, 3)) = 20,
                 "third alternative at (2, 0)");
         Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0,
                                  Iterations => 5_000, Check => True, others => <>), A, S);
         Assert (Evaluate (P.all, A, Min_Sum).Value = Evaluate (P.all, E, Min_Sum).Value,
                 "annealer not optimal on the nested plan");
         Assert (A.Choice (2) = 3 and then E.Choice (2) = 3, "the near door must be chosen");
      end;
      declare
         P : constant Problem_Access :=
           Mission_From (F, Head
                         & "  <robot id=""bo"" x=""0"" y=""0"" end_x=""10"" end_y=""0""/>" & NL
                         & "  <task id=""t"" x=""0"" y=""5"" robots=""bo""/>" & NL
                         & "</mission>" & NL);
         E : constant Assignment := Exact.Solve (P.all, Min_Sum);
      begin
         --  bo: (0, 0) -> (0, 5) -> its end depot (10, 0): 50 + nint (111.8).
         Assert (P.Finish (1) = 1 and then P.Finish (2) = P.Locations, "end depot location");
         Assert (Evaluate (P.all, E, Min_Sum).Sum = 162,
                 "cost with the end depot" & Evaluate (P.all, E, Min_Sum).Sum'Image);
      end;
      Expect_Mission_Error
        (F, Head & "  <robot id=""b"" x=""1"" y=""1"" end_x=""2""/>" & NL & "</mission>" & NL,
         F & ":3: <robot> needs attribute 'end_y'");
      Expect_Mission_Error
        (F, Head & "  <robot id=""b"" x=""1"" y=""1"" return=""false"" end_x=""2"" end_y=""2""/>"
         & NL & "</mission>" & NL,
         F & ":3: <robot> end_x/end_y with return='false'");
      Expect_Mission_Error
        (F, Head & "  <and>" & NL & "    <robot id=""b"" x=""1"" y=""1""/>" & NL
         & "  </and>" & NL & "</mission>" & NL,
         F & ":4: <robot> must be a child of <mission>");
      Expect_Mission_Error
        (F, Head & "  <task id=""t"" x=""1"" y=""1"">" & NL & "    <and/>" & NL
         & "  </task>" & NL & "</mission>" & NL,
         F & ":4: <and> must be inside <mission>, <and> or <or>");
      Expect_Mission_Error
        (F, Head & "  <or id=""e"">" & NL & "    <and/>" & NL & "  </or>" & NL
         & "</mission>" & NL,
         "<or id=""e""> has no alternative");
      Expect_Mission_Error
        (F, Head & "  <or id=""r""><task x=""1"" y=""1"" robots=""ari""/></or>" & NL
         & "</mission>" & NL,
         F & ":3: <task> inside <or>: put 'robots' on the outermost <or>");
      Ada.Directories.Delete_File (F);
   end Nested_Plans;

   procedure End_Depots (Unused : in out Fixture) is
      P : constant Problem_Access := Create (Locations => 3, Tasks => 1, Robots => 1);
      A : Assignment (1, 1);
      S : Annealers.Progress;
   begin
      --  Start (0, 0), end depot (10, 0), task (0, 5): 5 + nint (11.18) = 16;
      --  a closed tour would cost 10.
      Set_Euclidean (P.all, [1 => (0.0, 0.0), 2 => (10.0, 0.0), 3 => (0.0, 5.0)]);
      Set_Robot (P.all, 1, Start => 1, Closed => True);
      Set_Task (P.all, 1, Location => 3);
      Set_Robot_End (P.all, 1, 2);
      Assert (Is_Closed (P.all, 1), "an end depot is a closed tour");
      Annealers.Solve (P.all, (Criterion => Min_Sum, Time_Limit => 0.0, Iterations => 100,
                               Check => True, others => <>), A, S);
      Assert (Evaluate (P.all, A, Min_Sum).Max = 16, "evaluated"
              & Evaluate (P.all, A, Min_Sum).Max'Image);
      Assert (S.Best = 16.0, "annealer's best" & Img (S.Best));
      Assert (Evaluate (P.all, Exact.Solve (P.all, Min_Sum), Min_Sum).Max = 16, "exact");
      Set_Robot_End (P.all, 1, Nowhere);
      Assert (not Is_Closed (P.all, 1)
              and then Evaluate (P.all, A, Min_Sum).Max = 5, "open tour");
   end End_Depots;

   ---------------------------------------------------------------------------
   --  Each neighbourhood alone, as a near random walk with the expensive
   --  check after every applied move (the move's predicted costs against a
   --  recomputation): it must be applied often and never mispredict.

   procedure Each_Move_Kind_Checked (Unused : in out Fixture) is
      use Annealers;
      Variants : constant array (1 .. 5) of Variant :=
        [Variant'(others => <>),
         (Asymmetric => True, Closed => False, others => <>),
         (Frozen => Robots_1_And_2, Min_Tasks => 1, Infeasible => True, others => <>),
         (End_Depot => True, Heterogeneous => True, Alternatives => True, others => <>),
         (Closed => False, Asymmetric => True, Heterogeneous => True, Infeasible => True,
          Alternatives => True, Frozen => Robots_1_And_2, Min_Tasks => 1, others => <>)];
      Kinds : constant array (1 .. 7) of Move_Kind :=
        [Or_Opt_Near, Two_Opt_Near, Or3_Near, Cross_Near, Log_Auction, Guided_Move,
         Ruin_Recreate];
      --  Guided_Move: for makespan criteria mostly neighbour moves out of
      --  the longest tour.
      Seed : Interfaces.Unsigned_64 := 3_000;
   begin
      for K of Kinds loop
         for V of Variants loop
            for C of Pure_Criteria loop
               Seed := Seed + 1;
               declare
                  P : constant Problem_Access := Random_Problem (24, 3, V, Seed);
                  A : Assignment (P.Robots, P.Tasks);
                  S : Progress;
                  O : Options :=
                    (Criterion => C, Seed => Seed, Time_Limit => 0.0, Iterations => 3_000,
                     Check => True, Start_Temperature => 1.0E15, End_Temperature => 1.0E14,
                     Polish => False, Adaptive => False, Ruin_Share => 0.0,
                     Enabled => [others => False], others => <>);
               begin
                  O.Enabled (K) := True;
                  Solve (P.all, O, A, S);
                  Assert (S.Kinds (K).Accepted > 10,
                          K'Image & " applied only" & S.Kinds (K).Accepted'Image
                          & " times of" & S.Kinds (K).Tries'Image);
                  for Other in Move_Kind loop
                     Assert (Other = K or else S.Kinds (Other).Tries = 0,
                             Other'Image & " drawn while only " & K'Image & " is enabled");
                  end loop;
                  Assert (Validate (P.all, A) = "", K'Image & ": " & Validate (P.all, A));
                  --  Then descending with this kind only (tiny temperature).
                  O.Start_Temperature := 1.0E-6;
                  O.End_Temperature := 1.0E-7;
                  O.Initial := True;
                  declare
                     Before : constant Long_Float := Evaluate (P.all, A, C).Value;
                  begin
                     Solve (P.all, O, A, S);
                     Assert (Validate (P.all, A) = "", K'Image & ": " & Validate (P.all, A));
                     Assert (Evaluate (P.all, A, C).Value <= Before,
                             K'Image & " descent made it worse");
                  end;
               end;
            end loop;
         end loop;
      end loop;
   end Each_Move_Kind_Checked;

   --  Ejection chains (makespan criteria) under the expensive check after
   --  every applied and every undone step, in a random walk (so that the
   --  tours stay unbalanced) and in the final descent, on random problems
   --  of every variant: they run, many lower the objective, the result is
   --  valid and the same for a seed; none run for the total alone or when
   --  disabled.
   procedure Ejection_Chains_Checked (Unused : in out Fixture) is
      use Annealers;
      Variants : constant array (1 .. 7) of Variant :=
        [Variant'(others => <>),
         (Asymmetric => True, Closed => False, others => <>),
         (Frozen => Robots_1_And_2, Min_Tasks => 2, Infeasible => True, others => <>),
         (End_Depot => True, Heterogeneous => True, Alternatives => True, others => <>),
         (Own_Factor => True, Own_Matrix => True, Own_Callback => True,
          Infinite_Arcs => True, others => <>),
         (Plan_Trees => True, others => <>),
         (Closed => False, Asymmetric => True, Heterogeneous => True, Infeasible => True,
          Alternatives => True, Frozen => Robots_1_And_2, Min_Tasks => 1, others => <>)];
      Seed : Interfaces.Unsigned_64 := 4_000;
      Improving : Long_Long_Integer := 0;
   begin
      for V of Variants loop
         for C of Criterion_Array'[Min_Max, Min_Mix, Min_Sum] loop
            Seed := Seed + 1;
            declare
               P : constant Problem_Access := Random_Problem (40, 5, V, Seed);
               A, B : Assignment (P.Robots, P.Tasks);
               S : Progress;
               O : Options :=
                 (Criterion => C, Seed => Seed, Time_Limit => 0.0, Iterations => 20_000,
                  Check => True, Start_Temperature => 1.0E15, End_Temperature => 1.0E14,
                  Adaptive => False, Ruin_Share => 0.0, Chain_Share => 0.9,
                  Enabled => [Random_Move | Ejection_Chain => True, others => False],
                  others => <>);
               Tries : Long_Long_Integer;
            begin
               Solve_Checked (P.all, O, A, S);
               Tries := S.Kinds (Ejection_Chain).Tries;
               if C.Max_Weight = 0.0 then
                  Assert (Tries = 0, "chains for the total alone:" & Tries'Image);
               else
                  Assert (Tries > 3, "chains tried only" & Tries'Image & " times");
                  Improving := Improving + S.Kinds (Ejection_Chain).Improving;
               end if;
               Solve (P.all, O, B, S);
               Assert (A = B, "two runs with the same seed differ");
               O.Enabled (Ejection_Chain) := False;
               Solve (P.all, O, B, S);
               Assert (S.Kinds (Ejection_Chain).Tries = 0, "chains ran while disabled");
            end;
         end loop;
      end loop;
      Assert (Improving > 30, "only" & Improving'Image & " chains lowered the objective");
   end Ejection_Chains_Checked;

   --  The makespan search's squared excess over a floor below the best
   --  makespan (Options.Excess_Weight), under the expensive check after
   --  every move (the incremental sum of squared excesses recomputed, also
   --  after each new best moves the floor), on random problems of every
   --  variant, with the hybrid schedule: valid, the reported best is the
   --  allocation's makespan, the same for a seed, another search than
   --  without the term, and than with the term kept in the reheats
   --  (Excess_In_Reheats; valid too), which changes nothing under the
   --  geometric schedule; a band outside 0 .. 1 is refused.
   procedure Excess_Term_Checked (Unused : in out Fixture) is
      use Annealers;
      Variants : constant array (1 .. 6) of Variant :=
        [Variant'(others => <>),
         (Asymmetric => True, Closed => False, others => <>),
         (Frozen => Robots_1_And_2, Min_Tasks => 2, others => <>),
         (End_Depot => True, Heterogeneous => True, Alternatives => True, others => <>),
         (Own_Factor => True, Own_Matrix => True, Own_Callback => True, others => <>),
         (Plan_Trees => True, others => <>)];
      Seed : Interfaces.Unsigned_64 := 4_500;
      Differs, Reheats_Differ : Natural := 0;
   begin
      for V of Variants loop
         Seed := Seed + 1;
         declare
            P : constant Problem_Access := Random_Problem (40, 5, V, Seed);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => Min_Max, Seed => Seed, Time_Limit => 0.0, Iterations => 20_000,
               Schedule => Hybrid, Check => True, Excess_Weight => 1.0, Excess_Band => 0.03,
               others => <>);
         begin
            Solve_Checked (P.all, O, A, S);
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "two runs with the same seed differ");
            O.Excess_In_Reheats := True;
            Solve_Checked (P.all, O, B, T, What => "in reheats");
            if A /= B then
               Reheats_Differ := Reheats_Differ + 1;
            end if;
            O.Schedule := Geometric;
            Solve (P.all, O, A, S);
            O.Excess_In_Reheats := False;
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "Excess_In_Reheats acted without reheats");
            O.Excess_Weight := 0.0;
            Solve (P.all, O, B, T);
            if A /= B then
               Differs := Differs + 1;
            end if;
         end;
      end loop;
      Assert (Differs >= 5, "the excess term changed the search on" & Differs'Image & " of 6");
      Assert (Reheats_Differ >= 2,
              "the term in the reheats changed the search on" & Reheats_Differ'Image & " of 6");
      declare
         P : constant Problem_Access := Random_Problem (10, 2, (others => <>), 1);
         A : Assignment (P.Robots, P.Tasks);
         S : Progress;
      begin
         Solve (P.all, (Criterion => Min_Max, Iterations => 100, Excess_Band => 1.5,
                        others => <>), A, S);
         Assert (False, "an excess band of 1.5 was accepted");
      exception
         when E : Constraint_Error =>
            Assert (Ada.Exceptions.Exception_Message (E)
                      = "annealer: Excess_Band 1.50000000000000E+00 is not in 0 .. 1",
                    Ada.Exceptions.Exception_Message (E));
      end;
   end Excess_Term_Checked;

   --  Route-subset re-optimisation after the anneal (Options.Subset_Share)
   --  under the expensive check (every sub-anneal's moves too), on random
   --  makespan problems where it applies (distinct depots, open tours,
   --  asymmetric costs, depots of their own, multipliers, infeasible
   --  pairs, a minimum task count): valid, the reported best is the
   --  allocation's recomputed makespan, the same for a seed, the moves
   --  counted within the budget, another search than without it on most;
   --  where it does not apply (frozen prefixes, plan trees, alternatives,
   --  own costs, 2 robots, minsum) the plan is the one without it.
   procedure Subset_Reoptimisation_Checked (Unused : in out Fixture) is
      use Annealers;
      Applying : constant array (1 .. 5) of Variant :=
        [Variant'(others => <>),
         (Asymmetric => True, Closed => False, others => <>),
         (End_Depot => True, Heterogeneous => True, others => <>),
         (Infeasible => True, Min_Tasks => 2, others => <>),
         (Heterogeneous => True, Min_Tasks => 1, others => <>)];
      Other : constant array (1 .. 4) of Variant :=
        [Variant'(Frozen => Robot_1, others => <>),
         (Plan_Trees => True, others => <>),
         (Alternatives => True, others => <>),
         (Own_Factor => True, others => <>)];
      Both_Criteria : constant array (1 .. 2) of Criterion := [Min_Sum, Min_Max];
      Seed : Interfaces.Unsigned_64 := 4_700;
      Differs : Natural := 0;
   begin
      for V of Applying loop
         Seed := Seed + 1;
         declare
            P : constant Problem_Access := Random_Problem (36, 5, V, Seed);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => Min_Max, Seed => Seed, Time_Limit => 0.0, Iterations => 20_000,
               Check => True, Subset_Share => 0.5, Subset_Moves => 100.0, others => <>);
         begin
            Solve_Checked (P.all, O, A, S);
            --  Each sub-anneal may finish its last descent a few moves past
            --  its share (224 in all on the first variant): 5% allowed.
            Assert (S.Moves in 10_000 .. 21_000, "moves" & S.Moves'Image);
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "two runs with the same seed differ");
            O.Subset_Robots := 2;
            O.Subset_Fresh := True;
            Solve_Checked (P.all, O, B, T, What => "fresh");
            O.Subset_Share := 0.0;
            Solve (P.all, O, B, T);
            if A /= B then
               Differs := Differs + 1;
            end if;
         end;
      end loop;
      Assert (Differs >= 3, "the subsets changed the plan on" & Differs'Image & " of 5");
      for V of Other loop
         Seed := Seed + 1;
         declare
            P : constant Problem_Access := Random_Problem (30, 4, V, Seed);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => Min_Max, Seed => Seed, Time_Limit => 0.0, Iterations => 10_000,
               Subset_Share => 0.5, others => <>);
         begin
            Solve (P.all, O, A, S);
            O.Subset_Share := 0.0;
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "subsets acted where they do not apply");
         end;
      end loop;
      for C of Both_Criteria loop
         declare
            P : constant Problem_Access :=
              Random_Problem (20, (if C = Min_Sum then 4 else 2), (others => <>), 4_790);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => C, Seed => 3, Time_Limit => 0.0, Iterations => 10_000,
               Subset_Share => 0.5, others => <>);
         begin
            Solve (P.all, O, A, S);
            O.Subset_Share := 0.0;
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "subsets acted on minsum or 2 robots");
         end;
      end loop;
   end Subset_Reoptimisation_Checked;

   --  Computed Euclidean distances (no matrix) equal the matrix ones on
   --  every bundled TSPLIB file (EUC_2D, ATSP / explicit keep a matrix), on
   --  scaled and floored random points, with robot factors and own costs,
   --  and the annealer gives the same plan either way.
   procedure Computed_Distances_Equal_Matrix (F : in out Fixture) is
      pragma Unreferenced (F);
      use Ada.Directories;

      procedure Compare (Name : String; M, C : Problem; Step : Positive := 1) is
         A : Natural := 0;
      begin
         Assert (Has_Matrix (M), Name & ": no matrix kept");
         while A <= M.Locations loop
            for B in 0 .. M.Locations loop
               if Distance (M, A, B) /= Distance (C, A, B) then
                  Assert (False, Name & ":" & A'Image & B'Image & " matrix"
                          & Distance (M, A, B)'Image & " computed" & Distance (C, A, B)'Image);
               end if;
            end loop;
            A := A + Step;
         end loop;
      end Compare;

      procedure Each_File (Pattern : String) is
         Search : Search_Type;
         Item   : Directory_Entry_Type;
      begin
         Start_Search (Search, Data, Pattern);
         while More_Entries (Search) loop
            Get_Next_Entry (Search, Item);
            declare
               File : constant String := Full_Name (Item);
               M : constant Problem_Access := TSPLIB.Read (File, Keep_Matrix_Up_To => 10_000);
               C : constant Problem_Access := TSPLIB.Read (File, Keep_Matrix_Up_To => 0);
            begin
               Assert (Has_Matrix (C.all) = (Pattern = "*.atsp"),
                       Simple_Name (Item) & ": computed /= (not ATSP)");
               Assert (Has_Matrix (TSPLIB.Read (File).all) = (M.Locations <= Matrix_Limit
                                                              or else Pattern = "*.atsp"),
                       Simple_Name (Item) & ": matrix above the limit");
               Compare (Simple_Name (Item), M.all, C.all,
                        Step => (if M.Locations > 300 then 23 else 1));
            end;
         end loop;
         End_Search (Search);
      end Each_File;

      N : constant := 60;

      --  Per-robot costs on top: factors, then an own distance.
      procedure Robot_Costs (P : in out Problem) is
      begin
         Set_Robot_Factor (P, 2, 1.5);
         Set_Robot_Factor (P, 3, 0.7);
         Set_Robot_Distance (P, 3, 4, 5, 77);
         for T in 1 .. N - 3 loop
            Set_Task (P, T, T + 3);
         end loop;
         for R in 1 .. 3 loop
            Set_Robot (P, R, Start => R, Closed => True);
         end loop;
      end Robot_Costs;

      G : Random.Generator := Random.Seeded (5);
      Points : Point_Array (1 .. N);
   begin
      Each_File ("*.tsp");
      Each_File ("*.atsp");
      for I in Points'Range loop
         Points (I) := (Sancta.Geometry.Real (1000.0 * Random.Uniform (G)),
                        Sancta.Geometry.Real (1000.0 * Random.Uniform (G)));
      end loop;
      for Round in Boolean loop
         declare
            M : constant Problem_Access := Create (N, N - 3, 3);
            C : constant Problem_Access := Create (N, N - 3, 3);
         begin
            Set_Euclidean (M.all, Points, 100.0, Round, Keep_Matrix_Up_To => N);
            Set_Euclidean (C.all, Points, 100.0, Round, Keep_Matrix_Up_To => N - 1);
            Assert (not Has_Matrix (C.all), "computed random points");
            Compare ("random, round " & Round'Image, M.all, C.all);
            --  Per-robot costs on top: a factor, then own distances.
            Robot_Costs (M.all);
            Robot_Costs (C.all);
            Assert (not Has_Matrix (C.all), "robot costs made a shared matrix");
            for R in 1 .. 3 loop
               for A in 0 .. N loop
                  for B in 0 .. N loop
                     Assert (Robot_Distance (M.all, R, A, B) = Robot_Distance (C.all, R, A, B),
                             "robot" & R'Image & A'Image & B'Image);
                  end loop;
               end loop;
            end loop;
            Assert (Robot_Distance (C.all, 3, 4, 5) = 77 and then Robot_Distance (C.all, 3, 5, 4)
                      = Cost (Long_Float'Floor (0.7 * Long_Float (Distance (C.all, 5, 4)) + 0.5)),
                    "own distance over a factor");
            declare
               AM : Assignment (3, N - 3);
               AC : Assignment (3, N - 3);
               S  : Annealers.Progress;
               O  : constant Annealers.Options :=
                 (Criterion => Min_Max, Time_Limit => 0.0, Iterations => 30_000, others => <>);
            begin
               Annealers.Solve (M.all, O, AM, S);
               Annealers.Solve (C.all, O, AC, S);
               Assert (AM = AC, "the annealer's plans differ");
            end;
            --  Set_Distance turns computed distances into a matrix.
            Set_Distance (C.all, 1, 2, 5);
            Assert (Has_Matrix (C.all) and then Distance (C.all, 1, 2) = 5
                    and then Distance (C.all, 2, 1) = Distance (M.all, 2, 1)
                    and then Distance (C.all, 7, 9) = Distance (M.all, 7, 9),
                    "matrix from computed distances");
         end;
      end loop;
   end Computed_Distances_Equal_Matrix;

   --  The rounding of computed distances without the attributes' library
   --  calls: equal to Cost (Long_Float'Floor / 'Ceiling (X)) on integers,
   --  halves, values next to integers (both signs) and random reals.
   procedure Fast_Rounding (Unused : in out Fixture) is
      type Offsets is array (Positive range <>) of Long_Float;
      G : Random.Generator := Random.Seeded (31);
      procedure Same (X : Long_Float) is
      begin
         Assert (Floor_Cost (X) = Cost (Long_Float'Floor (X)), "floor of" & X'Image);
         Assert (Ceiling_Cost (X) = Cost (Long_Float'Ceiling (X)), "ceiling of" & X'Image);
         Assert (Rounded (Euclidean_Nearest, abs X) = Cost (Long_Float'Floor (abs X + 0.5)),
                 "nearest of" & Long_Float'Image (abs X));
      end Same;
   begin
      for I in -1_000 .. 1_000 loop
         for Offset of Offsets'[0.0, 0.5, -0.5, 1.0E-9, -1.0E-9, 0.499_999_999,
                                0.500_000_001, 0.25, 0.75]
         loop
            Same (Long_Float (I) + Offset);
         end loop;
      end loop;
      for I in 1 .. 100_000 loop
         Same ((Random.Uniform (G) - 0.5) * 1.0E7);
      end loop;
      Same (2.0 ** 52 + 1.0);
      Same (-(2.0 ** 52) - 1.0);
   end Fast_Rounding;

   --  The annealer reads a compact copy of the distance matrix (16 bits when
   --  every distance fits, else 32, else the problem's 64-bit costs; none
   --  when a robot has costs of its own): the same random 60-task problem
   --  with its distances times 1, 1 000 and 1 000 000 (largest about 14 000,
   --  14 M and 14 G), and with a robot of its own factor, annealed under the
   --  expensive check (every cost recomputed arc by arc from the problem
   --  after every move): valid, the reported best, deterministic.
   procedure Compact_Distances_Checked (Unused : in out Fixture) is
      use Ada.Numerics.Long_Elementary_Functions;
      N : constant := 61;
      G : Random.Generator := Random.Seeded (77);
      X, Y : array (1 .. N) of Long_Float;
   begin
      for I in 1 .. N loop
         X (I) := Long_Float'Floor (Random.Uniform (G) * 10_000.0);
         Y (I) := Long_Float'Floor (Random.Uniform (G) * 10_000.0);
      end loop;
      for Case_Number in 1 .. 4 loop
         declare
            Times : constant Cost :=
              (case Case_Number is when 2 => 1_000, when 3 => 1_000_000, when others => 1);
            P : constant Problem_Access := Create (Locations => N, Tasks => N - 1, Robots => 3);
            O : constant Annealers.Options :=
              (Criterion => Min_Max, Seed => 9, Time_Limit => 0.0, Iterations => 20_000,
               Check => True, others => <>);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Annealers.Progress;
         begin
            for I in 1 .. N loop
               for J in 1 .. N loop
                  if I /= J then
                     Set_Distance
                       (P.all, I, J,
                        Times * Cost (Long_Float'Floor
                                        (Sqrt ((X (I) - X (J)) ** 2 + (Y (I) - Y (J)) ** 2)
                                         + 0.5)));
                  end if;
               end loop;
            end loop;
            for T in 1 .. N - 1 loop
               Set_Task (P.all, T, T + 1);
            end loop;
            if Case_Number = 4 then
               Set_Robot_Factor (P.all, 2, 1.5);
            end if;
            Annealers.Solve (P.all, O, A, S);
            Assert (Validate (P.all, A) = "", Validate (P.all, A));
            Assert (abs (Evaluate (P.all, A, Min_Max).Value - S.Best) < 1.0E-6,
                    "reported best, case" & Case_Number'Image);
            Annealers.Solve (P.all, O, B, T);
            Assert (A = B, "two runs with the same seed differ, case" & Case_Number'Image);
         end;
      end loop;
   end Compact_Distances_Checked;

   --  What the population search's reports saw (Population_Search_Checked).
   Reported_Plans : Natural := 0;
   Least_Reported : Long_Float := Long_Float'Last;
   Parents_Best   : Long_Float := Long_Float'Last;
   Parents        : Positive := 1;

   procedure Note_Report (S : Annealers.Progress) is
   begin
      Reported_Plans := Reported_Plans + 1;
      Least_Reported := Long_Float'Min (Least_Reported, S.Current);
      if Reported_Plans <= Parents then
         Parents_Best := Long_Float'Min (Parents_Best, S.Current);
      end if;
   end Note_Report;

   --  The giant tours' split is optimal against enumerating every cut of the
   --  sequence (random tiny problems: distinct depots, open tours,
   --  multipliers, asymmetric costs, a minimum task count); with alike
   --  robots, the split of a plan's giant tour is no longer than the plan.
   --  The population search (Options.Population) under the expensive check
   --  (every anneal's moves): valid, the reported best is the recomputed
   --  makespan, the same for a seed, within the move budget, never worse
   --  than a member or child it reported (the first members: the parents),
   --  another plan than without it on most; where it does not apply (the
   --  total, plan trees, alternatives, frozen prefixes, own costs, one
   --  robot) the plan is the one without it.
   procedure Population_Search_Checked (Unused : in out Fixture) is
      use Annealers;
      Splitting : constant array (1 .. 5) of Variant :=
        [Variant'(others => <>),
         (Asymmetric => True, Closed => False, others => <>),
         (End_Depot => True, Heterogeneous => True, others => <>),
         (Min_Tasks => 1, others => <>),
         (Heterogeneous => True, Min_Tasks => 2, others => <>)];
      Other : constant array (1 .. 5) of Variant :=
        [Variant'(Frozen => Robot_1, others => <>),
         (Plan_Trees => True, others => <>),
         (Alternatives => True, others => <>),
         (Own_Factor => True, others => <>),
         (Infeasible => True, others => <>)];
      Seed : Interfaces.Unsigned_64 := 5_300;
      Differs : Natural := 0;
   begin
      for V of Splitting loop
         for Robots in 2 .. 3 loop
            Seed := Seed + 1;
            declare
               P : constant Problem_Access := Random_Problem (7, Robots, V, Seed);
               G : Random.Generator := Random.Seeded (Seed);
               Order : Count_Array (1 .. P.Tasks) := [for T in 1 .. P.Tasks => T];
               A, B : Assignment (P.Robots, P.Tasks);
               Max, Sum : Cost;
               Best_Max, Best_Sum : Cost := Cost'Last;
               Cuts : array (0 .. Robots) of Natural := [0 => 0, others => P.Tasks];
               --  Robot K takes Order (Cuts (K - 1) + 1 .. Cuts (K)).
               procedure Enumerate (K : Positive) is
               begin
                  if K = Robots then
                     if P.Tasks - Cuts (K - 1) < P.Min_Tasks then
                        return;
                     end if;
                     B := Empty (P.all);
                     for R in 1 .. Robots loop
                        for X in Cuts (R - 1) + 1 .. Cuts (R) loop
                           Append (B, R, Order (X));
                        end loop;
                     end loop;
                     declare
                        E : constant Evaluation := Evaluate (P.all, B, Min_Max);
                     begin
                        if E.Max < Best_Max or else (E.Max = Best_Max and then E.Sum < Best_Sum)
                        then
                           Best_Max := E.Max;
                           Best_Sum := E.Sum;
                        end if;
                     end;
                     return;
                  end if;
                  for C in Cuts (K - 1) + P.Min_Tasks .. P.Tasks loop
                     Cuts (K) := C;
                     Enumerate (K + 1);
                  end loop;
                  Cuts (K) := P.Tasks;
               end Enumerate;
            begin
               Assert (Giant_Tours.Applies (P.all), "split does not apply");
               for I in reverse 2 .. P.Tasks loop
                  declare
                     J : constant Positive := 1 + Random.Below (G, I);
                     X : constant Natural := Order (I);
                  begin
                     Order (I) := Order (J);
                     Order (J) := X;
                  end;
               end loop;
               Giant_Tours.Split (P.all, Order, A, Max, Sum);
               Enumerate (1);
               Assert (Validate (P.all, A) = "", "split invalid: " & Validate (P.all, A));
               Assert (Max = Best_Max and then Sum = Best_Sum,
                       "split" & Max'Image & Sum'Image & ", enumeration" & Best_Max'Image
                       & Best_Sum'Image & ", seed" & Seed'Image);
               Assert (Evaluate (P.all, A, Min_Max).Max = Max
                         and then Evaluate (P.all, A, Min_Max).Sum = Sum,
                       "split's reported costs differ from the recomputed ones");
               Assert (Giant_Tours.Giant_Tour (A) = Order, "split changed the sequence");
            end;
         end loop;
      end loop;
      for Robots in 2 .. 5 loop
         declare
            P : constant Problem_Access := Scattered (40, 5_350 + Interfaces.Unsigned_64 (Robots),
                                                      Robots);
            A, B : Assignment (P.Robots, P.Tasks);
            S : Progress;
            Max, Sum : Cost;
         begin
            Solve (P.all, (Criterion => Min_Max, Seed => 3, Time_Limit => 0.0,
                           Iterations => 5_000, others => <>), A, S);
            Giant_Tours.Split (P.all, Giant_Tours.Giant_Tour (A), B, Max, Sum);
            Assert (Max <= Evaluate (P.all, A, Min_Max).Max,
                    "split of a plan's giant tour is longer than the plan:" & Max'Image);
         end;
      end loop;
      for V of Splitting loop
         Seed := Seed + 1;
         declare
            P : constant Problem_Access := Random_Problem (24, 4, V, Seed);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => Min_Max, Seed => Seed, Time_Limit => 0.0, Iterations => 30_000,
               Check => True, Population => 3, Child_Moves => 200.0,
               Report => Note_Report'Access, Report_Every => 0.0, others => <>);
         begin
            Reported_Plans := 0;
            Least_Reported := Long_Float'Last;
            Parents_Best := Long_Float'Last;
            Parents := 3;
            Solve_Checked (P.all, O, A, S);
            --  Each anneal may end its last descent a few moves past its
            --  budget (80 in all on the first variant): 5% allowed.
            Assert (S.Moves in 15_000 .. 31_500, "moves" & S.Moves'Image);
            Assert (Reported_Plans > 3, "no child:" & Reported_Plans'Image & " plans");
            Assert (S.Best <= Parents_Best and then S.Best = Least_Reported,
                    "best" & S.Best'Image & ", best parent" & Parents_Best'Image
                    & ", least reported" & Least_Reported'Image);
            O.Report := null;
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "two runs with the same seed differ");
            O.Population := 0;
            Solve (P.all, O, B, T);
            if A /= B then
               Differs := Differs + 1;
            end if;
         end;
      end loop;
      Assert (Differs >= 3, "the population changed the plan on" & Differs'Image & " of 5");
      for V of Other loop
         Seed := Seed + 1;
         declare
            P : constant Problem_Access := Random_Problem (20, 3, V, Seed);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => Min_Max, Seed => Seed, Time_Limit => 0.0, Iterations => 10_000,
               Population => 3, others => <>);
         begin
            Solve (P.all, O, A, S);
            O.Population := 0;
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "the population acted where it does not apply");
         end;
      end loop;
      for C of Criterion_Array'[Min_Sum, Min_Ave, Min_Max] loop
         declare
            P : constant Problem_Access :=
              Random_Problem (20, (if C = Min_Max then 1 else 3), (others => <>), 5_390);
            A, B : Assignment (P.Robots, P.Tasks);
            S, T : Progress;
            O : Options :=
              (Criterion => C, Seed => 3, Time_Limit => 0.0, Iterations => 10_000,
               Population => 3, others => <>);
         begin
            Solve (P.all, O, A, S);
            O.Population := 0;
            Solve (P.all, O, B, T);
            Assert (A = B and then S.Best = T.Best, "the population acted on minsum / 1 robot");
         end;
      end loop;
   end Population_Search_Checked;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
      procedure Add (Name : String; Proc : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("allocation: " & Name, Proc));
      end Add;
   begin
      Add ("incremental costs equal recomputed costs", Incremental_Equals_Recomputed'Access);
      Add ("exact solver equals brute force", Exact_Equals_Brute_Force'Access);
      Add ("annealer reaches the exact optimum; baselines valid",
           Annealer_Reaches_Optimum'Access);
      Add ("baselines valid with constraints", Baselines_Valid_On_Larger'Access);
      Add ("same seed, same result", Deterministic'Access);
      Add ("route search inside the anneal, checked", Route_Search_In_Anneal'Access);
      Add ("anytime best box", Anytime_Box'Access);
      Add ("TSPLIB optimal tours give the optimal lengths", Optimal_Tours'Access);
      Add ("TSPLIB explicit matrix formats", Explicit_Formats'Access);
      Add ("TSPLIB ATT and GEO distances", Pseudo_Euclidean_And_Geo'Access);
      Add ("computed distances equal the matrix", Computed_Distances_Equal_Matrix'Access);
      Add ("fast floor / ceiling / nearest rounding", Fast_Rounding'Access);
      Add ("hybrid schedule, checked", Hybrid_Schedule'Access);
      Add ("TSPLIB bad files: file:line and reason", Bad_Files'Access);
      Add ("mission XML: robots, OR tasks, done prefix, errors", Mission_File'Access);
      Add ("robots ending at their own depots", End_Depots'Access);
      Add ("mission XML: nested AND/OR plans, errors", Nested_Plans'Access);
      Add ("each move kind alone, checked after every move", Each_Move_Kind_Checked'Access);
      Add ("ejection chains, checked after every step", Ejection_Chains_Checked'Access);
      Add ("makespan search's excess term, checked after every move",
           Excess_Term_Checked'Access);
      Add ("route-subset re-optimisation, checked", Subset_Reoptimisation_Checked'Access);
      Add ("compact distance matrices (16, 32, 64 bits, own costs), checked",
           Compact_Distances_Checked'Access);
      Add ("population search and giant tour split, checked",
           Population_Search_Checked'Access);
      return Result;
   end Suite;

end Sancta.Allocation.Tests;
