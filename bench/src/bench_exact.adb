--  Exact solver benchmark (bench/allocation runs it for its "time to
--  proof" table; it can be run alone): for each TSPLIB .tsp/.atsp file,
--  a first tour by the heuristic (iterated LK for symmetric instances,
--  the annealer for asymmetric ones; its time is printed apart), then
--  branch and cut with the chosen separators; prints one row per file:
--  n, tour, root bound, lower bound, gap, CPU time to proof (or at the
--  limit), nodes, cuts by class (subtour / blossom / comb), purged and
--  fixed counts. Times are CPU seconds of the solver (a shared machine).
--
--     bench_exact [--time S] [--wall] [--no-heuristic-blossoms]
--                 [--no-exact-blossoms] [--no-combs] [--no-pricing]
--                 [--no-node-fixing] [--strong K] [--depth-first]
--                 [--no-purge] [--csv FILE] FILE...
with Ada.Command_Line;        use Ada.Command_Line;
with Ada.Execution_Time;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Exceptions;
with Ada.Text_IO;             use Ada.Text_IO;
with Bench_Arguments;
with Sancta.Allocation;       use Sancta.Allocation;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Assignments;
with Sancta.Allocation.Branch_And_Cut;
with Sancta.Allocation.Local_Search;
with Sancta.Allocation.Problems;
with Sancta.Allocation.TSPLIB;

procedure Bench_Exact is

   package BC renames Sancta.Allocation.Branch_And_Cut;
   use type Ada.Execution_Time.CPU_Time;
   use type BC.Cut_Class;

   Config : BC.Settings := (Time_Limit => 60.0, CPU_Time_Limit => True, others => <>);
   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_exact [OPTION]... FILE..." & ASCII.LF
      & "exact solver (branch and cut) on TSPLIB .tsp/.atsp files, one row per file: bound,"
      & ASCII.LF & "gap, CPU time to proof, nodes, cuts by class (bench/allocation runs it)"
      & ASCII.LF
      & "  --time S                  CPU-time limit per instance (default 60)" & ASCII.LF
      & "  --wall                    the limit on wall-clock time" & ASCII.LF
      & "  --strong K                strong branching on K candidates" & ASCII.LF
      & "  --no-heuristic-blossoms, --no-exact-blossoms, --no-combs, --no-pricing,"
      & ASCII.LF
      & "  --no-node-fixing, --no-purge   turn that technique off" & ASCII.LF
      & "  --depth-first             depth-first instead of best-bound node selection"
      & ASCII.LF
      & "  --csv FILE                also write the rows there",
      Min => 1, Max => Natural'Last);
   pragma Unreferenced (Read);
   CSV : File_Type;
   Has_CSV : Boolean := False;

   package Real_IO is new Ada.Text_IO.Float_IO (Long_Float);

   function Img (V : Long_Float; Decimals : Natural := 2) return String is
      S : String (1 .. 40);
   begin
      Real_IO.Put (S, V, Aft => Decimals, Exp => 0);
      return Ada.Strings.Fixed.Trim (S, Ada.Strings.Both);
   end Img;

   function Pad (S : String; Width : Positive) return String is
     (if S'Length >= Width then S else [1 .. Width - S'Length => ' '] & S);

   procedure Run (File : String) is
      use Sancta.Allocation.Problems;
      Instance : constant Problem_Access := TSPLIB.Read (File);
      P : constant Problem_Access := TSPLIB.To_MTSP (Instance.all, Robots => 1);
      Start : Assignments.Assignment := Annealers.Greedy_Start (P.all, Min_Sum, 1);
      Heuristic_Started : constant Ada.Execution_Time.CPU_Time := Ada.Execution_Time.Clock;
      Heuristic_CPU : Duration;
      Outcome : BC.Result (P.Robots, P.Tasks);
      Name : constant String := Ada.Strings.Fixed.Tail
        (File, File'Length - Ada.Strings.Fixed.Index (File, "/", Ada.Strings.Backward));
   begin
      if Local_Search.Applies (P.all) then
         declare
            Stats : Local_Search.Statistics;
         begin
            Local_Search.Improve (P.all, Start, (Time_Limit => 2.0, others => <>), Stats);
         end;
      else
         declare
            O : constant Annealers.Options :=
              (Time_Limit => 0.0, Iterations => 2_000_000, others => <>);
            Progress : Annealers.Progress;
         begin
            Annealers.Solve (P.all, O, Start, Progress);
         end;
      end if;
      Heuristic_CPU := Ada.Real_Time.To_Duration (Ada.Execution_Time.Clock - Heuristic_Started);
      BC.Solve (P.all, Start, Outcome, Config);
      declare
         Gap : constant Long_Float :=
           100.0 * Long_Float (Outcome.Upper - Outcome.Lower) / Long_Float (Outcome.Upper);
         Root_Gap : constant Long_Float :=
           100.0 * (Long_Float (Outcome.Upper) - Outcome.Root_Bound) / Long_Float (Outcome.Upper);
      begin
         Put_Line (Pad (Name, 14) & Pad (P.Tasks'Image, 5) & Pad (Outcome.Upper'Image, 8)
                   & Pad (Img (Outcome.Root_Bound, 1), 10) & Pad (Img (Root_Gap, 3), 7)
                   & Pad (Outcome.Lower'Image, 8) & Pad (Img (Gap, 3), 7)
                   & Pad (Img (Long_Float (Outcome.CPU)), 8)
                   & Pad (Img (Long_Float (Outcome.Elapsed)), 8)
                   & Pad (Outcome.Nodes'Image, 7)
                   & Pad (Outcome.By_Class (BC.Subtour)'Image, 6)
                   & Pad (Outcome.By_Class (BC.Blossom)'Image, 6)
                   & Pad (Outcome.By_Class (BC.Comb)'Image, 6)
                   & Pad (Outcome.Purged'Image, 7) & Pad (Outcome.Fixed'Image, 7)
                   & Pad (Outcome.Edges'Image, 7)
                   & Pad (Img (Long_Float (Heuristic_CPU)), 7)
                   & "  " & (if Outcome.Proven then "proven" else "limit"));
         if Has_CSV then
            Put_Line (CSV, Name & "," & Ada.Strings.Fixed.Trim (P.Tasks'Image, Ada.Strings.Both)
                      & "," & Outcome.Upper'Image & "," & Img (Outcome.Root_Bound, 3) & ","
                      & Outcome.Lower'Image & "," & Img (Long_Float (Outcome.CPU), 3) & ","
                      & Img (Long_Float (Outcome.Elapsed), 3) & "," & Outcome.Nodes'Image
                      & "," & Outcome.By_Class (BC.Subtour)'Image
                      & "," & Outcome.By_Class (BC.Blossom)'Image
                      & "," & Outcome.By_Class (BC.Comb)'Image & "," & Outcome.Purged'Image
                      & "," & Outcome.Fixed'Image & "," & Outcome.Edges'Image & ","
                      & (if Outcome.Proven then "true" else "false"));
         end if;
      end;
   end Run;

   I : Positive := 1;
begin
   while I <= Argument_Count and then Argument (I)'Length > 2
     and then Argument (I) (Argument (I)'First .. Argument (I)'First + 1) = "--"
   loop
      declare
         A : constant String := Argument (I);
      begin
         if A in "--time" | "--strong" | "--csv" and then I = Argument_Count then
            Bench_Arguments.Fail ("option " & A & " needs a value");
         elsif A = "--time" then
            Config.Time_Limit := Bench_Arguments.Seconds (I + 1, "--time", Default => 0.0);
            I := I + 1;
         elsif A = "--strong" then
            Config.Strong_Branching := Bench_Arguments.Count (I + 1, "--strong");
            I := I + 1;
         elsif A = "--csv" then
            Bench_Arguments.Create_Output (CSV, Argument (I + 1), "--csv");
            Has_CSV := True;
            Put_Line (CSV, "instance,n,tour,root_bound,lower_bound,cpu_s,wall_s,nodes,"
                      & "subtour_cuts,blossom_cuts,comb_cuts,purged,fixed,edges,proven");
            I := I + 1;
         elsif A = "--wall" then
            Config.CPU_Time_Limit := False;
         elsif A = "--no-heuristic-blossoms" then
            Config.Heuristic_Blossoms := False;
         elsif A = "--no-exact-blossoms" then
            Config.Exact_Blossoms := False;
         elsif A = "--no-combs" then
            Config.Combs := False;
         elsif A = "--no-pricing" then
            Config.Pricing := False;
         elsif A = "--no-node-fixing" then
            Config.Node_Fixing := False;
         elsif A = "--depth-first" then
            Config.Best_Bound := False;
         elsif A = "--no-purge" then
            Config.Purge := False;
         else
            Bench_Arguments.Fail ("unknown option " & A);
         end if;
      end;
      I := I + 1;
   end loop;
   if I > Argument_Count then
      Bench_Arguments.Fail ("no FILE given");
   end if;
   Put_Line ("Branch and cut, CPU-time limit" & Duration'Image (Config.Time_Limit)
             & " s per instance"
             & (if Config.CPU_Time_Limit then "" else " (wall)"));
   Put_Line ("      instance    n    tour      root  root%   lower   gap%  cpu s  wall s"
             & "  nodes   sub  blos  comb purged  fixed  edges heur s");
   for J in I .. Argument_Count loop
      begin
         Run (Argument (J));
      exception
         when E : Format_Error =>
            Put_Line (Standard_Error, "bench_exact: " & Ada.Exceptions.Exception_Message (E));
            Set_Exit_Status (1);
      end;
   end loop;
   if Has_CSV then
      Close (CSV);
   end if;
end Bench_Exact;
