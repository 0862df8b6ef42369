with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with AUnit.Assertions;        use AUnit.Assertions;
with Sancta.Allocation.Baselines;
with Sancta.Allocation.Exact;
with Sancta.Allocation.Problem_Files;
with Sancta.Allocation.Random;
with Sancta.Geometry;

package body Sancta.Allocation.Test_Support is

   function Odd_Metric (R, From, To : Positive) return Cost is
     (Cost ((From * 37 + To * 91 + R * 11) mod 500 + 1));

   function Odd_Metric_Unreachable (R, From, To : Positive) return Cost is
     (if (From * 7 + To * 3 + R) mod 13 = 0 then Infinity else Odd_Metric (R, From, To));

   function Random_Problem
     (Tasks, Robots : Positive; V : Variant; Seed : Interfaces.Unsigned_64)
      return Problem_Access
   is
      G : Random.Generator := Random.Seeded (Seed);
      N_Alt : constant Positive := (if V.Alternatives then 2 * Tasks else Tasks);
      L : constant Positive := Robots + N_Alt;
      P : constant Problem_Access := Create (L, Tasks, Robots, N_Alt);
      Pts : Point_Array (1 .. L);

      procedure Build (Parent : Natural; First, Last : Positive) is
         N     : constant Positive := Last - First + 1;
         Node  : Positive;
         Parts : Positive;
         Start : Positive := First;
      begin
         if N = 1 and then Parent /= 0 then
            Add_Plan_Task (P.all, Parent, First);
            return;
         end if;
         Add_Node (P.all, (if Parent /= 0 and then Random.Below (G, 3) = 0 then And_Node
                           else Or_Node), Parent, Node);
         if N = 1 then
            Add_Plan_Task (P.all, Node, First);
            return;
         end if;
         Parts := 2 + Random.Below (G, Natural'Min (2, N - 1));
         for K in 1 .. Parts loop
            declare
               Left : constant Positive := Last - Start + 1;
               Size : constant Positive :=
                 (if K = Parts then Left else 1 + Random.Below (G, Left - (Parts - K)));
            begin
               Build (Node, Start, Start + Size - 1);
               Start := Start + Size;
            end;
         end loop;
      end Build;
   begin
      for I in Pts'Range loop
         Pts (I) := (Sancta.Geometry.Real (Random.Below (G, 1000)),
                     Sancta.Geometry.Real (Random.Below (G, 1000)));
      end loop;
      Set_Euclidean (P.all, Pts, 1.0);
      if V.Asymmetric then
         for A in 1 .. L loop
            for B in 1 .. L loop
               if A /= B then
                  Set_Distance (P.all, A, B, Distance (P.all, A, B) + Cost (Random.Below (G, 300)));
               end if;
            end loop;
         end loop;
         Update_Symmetry (P.all);
      end if;
      for R in 1 .. Robots loop
         Set_Robot (P.all, R, R, V.Closed,
                    Multiplier => (if V.Heterogeneous then 1 + (R - 1) mod 3 else 1));
      end loop;
      for T in 1 .. Tasks loop
         if V.Alternatives and then T mod 2 = 0 then
            Set_Task_Alternatives (P.all, T, [Robots + 2 * T - 1, Robots + 2 * T]);
         elsif V.Alternatives then
            Set_Task_Alternatives (P.all, T, [1 => Robots + 2 * T - 1]);
         else
            Set_Task (P.all, T, Robots + T);
         end if;
      end loop;
      if V.Own_Factor then
         Set_Robot_Factor (P.all, 1, 1.7);
      end if;
      if V.Own_Matrix and then Robots >= 2 then
         for A in 1 .. L loop
            for B in 1 .. L loop
               if A /= B then
                  Set_Robot_Distance (P.all, 2, A, B,
                                      Distance (P.all, A, B) / 2 + Cost (Random.Below (G, 400)));
               end if;
            end loop;
         end loop;
      end if;
      if V.Own_Callback then
         Set_Robot_Costs (P.all, Robots, (if V.Infinite_Arcs then Odd_Metric_Unreachable'Access
                                          else Odd_Metric'Access));
      end if;
      if V.Plan_Trees and then Tasks > 6 then
         Build (0, 1, Tasks / 2);
         Build (0, Tasks / 2 + 1, Tasks - 1);
      elsif V.Plan_Trees and then Tasks > 1 then
         Build (0, 1, Tasks - 1);
      end if;
      if V.Infeasible then
         for T in 1 .. Tasks loop
            if T mod 3 = 0 then
               Forbid (P.all, 1 + T mod Robots, T);
            end if;
         end loop;
      end if;
      if V.Frozen /= None then
         Freeze (P.all, 1, [1 => 1]);
      end if;
      if V.Frozen = Robots_1_And_2 and then Robots > 1 and then Tasks > 3 then
         Freeze (P.all, 2, [2, 4]);
      end if;
      if V.End_Depot then
         for R in 1 .. Robots loop
            Set_Robot_End (P.all, R, (if R = Robots then Nowhere else R + 1));
         end loop;
      end if;
      P.Min_Tasks := V.Min_Tasks;
      return P;
   end Random_Problem;

   function Scattered
     (Tasks  : Positive;
      Seed   : Interfaces.Unsigned_64;
      Robots : Positive := 1) return Problem_Access
   is
      G : Random.Generator := Random.Seeded (Seed);
      P : constant Problem_Access := Create (Tasks + 1, Tasks, Robots);
   begin
      Set_Euclidean (P.all, [for I in 1 .. Tasks + 1 =>
                               (Sancta.Geometry.Real (Random.Below (G, 1000)),
                                Sancta.Geometry.Real (Random.Below (G, 1000)))], 1.0);
      for T in 1 .. Tasks loop
         Set_Task (P.all, T, T + 1);
      end loop;
      return P;
   end Scattered;

   function Brute_Force (P : Problem; C : Criterion) return Long_Float is
      N : constant Positive := P.Tasks;
      Sel : Location_Array (1 .. N) := [others => 1];
      Act : Location_Array (1 .. N);
      NA  : Natural := 0;
      Perm : Location_Array (1 .. N);
      Used : Boolean_Array (1 .. N) := [others => False];
      Best : Long_Float := Long_Float'Last;
      A : Assignment (P.Robots, P.Tasks);

      procedure Try_Cuts (Robot : Positive; From : Positive) is
      begin
         if Robot = P.Robots then
            A.Length (Robot) := 0;
            for K in From .. NA loop
               Append (A, Robot, Perm (K));
            end loop;
            if Validate (P, A) = "" then
               Best := Long_Float'Min (Best, Evaluate (P, A, C).Value);
            end if;
            return;
         end if;
         for Last in From - 1 .. NA loop
            A.Length (Robot) := 0;
            for K in From .. Last loop
               Append (A, Robot, Perm (K));
            end loop;
            Try_Cuts (Robot + 1, Last + 1);
         end loop;
      end Try_Cuts;

      procedure Try_Choices (K : Positive) is
      begin
         if K > NA then
            Try_Cuts (1, 1);
            return;
         end if;
         for Ch in 1 .. P.Alt_Count (Act (K)) loop
            A.Choice (Act (K)) := Ch;
            Try_Choices (K + 1);
         end loop;
      end Try_Choices;

      procedure Permute (K : Positive) is
      begin
         if K > NA then
            Try_Choices (1);
            return;
         end if;
         for I in 1 .. NA loop
            if not Used (I) then
               Used (I) := True;
               Perm (K) := Act (I);
               Permute (K + 1);
               Used (I) := False;
            end if;
         end loop;
      end Permute;

      procedure Try_Selections (O : Positive) is
      begin
         if O > Or_Count (P) then
            NA := 0;
            for T in 1 .. N loop
               if Is_Active (P, Sel, T) then
                  NA := NA + 1;
                  Act (NA) := T;
               end if;
            end loop;
            A.Branch := Sel;
            Permute (1);
            return;
         end if;
         for B in 1 .. Alternatives (P, O) loop
            Sel (O) := B;
            Try_Selections (O + 1);
         end loop;
      end Try_Selections;
   begin
      Try_Selections (1);
      return Best;
   end Brute_Force;

   procedure Solve_Checked
     (P    : Problem;
      O    : Annealers.Options;
      A    : in out Assignment;
      S    : out Annealers.Progress;
      What : String := "")
   is
      Prefix : constant String := (if What = "" then "" else What & ": ");
   begin
      Annealers.Solve (P, O, A, S);
      Assert (Validate (P, A) = "", Prefix & "invalid: " & Validate (P, A));
      Assert (abs (Evaluate (P, A, O.Criterion).Value - S.Best) < 1.0E-6,
              Prefix & "reported best" & Img (S.Best) & " /= recomputed"
              & Img (Evaluate (P, A, O.Criterion).Value));
   end Solve_Checked;

   procedure Anneal_Checked
     (P : Problem; O : in out Annealers.Options; A : in out Assignment;
      S : out Annealers.Progress) is
   begin
      O.Start_Temperature := 0.0;
      O.End_Temperature := 0.0;
      O.Polish := True;
      Solve_Checked (P, O, A, S);
   end Anneal_Checked;

   procedure Print_Mismatch (P : Problem; A, E : Assignment) is
   begin
      for R in 1 .. P.Robots loop
         Ada.Text_IO.Put ("mismatch: robot" & R'Image & " A:");
         for K in 1 .. A.Length (R) loop
            Ada.Text_IO.Put (A.Tour (R, K)'Image);
         end loop;
         Ada.Text_IO.Put (" cost" & Tour_Cost (P, A, R)'Image & "  E:");
         for K in 1 .. E.Length (R) loop
            Ada.Text_IO.Put (E.Tour (R, K)'Image);
         end loop;
         Ada.Text_IO.Put_Line (" cost" & Tour_Cost (P, E, R)'Image);
      end loop;
   end Print_Mismatch;

   procedure For_Each_Random_Problem
     (Variants : Variant_Array;
      Criteria : Criterion_Array;
      Problems : Random_Problems)
   is
      use type Interfaces.Unsigned_64;
      Seed : Interfaces.Unsigned_64 := Problems.First_Seed;
   begin
      for V of Variants loop
         for C of Criteria loop
            Seed := Seed + 1;
            declare
               P : constant Problem_Access :=
                 Random_Problem (Problems.Tasks, Problems.Robots,
                                 (V with delta Plan_Trees => Problems.Plan_Trees), Seed);
            begin
               Check (P.all, V, C, Seed);
            end;
         end loop;
      end loop;
   end For_Each_Random_Problem;

   procedure Check_Annealer_Reaches_Optimum
     (Variants   : Variant_Array;
      Problems   : Random_Problems;
      Iterations : Long_Long_Integer)
   is
      procedure Check_One (P : Problem; V : Variant; C : Criterion; Seed : Interfaces.Unsigned_64)
      is
         pragma Unreferenced (V);
         E : constant Assignment := Exact.Solve (P, C);
         Opt : constant Long_Float := Evaluate (P, E, C).Value;
         A : Assignment (P.Robots, P.Tasks);
         S : Annealers.Progress;
      begin
         Annealers.Solve (P, (Criterion => C, Seed => Seed, Time_Limit => 0.0,
                              Iterations => Iterations, others => <>), A, S);
         Assert (Validate (P, A) = "", "annealer invalid: " & Validate (P, A));
         if Evaluate (P, A, C).Value /= Opt then
            Print_Mismatch (P, A, E);
         end if;
         Assert (Evaluate (P, A, C).Value = Opt,
                 "annealer" & Img (Evaluate (P, A, C).Value) & " /= optimum"
                 & Img (Opt) & " (seed" & Seed'Image & ")");
         for M in Baselines.Method loop
            declare
               B : constant Assignment := Baselines.Solve (P, M, C);
            begin
               Assert (Validate (P, B) = "", M'Image & " invalid: " & Validate (P, B));
               Assert (Evaluate (P, B, C).Value >= Opt, M'Image & " better than the optimum");
            end;
         end loop;
      end Check_One;

      procedure Check_All is new For_Each_Random_Problem (Check_One);
   begin
      Check_All (Variants, Pure_Criteria, Problems);
   end Check_Annealer_Reaches_Optimum;

   procedure Check_Exact_Equals_Brute_Force
     (Variants : Variant_Array; Problems : Random_Problems)
   is
      procedure Check_One (P : Problem; V : Variant; C : Criterion; Seed : Interfaces.Unsigned_64)
      is
         pragma Unreferenced (V);
         A : constant Assignment := Exact.Solve (P, C);
         B : constant Long_Float := Brute_Force (P, C);
      begin
         Assert (not Problems.Plan_Trees or else Or_Count (P) > 0,
                 "no OR node in the test problem");
         Assert (Validate (P, A) = "", "exact invalid: " & Validate (P, A));
         Assert (Evaluate (P, A, C).Value = B,
                 "exact" & Img (Evaluate (P, A, C).Value) & " /= brute force" & Img (B)
                 & " (seed" & Seed'Image & ")");
      end Check_One;

      procedure Check_All is new For_Each_Random_Problem (Check_One);
   begin
      Check_All (Variants, Pure_Criteria, Problems);
   end Check_Exact_Equals_Brute_Force;

   procedure Write (File, Text : String) is
      F : Ada.Text_IO.File_Type;
   begin
      Ada.Text_IO.Create (F, Ada.Text_IO.Out_File, File);
      Ada.Text_IO.Put (F, Text);
      Ada.Text_IO.Close (F);
   end Write;

   procedure Expect_Read_Error (File, Text, Expect : String) is
   begin
      Write (File, Text);
      declare
         P : constant Problem_Access := Read (File);
         pragma Unreferenced (P);
      begin
         Assert (False, "no error, expected '" & Expect & "'");
      end;
   exception
      when E : Format_Error =>
         Assert (Ada.Strings.Fixed.Index (Ada.Exceptions.Exception_Message (E), Expect) > 0,
                 "message '" & Ada.Exceptions.Exception_Message (E) & "' lacks '"
                 & Expect & "'");
   end Expect_Read_Error;

   function Read_Mission (File : String) return Problem_Access is (Problem_Files.Read (File));

   function Mission_From (File, Text : String) return Problem_Access is
   begin
      Write (File, Text);
      return Problem_Files.Read (File);
   end Mission_From;

   procedure Expect_Mission_Error_Instance is new Expect_Read_Error (Read_Mission);

   procedure Expect_Mission_Error (File, Text, Expect : String)
     renames Expect_Mission_Error_Instance;

end Sancta.Allocation.Test_Support;
