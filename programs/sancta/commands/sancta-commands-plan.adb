with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Execution_Time;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Interfaces;
with Interfaces.C;
with Sancta.Allocation;             use Sancta.Allocation;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Baselines;
with Sancta.Allocation.Branch_And_Cut;
with Sancta.Allocation.Budget_Clocks;
with Sancta.Allocation.Exact;
with Sancta.Allocation.Problem_Files;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;
with Sancta.Allocation.TSPLIB;
with Sancta.Geometry;

package body Sancta.Commands.Plan is

   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   package CL renames Ada.Command_Line;
   package Annealers renames Sancta.Allocation.Annealers;

   Usage_Error : exception;

   Auto_Subset_Share     : constant := 0.2;
   Auto_Subset_Min_Tasks : constant := 200;
   --  --subsets when not given, with the annealer: Auto_Subset_Share from
   --  Auto_Subset_Min_Tasks tasks up, else 0 (none); it applies to a pure
   --  makespan with 3+ robots only (Annealers.Options' Subset_Share, whose
   --  comment has the figures measured).

   Auto_Population           : constant := 4;
   Auto_Population_Min_Tasks : constant := 60;
   --  --population when not given, with the annealer: Auto_Population from
   --  Auto_Population_Min_Tasks tasks up to Auto_Subset_Min_Tasks - 1 (where
   --  the subsets start), else 0 (none); it applies to a pure makespan with
   --  2+ robots only (Annealers.Options' Population, whose comment has the
   --  figures measured on unseen instances). The bench's MinMax rows in
   --  that range (eil76, rat99, kroA100, eil101, kroA200 x 3 / 5 / 10; 10 s
   --  CPU, 3 seeds) against --population 0: -0.22% mean makespan, 20 better
   --  / 2 worse; kroA200/10 6224 (best-known) on 3 of 3 seeds, was 6281.

   --  CPU seconds used so far by the main task (set-up and search; runs of
   --  --restarts work in tasks of their own).
   function CPU_Seconds return Long_Float is
      use type Ada.Execution_Time.CPU_Time;
   begin
      return Long_Float (Ada.Real_Time.To_Duration
                           (Ada.Execution_Time.Clock - Ada.Execution_Time.Time_Of (0)));
   end CPU_Seconds;

   procedure Help is
   begin
      Put_Line ("usage: sancta plan FILE [options]");
      Put_Line ("  FILE                 a TSPLIB .tsp/.atsp instance (depot = node 1) or a");
      Put_Line ("                       SANCTA mission .xml (robots, tasks, AND/OR plans)");
      Put_Line ("options:");
      Put_Line ("  --robots N           number of robots for TSPLIB files (default 1)");
      Put_Line ("  --objective NAME     minmax | minsum | minave | minmix | mintim, or");
      Put_Line ("                       weights MAX,SUM,AVE (default minsum)");
      Put_Line ("  --time T             time budget: 10s, 500ms, 2.5 (s); default 10s");
      Put_Line ("  --clock K            what --time counts: wall (default) or cpu, the CPU");
      Put_Line ("                       time of the search's task (the same work on a busy");
      Put_Line ("                       machine; branch and cut (--solver exact) stays wall)");
      Put_Line ("  --iterations N       move budget (with --time 0: deterministic)");
      Put_Line ("  --converge N         stop after N moves without a new best");
      Put_Line ("  --seed N             random seed (default 1)");
      Put_Line ("  --schedule S         automatic | geometric | cyclic | reheat | hybrid");
      Put_Line ("                       (automatic: hybrid for minmax, else geometric;");
      Put_Line ("                       hybrid: geometric over half the budget, then");
      Put_Line ("                       reheats from the best)");
      Put_Line ("  --geometric-share F  hybrid: share of the budget cooled geometrically");
      Put_Line ("                       (0.01 .. 0.99, default 0.5)");
      Put_Line ("  --cycles N           cyclic schedule: cycles, each from the best (3)");
      Put_Line ("  --restarts N         independent runs in parallel tasks, best kept");
      Put_Line ("  --solver S           anneal | greedy | makespan | auction | exact");
      Put_Line ("                       exact: Held-Karp up to 12 tasks, else branch and cut");
      Put_Line ("                       (LP with subtour cuts on GLPK; minsum, or one robot)");
      Put_Line ("                       from an anneal of a tenth of --time; prints the");
      Put_Line ("                       proof or, at the time limit, the lower bound and gap");
      Put_Line ("  --real SCALE         real Euclidean distances in fixed point, x SCALE");
      Put_Line ("  --open               open tours (robots do not return)");
      Put_Line ("  --min-tasks N        each robot visits at least N cities (default 1)");
      Put_Line ("  --target V           stop as soon as the objective is <= V");
      Put_Line ("  --balance W          minmax: initial weight of the total cost in the");
      Put_Line ("                       search objective (default 0.05, 0 = none)");
      Put_Line ("  --balance-decay      minmax: the total cost's weight decays to a mere");
      Put_Line ("                       tie-break over the budget");
      Put_Line ("  --square W           minmax: weight of the sum of squared tour costs in");
      Put_Line ("                       the search objective, per unit of a mean tour");
      Put_Line ("                       (default 0 = none)");
      Put_Line ("  --excess W           minmax: weight of the tours' squared excess over a");
      Put_Line ("                       floor below the best makespan, per unit of the");
      Put_Line ("                       longest tour's excess (default 1, 0 = none)");
      Put_Line ("  --excess-band F      minmax: that floor, as a share of the best makespan");
      Put_Line ("                       below it (default 0.04)");
      Put_Line ("  --excess-reheats     minmax, hybrid schedule: that term also in the");
      Put_Line ("                       reheats (default: they anneal on the makespan)");
      Put_Line ("  --subsets F          minmax, 3+ robots: share of the budget for re-annealing");
      Put_Line ("                       the longest tour with tours near it as a problem of");
      Put_Line ("                       their own, kept when their makespan falls (default");
      Put_Line ("                       0.2 from 200 tasks up, else 0 = none; 10 s CPU,");
      Put_Line ("                       unseen 250-1000 tasks: mean makespan -0.59%, 34");
      Put_Line ("                       better / 12 worse; 150 tasks +0.26%)");
      Put_Line ("  --subset-robots N    tours per such subset (2 .. 5, default 3)");
      Put_Line ("  --subset-moves M     moves per task of a subset's anneal (default 5000)");
      Put_Line ("  --subset-fresh       a subset's anneal starts from its own construction");
      Put_Line ("  --subset-total W     subsets minimise makespan + W x total, kept when the");
      Put_Line ("                       plan's makespan, else its total, falls (0 = none)");
      Put_Line ("  --subset-t0 F        a subset's anneal: start temperature factor (0.05;");
      Put_Line ("                       0 = --t0)");
      Put_Line ("  --population N       minmax, 2+ robots: a population search of N plans");
      Put_Line ("                       (independent anneals, then children: order crossover");
      Put_Line ("                       of two plans' tours end to end, optimal split into");
      Put_Line ("                       tours, a short anneal; default 4 from 60 to 199");
      Put_Line ("                       tasks, else 0 = none)");
      Put_Line ("  --population-share F share of the budget for the first N anneals (0.5)");
      Put_Line ("  --child-moves M      moves per task of a child's anneal (default 2000)");
      Put_Line ("  --child-t0 F         a child's anneal: start temperature factor (0.05;");
      Put_Line ("                       0 = --t0)");
      Put_Line ("  --runs N             anneals in sequence sharing the budget, each from a");
      Put_Line ("                       fresh start (geometric schedule; 0 = automatic)");
      Put_Line ("  --ruin F             share of the work spent in ruin-and-recreate moves");
      Put_Line ("                       (evaluations per move drawn; default 0.2, 0 = none)");
      Put_Line ("  --lk F               one robot: share of the budget for iterated");
      Put_Line ("                       2-opt/Or-opt/Lin-Kernighan search after the anneal");
      Put_Line ("                       (default 0.8, 0 = none; above 1000 tasks on a closed");
      Put_Line ("                       tour, the whole budget from a nearest-neighbour tour);");
      Put_Line ("                       teams: every route gets one such descent");
      Put_Line ("  --t0 F, --cool R     start temperature = F x mean uphill delta (0.5),");
      Put_Line ("                       end temperature = start / R (2000)");
      Put_Line ("  --no-polish          skip the final local search");
      Put_Line ("  --check              expensive self-check after every move (slow)");
      Put_Line ("  --profile            per move kind: drawn, legal, accepted, improving,");
      Put_Line ("                       new best (on standard error)");
      Put_Line ("  --svg FILE           draw the tours");
      Put_Line ("  --json FILE|-        write the result as JSON (- = standard output)");
      Put_Line ("  --quiet              no tours on standard output, no progress line");
   end Help;

   function Trim (S : String) return String is
     (Ada.Strings.Fixed.Trim (S, Ada.Strings.Both));

   function Img (X : Long_Long_Integer) return String is (Trim (X'Image));
   function Img (X : Integer) return String is (Trim (X'Image));

   function Real_Img (X : Long_Float; Decimals : Natural := 2) return String is
      package F is new Ada.Text_IO.Float_IO (Long_Float);
      S : String (1 .. 40);
   begin
      F.Put (S, X, Aft => Decimals, Exp => 0);
      return Trim (S);
   end Real_Img;

   Scale_Factor : Long_Float := 1.0;

   function Cost_Img (C : Cost) return String is
   begin
      if Is_Infinite (C) then
         return "inf";
      elsif Scale_Factor = 1.0 then
         return Img (C);
      else
         return Real_Img (Long_Float (C) / Scale_Factor, 3);
      end if;
   end Cost_Img;

   function Parse_Duration (S : String) return Duration is
   begin
      if S'Length > 2 and then S (S'Last - 1 .. S'Last) = "ms" then
         return Duration (Long_Float'Value (S (S'First .. S'Last - 2)) / 1000.0);
      elsif S'Length > 1 and then S (S'Last) = 's' then
         return Duration (Long_Float'Value (S (S'First .. S'Last - 1)));
      elsif S'Length > 1 and then S (S'Last) = 'm' then
         return Duration (60.0 * Long_Float'Value (S (S'First .. S'Last - 1)));
      else
         return Duration (Long_Float'Value (S));
      end if;
   exception
      when Constraint_Error =>
         raise Usage_Error with "--time: '" & S & "' is not a duration (e.g. 10s, 500ms)";
   end Parse_Duration;

   function Parse_Natural (Option, S : String) return Long_Long_Integer is
   begin
      return X : constant Long_Long_Integer := Long_Long_Integer'Value (S) do
         if X < 0 then
            raise Constraint_Error;
         end if;
      end return;
   exception
      when Constraint_Error =>
         raise Usage_Error with Option & ": '" & S & "' is not a non-negative integer";
   end Parse_Natural;

   function Parse_Criterion (S : String; Name : out Unbounded_String) return Criterion is
      Found : Boolean;
      C : constant Criterion := Preset (S, Found);
   begin
      Name := To_Unbounded_String (S);
      if Found then
         return C;
      end if;
      declare
         C1 : constant Natural := Ada.Strings.Fixed.Index (S, ",");
         C2 : constant Natural :=
           (if C1 = 0 then 0 else Ada.Strings.Fixed.Index (S (C1 + 1 .. S'Last), ","));
      begin
         if C1 = 0 or else C2 = 0 then
            raise Usage_Error with "--objective: '" & S
              & "' is not minmax, minsum, minave, minmix, mintim or MAX,SUM,AVE";
         end if;
         return R : constant Criterion :=
           (Long_Float'Value (S (S'First .. C1 - 1)), Long_Float'Value (S (C1 + 1 .. C2 - 1)),
            Long_Float'Value (S (C2 + 1 .. S'Last)))
         do
            if R.Max_Weight < 0.0 or else R.Sum_Weight < 0.0 or else R.Ave_Weight < 0.0
              or else R.Max_Weight + R.Sum_Weight + R.Ave_Weight = 0.0
            then
               raise Usage_Error with "--objective: weights must be >= 0, not all 0";
            end if;
         end return;
      exception
         when Constraint_Error =>
            raise Usage_Error with "--objective: bad weights '" & S & "'";
      end;
   end Parse_Criterion;

   --  Progress on standard error: one line rewritten in place on a
   --  terminal; in a file or a pipe, a line per second of the run.
   Quiet : Boolean := False;
   Has_Progress : Boolean := False;
   Next_Line_At : Duration := 0.0;

   function Error_Is_Terminal return Boolean is
      function Is_A_TTY (Fd : Interfaces.C.int) return Interfaces.C.int
        with Import, Convention => C, External_Name => "isatty";
      use type Interfaces.C.int;
   begin
      return Is_A_TTY (2) /= 0;
   end Error_Is_Terminal;

   procedure Show (Pr : Annealers.Progress) is
      Line : constant String := "plan: " & Real_Img (Long_Float (Pr.Elapsed), 1)
        & " s  best " & Real_Img (Pr.Best / Scale_Factor, 2)
        & "  " & Real_Img (Pr.Moves_Per_Second / 1.0E6, 2) & " M moves/s"
        & "  T " & Real_Img (Pr.Temperature / Scale_Factor, 4);
   begin
      if Quiet then
         return;
      elsif Error_Is_Terminal then
         Put (Standard_Error, ASCII.CR & Line & "   ");
         Flush (Standard_Error);
         Has_Progress := True;
      elsif Pr.Elapsed >= Next_Line_At then
         Put_Line (Standard_Error, Line);
         Next_Line_At := Pr.Elapsed + 1.0;
      end if;
   end Show;

   --  The annealer's per-move-kind statistics, on standard error.
   procedure Show_Profile (Stats : Annealers.Progress) is
      function Pct (A, B : Long_Long_Integer) return String is
        (if B = 0 then "-" else Real_Img (100.0 * Long_Float (A) / Long_Float (B), 2));
      procedure Cell (S : String; Width : Positive := 11) is
      begin
         Put (Standard_Error, [1 .. Integer'Max (0, Width - S'Length) => ' '] & S);
      end Cell;
   begin
      Put_Line (Standard_Error, "move kind         drawn   legal%  accepted%  improving%"
                & "   new best");
      for K in Annealers.Move_Kind loop
         declare
            X : Annealers.Kind_Stats renames Stats.Kinds (K);
            N : constant String := Annealers.Move_Kind'Image (K);
         begin
            if X.Tries > 0 then
               Put (Standard_Error, N & [1 .. Integer'Max (1, 14 - N'Length) => ' ']);
               Cell (Img (X.Tries));
               Cell (Pct (X.Legal, X.Tries), 9);
               Cell (Pct (X.Accepted, X.Legal));
               Cell (Pct (X.Improving, X.Legal), 12);
               Cell (Img (X.New_Best));
               New_Line (Standard_Error);
            end if;
         end;
      end loop;
      Put_Line (Standard_Error, "final descent gained " & Real_Img (Stats.Polish_Gain, 2));
   end Show_Profile;

   --  Parallel restarts: one task per run.
   type Run_Result (R, T : Positive) is record
      A : Assignment (R, T);
      Stats : Annealers.Progress;
      Error : Unbounded_String;
   end record;
   type Result_Access is access Run_Result;

   task type Runner is
      entry Start (P : Problem_Access; O : Annealers.Options; Out_Result : Result_Access);
      entry Wait;
   end Runner;

   task body Runner is
      PA : Problem_Access;
      Opts : Annealers.Options;
      Res : Result_Access;
   begin
      accept Start (P : Problem_Access; O : Annealers.Options; Out_Result : Result_Access) do
         PA := P;
         Opts := O;
         Res := Out_Result;
      end Start;
      begin
         Annealers.Solve (PA.all, Opts, Res.A, Res.Stats);
      exception
         when E : others =>
            Res.Error := To_Unbounded_String (Ada.Exceptions.Exception_Message (E));
      end;
      accept Wait;
   end Runner;

   --  JSON string contents: quotes, backslashes and control characters escaped.
   function JSON_Text (S : String) return String is
      Hex : constant String := "0123456789abcdef";
      R   : Unbounded_String;
   begin
      for C of S loop
         if C = '"' or else C = '\' then
            Append (R, '\' & C);
         elsif Character'Pos (C) < 32 then
            Append (R, "\u00" & Hex (Character'Pos (C) / 16 + 1)
                    & Hex (Character'Pos (C) mod 16 + 1));
         else
            Append (R, C);
         end if;
      end loop;
      return To_String (R);
   end JSON_Text;

   --  Task T lies below alternative Sel (O) of OR ordinal O.
   function Below (P : Problem; Sel : Location_Array; T, O : Positive) return Boolean is
      X : Natural := P.Task_Or (T);
      B : Natural := P.Task_Branch (T);
   begin
      while X /= 0 loop
         if X = O then
            return B = Sel (O);
         end if;
         B := Or_Branch (P, X);
         X := Or_Parent (P, X);
      end loop;
      return False;
   end Below;

   --  The tasks done for OR ordinal O's chosen alternative, by name.
   function Chosen_Tasks (P : Problem; A : Assignment; O : Positive; Sep, Quote : String)
     return String
   is
      R : Unbounded_String;
   begin
      for T in 1 .. P.Tasks loop
         if Is_Active (P, A.Branch, T) and then Below (P, A.Branch, T, O) then
            Append (R, (if R = "" then "" else Sep) & Quote & JSON_Text (Task_Name (P, T))
                    & Quote);
         end if;
      end loop;
      return To_String (R);
   end Chosen_Tasks;

   procedure Write_SVG (File : String; P : Problem; A : Assignment) is
      use Sancta.Geometry;
      F : File_Type;
      Min_X, Min_Y : Real := Real'Last;
      Max_X, Max_Y : Real := Real'First;
      Size : constant Real := 800.0;
      Colours : constant array (0 .. 9) of String (1 .. 7) :=
        ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4",
         "#42d4f4", "#f032e6", "#9a6324", "#808000", "#000075"];

      function SX (X : Real) return String is
        (Real_Img (Long_Float (20.0 + (X - Min_X) / Real'Max (1.0E-9, Max_X - Min_X) * Size), 1));
      function SY (Y : Real) return String is
        (Real_Img (Long_Float (20.0 + Size - (Y - Min_Y) / Real'Max (1.0E-9, Max_Y - Min_Y)
                               * Size), 1));
      function Pt (L : Natural) return String is
        (SX (P.Coordinates (L).X) & "," & SY (P.Coordinates (L).Y));
   begin
      if not P.Has_Coordinates then
         raise Usage_Error with "--svg: the instance has no coordinates";
      end if;
      for L in 1 .. P.Locations loop
         Min_X := Real'Min (Min_X, P.Coordinates (L).X);
         Max_X := Real'Max (Max_X, P.Coordinates (L).X);
         Min_Y := Real'Min (Min_Y, P.Coordinates (L).Y);
         Max_Y := Real'Max (Max_Y, P.Coordinates (L).Y);
      end loop;
      Create (F, Out_File, File);
      Put_Line (F, "<svg xmlns=""http://www.w3.org/2000/svg"" width=""840"" height=""840"">");
      Put_Line (F, "<rect width=""100%"" height=""100%"" fill=""white""/>");
      for R in 1 .. P.Robots loop
         Put (F, "<polyline fill=""none"" stroke-width=""2"" stroke="""
              & Colours ((R - 1) mod 10) & """ points=""" & Pt (P.Start (R)));
         for K in 1 .. A.Length (R) loop
            Put (F, " " & Pt (Location_Of (P, A.Tour (R, K), A.Choice (A.Tour (R, K)))));
         end loop;
         if Is_Closed (P, R) then
            Put (F, " " & Pt (P.Finish (R)));
         end if;
         Put_Line (F, """/>");
      end loop;
      for L in 1 .. P.Locations loop
         Put_Line (F, "<circle r=""3"" fill=""black"" cx=""" & SX (P.Coordinates (L).X)
                   & """ cy=""" & SY (P.Coordinates (L).Y) & """/>");
      end loop;
      --  Places not used: alternatives not chosen (OR nodes, locations), grey.
      for T in 1 .. P.Tasks loop
         for C in 1 .. P.Alt_Count (T) loop
            if not Is_Active (P, A.Branch, T) or else C /= A.Choice (T) then
               declare
                  L : constant Positive := Location_Of (P, T, C);
               begin
                  Put_Line (F, "<circle r=""4"" fill=""#cccccc"" stroke=""#999999"" cx="""
                            & SX (P.Coordinates (L).X) & """ cy=""" & SY (P.Coordinates (L).Y)
                            & """/>");
               end;
            end if;
         end loop;
      end loop;
      for R in 1 .. P.Robots loop
         Put_Line (F, "<rect width=""10"" height=""10"" fill=""black"" x="""
                   & Real_Img (Long_Float'Value (SX (P.Coordinates (P.Start (R)).X)) - 5.0, 1)
                   & """ y="""
                   & Real_Img (Long_Float'Value (SY (P.Coordinates (P.Start (R)).Y)) - 5.0, 1)
                   & """/>");
      end loop;
      Put_Line (F, "</svg>");
      Close (F);
   end Write_SVG;

   --  --solver exact beyond Held-Karp's size: an anneal of a tenth of the
   --  budget (at most 5 s) gives the first tour, branch and cut the rest.
   procedure Solve_By_Branch_And_Cut
     (P : Problem; Free_Tasks : Natural; Crit : Criterion; Opts : Annealers.Options;
      Result : out Assignment; Stats : out Annealers.Progress;
      Proven : out Boolean; Lower_Bound : out Cost; Note : out Unbounded_String)
   is
      Why : constant String := Sancta.Allocation.Branch_And_Cut.Supports (P);
      Budget : constant Duration := (if Opts.Time_Limit > 0.0 then Opts.Time_Limit else 86_400.0);
      Outcome : Sancta.Allocation.Branch_And_Cut.Result (P.Robots, P.Tasks);
      O : Annealers.Options := Opts;
   begin
      if Why /= "" then
         raise Usage_Error with "--solver exact: the instance has" & Free_Tasks'Image
           & " tasks (Held-Karp takes at most" & Sancta.Allocation.Exact.Max_Tasks'Image
           & ") and branch and cut cannot take it: " & Why;
      elsif Crit /= Min_Sum and then (P.Robots > 1 or else Crit = Min_Ave) then
         raise Usage_Error with "--solver exact: branch and cut minimises the total cost "
           & "(minsum; with one robot also minmax)";
      end if;
      O.Criterion := Min_Sum;
      O.Time_Limit := Duration'Max (0.05, Duration'Min (5.0, Budget / 10));
      O.Iterations := 0;
      O.Convergence := 0;
      Annealers.Solve (P, O, Result, Stats);
      Sancta.Allocation.Branch_And_Cut.Solve
        (P, Result, Outcome,
         (Time_Limit => Duration'Max (0.01, Budget - Stats.Elapsed), others => <>));
      Result := Outcome.Best;
      Proven := Outcome.Proven;
      Lower_Bound := Outcome.Lower;
      Note := To_Unbounded_String
        ("branch and cut:" & Outcome.Nodes'Image & " nodes," & Outcome.Cuts'Image & " cuts ("
         & Outcome.By_Class (Sancta.Allocation.Branch_And_Cut.Subtour)'Image & " subtour,"
         & Outcome.By_Class (Sancta.Allocation.Branch_And_Cut.Blossom)'Image & " blossom,"
         & Outcome.By_Class (Sancta.Allocation.Branch_And_Cut.Comb)'Image & " comb),"
         & Outcome.Edges'Image & " edges, root bound "
         & Real_Img (Outcome.Root_Bound, 1) & ", " & Real_Img (Long_Float (Outcome.Elapsed), 2)
         & " s (CPU " & Real_Img (Long_Float (Outcome.CPU), 2) & " s) after an anneal of "
         & Real_Img (Long_Float (Stats.Elapsed), 2) & " s");
   end Solve_By_Branch_And_Cut;

   procedure Run (First_Argument : Positive := 2) is
      File       : Unbounded_String;
      Robots     : Positive := 1;
      Crit_Name  : Unbounded_String := To_Unbounded_String ("minsum");
      Crit       : Criterion := Min_Sum;
      Opts       : Annealers.Options;
      Restarts   : Positive := 1;
      Profile    : Boolean := False;
      Solver     : Unbounded_String := To_Unbounded_String ("anneal");
      Real_Scale : Long_Float := 0.0;
      Open_Tours : Boolean := False;
      Min_Tasks  : Natural := 1;
      SVG, JSON  : Unbounded_String;
      I          : Natural := First_Argument;
      Time_Set   : Boolean := False;
      Subsets_Set : Boolean := False;
      Population_Set : Boolean := False;
      Proven     : Boolean := False;
      Lower_Bound : Cost := 0;
      Exact_Note : Unbounded_String;
      --  --solver exact: the proof or the bound, and how it was obtained.

      function Value_Of (Option : String) return String is
      begin
         if I + 1 > CL.Argument_Count then
            raise Usage_Error with Option & " needs a value";
         end if;
         I := I + 1;
         return CL.Argument (I);
      end Value_Of;

      function Number_In (Option : String; Low, High : Long_Float) return Long_Float is
         S : constant String := Value_Of (Option);
         X : Long_Float;
      begin
         X := Long_Float'Value (S);
         if X not in Low .. High then
            raise Constraint_Error;
         end if;
         return X;
      exception
         when Constraint_Error =>
            raise Usage_Error with Option & ": '" & S & "' is not a number in "
              & Real_Img (Low, 2) & " .. " & Real_Img (High, 2);
      end Number_In;
   begin
      Opts.Time_Limit := 10.0;
      Opts.Local_Search := 0.8;
      while I <= CL.Argument_Count loop
         declare
            A : constant String := CL.Argument (I);
         begin
            if A = "--help" or else A = "-h" then
               Help;
               return;
            elsif A = "--robots" then
               declare
                  N : constant Long_Long_Integer := Parse_Natural (A, Value_Of (A));
               begin
                  if N < 1 or else N > 1000 then
                     raise Usage_Error with "--robots: must be 1 .. 1000";
                  end if;
                  Robots := Positive (N);
               end;
            elsif A = "--objective" then
               Crit := Parse_Criterion (Value_Of (A), Crit_Name);
            elsif A = "--time" then
               Opts.Time_Limit := Parse_Duration (Value_Of (A));
               Time_Set := True;
               if Opts.Time_Limit < 0.0 then
                  raise Usage_Error with "--time: must not be negative";
               end if;
            elsif A = "--clock" then
               declare
                  K : constant String := Value_Of (A);
               begin
                  if K = "cpu" then
                     Opts.Budget_Clock := Budget_Clocks.CPU_Time;
                  elsif K = "wall" then
                     Opts.Budget_Clock := Budget_Clocks.Wall_Time;
                  else
                     raise Usage_Error with "--clock: '" & K & "' is not wall or cpu";
                  end if;
               end;
            elsif A = "--iterations" then
               Opts.Iterations := Parse_Natural (A, Value_Of (A));
               if not Time_Set then
                  Opts.Time_Limit := 0.0;
               end if;
            elsif A = "--converge" then
               Opts.Convergence := Parse_Natural (A, Value_Of (A));
            elsif A = "--seed" then
               Opts.Seed := Interfaces.Unsigned_64 (Parse_Natural (A, Value_Of (A)));
            elsif A = "--schedule" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  if S = "automatic" then
                     Opts.Schedule := Annealers.Automatic;
                  elsif S = "geometric" then
                     Opts.Schedule := Annealers.Geometric;
                  elsif S = "cyclic" then
                     Opts.Schedule := Annealers.Cyclic;
                  elsif S = "reheat" then
                     Opts.Schedule := Annealers.Reheat;
                  elsif S = "hybrid" then
                     Opts.Schedule := Annealers.Hybrid;
                  else
                     raise Usage_Error with "--schedule: '" & S
                       & "' is not automatic, geometric, cyclic, reheat or hybrid";
                  end if;
               end;
            elsif A = "--cycles" then
               declare
                  N : constant Long_Long_Integer := Parse_Natural (A, Value_Of (A));
               begin
                  if N < 1 or else N > 1000 then
                     raise Usage_Error with "--cycles: must be 1 .. 1000";
                  end if;
                  Opts.Cycles := Positive (N);
               end;
            elsif A = "--restarts" then
               declare
                  N : constant Long_Long_Integer := Parse_Natural (A, Value_Of (A));
               begin
                  if N < 1 or else N > 64 then
                     raise Usage_Error with "--restarts: must be 1 .. 64";
                  end if;
                  Restarts := Positive (N);
               end;
            elsif A = "--solver" then
               Solver := To_Unbounded_String (Value_Of (A));
               if To_String (Solver) not in "anneal" | "greedy" | "makespan" | "auction" | "exact"
               then
                  raise Usage_Error with "--solver: '" & To_String (Solver)
                    & "' is not anneal, greedy, makespan, auction or exact";
               end if;
            elsif A = "--real" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  Real_Scale := Long_Float'Value (S);
                  if Real_Scale <= 0.0 or else Real_Scale > 1.0E6 then
                     raise Constraint_Error;
                  end if;
               exception
                  when Constraint_Error =>
                     raise Usage_Error with "--real: '" & S & "' is not a scale in (0, 1e6]";
               end;
            elsif A = "--open" then
               Open_Tours := True;
            elsif A = "--min-tasks" then
               Min_Tasks := Natural (Long_Long_Integer'Min (1000, Parse_Natural (A, Value_Of (A))));
            elsif A = "--target" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  Opts.Target := Long_Float'Value (S);
                  if Opts.Target <= 0.0 then
                     raise Constraint_Error;
                  end if;
               exception
                  when Constraint_Error =>
                     raise Usage_Error with "--target: '" & S & "' is not a positive value";
               end;
            elsif A = "--runs" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  Opts.Runs := Natural'Value (S);
               exception
                  when Constraint_Error =>
                     raise Usage_Error with "--runs: '" & S & "' is not a count (0 = automatic)";
               end;
            elsif A = "--ruin" then
               Opts.Ruin_Share := Number_In (A, 0.0, 1.0);
            elsif A = "--geometric-share" then
               Opts.Geometric_Share := Number_In (A, 0.01, 0.99);
            elsif A = "--lk" then
               Opts.Local_Search := Number_In (A, 0.0, 0.95);
            elsif A = "--balance-decay" then
               Opts.Balance_Decay := True;
            elsif A = "--square" then
               Opts.Square_Balance := Number_In (A, 0.0, 10.0);
            elsif A = "--excess" then
               Opts.Excess_Weight := Number_In (A, 0.0, 10.0);
            elsif A = "--excess-band" then
               Opts.Excess_Band := Number_In (A, 0.0, 1.0);
            elsif A = "--subsets" then
               Opts.Subset_Share := Number_In (A, 0.0, 0.9);
               Subsets_Set := True;
            elsif A = "--subset-robots" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  Opts.Subset_Robots := Positive'Value (S);
                  if Opts.Subset_Robots not in 2 .. 5 then
                     raise Constraint_Error;
                  end if;
               exception
                  when Constraint_Error =>
                     raise Usage_Error with "--subset-robots: '" & S & "' is not a count in 2 .. 5";
               end;
            elsif A = "--subset-moves" then
               Opts.Subset_Moves := Number_In (A, 1.0, 1.0E6);
            elsif A = "--subset-t0" then
               Opts.Subset_Start_Factor := Number_In (A, 0.0, 10.0);
            elsif A = "--subset-total" then
               Opts.Subset_Total_Weight := Number_In (A, 0.0, 10.0);
            elsif A = "--population" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  Opts.Population := Natural'Value (S);
                  Population_Set := True;
                  if Opts.Population > 100 then
                     raise Constraint_Error;
                  end if;
               exception
                  when Constraint_Error =>
                     raise Usage_Error with "--population: '" & S & "' is not a count in 0 .. 100";
               end;
            elsif A = "--population-share" then
               Opts.Population_Share := Number_In (A, 0.05, 0.95);
            elsif A = "--child-moves" then
               Opts.Child_Moves := Number_In (A, 1.0, 1.0E6);
            elsif A = "--child-t0" then
               Opts.Child_Start_Factor := Number_In (A, 0.0, 10.0);
            elsif A = "--subset-fresh" then
               Opts.Subset_Fresh := True;
            elsif A = "--excess-reheats" then
               Opts.Excess_In_Reheats := True;
            elsif A = "--balance" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  Opts.Balance := Long_Float'Value (S);
               exception
                  when Constraint_Error =>
                     raise Usage_Error with "--balance: '" & S & "' is not a number";
               end;
            elsif A = "--t0" or else A = "--cool" then
               declare
                  S : constant String := Value_Of (A);
               begin
                  if A = "--t0" then
                     Opts.Start_Factor := Long_Float'Value (S);
                  else
                     Opts.End_Ratio := Long_Float'Value (S);
                  end if;
                  if Opts.Start_Factor <= 0.0 or else Opts.End_Ratio < 1.0 then
                     raise Constraint_Error;
                  end if;
               exception
                  when Constraint_Error =>
                     raise Usage_Error with A & ": '" & S & "' is not a valid factor";
               end;
            elsif A = "--no-polish" then
               Opts.Polish := False;
            elsif A = "--check" then
               Opts.Check := True;
            elsif A = "--quiet" then
               Quiet := True;
            elsif A = "--profile" then
               Profile := True;
            elsif A = "--svg" then
               SVG := To_Unbounded_String (Value_Of (A));
            elsif A = "--json" then
               JSON := To_Unbounded_String (Value_Of (A));
            elsif A'Length > 0 and then A (A'First) = '-' and then A /= "-" then
               raise Usage_Error with "unknown option '" & A & "' (see sancta plan --help)";
            elsif File = "" then
               File := To_Unbounded_String (A);
            else
               raise Usage_Error with "more than one FILE ('" & To_String (File) & "', '"
                 & A & "')";
            end if;
         end;
         I := I + 1;
      end loop;
      if File = "" then
         raise Usage_Error with "no FILE given (see sancta plan --help)";
      end if;
      Opts.Criterion := Crit;

      declare
         Name : constant String := To_String (File);
         Is_XML : constant Boolean :=
           Name'Length > 4 and then Name (Name'Last - 3 .. Name'Last) = ".xml";
         P : constant Problem_Access :=
           (if Is_XML then Sancta.Allocation.Problem_Files.Read (Name, Real_Scale)
            else TSPLIB.To_MTSP (TSPLIB.Read (Name, Real_Scale).all, Robots,
                                 Min_Tasks => Min_Tasks));
         Result : Assignment (P.Robots, P.Tasks);
         Stats : Annealers.Progress;
      begin
         Scale_Factor := P.Scale;
         Opts.Target := Opts.Target * Scale_Factor;
         if Open_Tours then
            for R in 1 .. P.Robots loop
               Set_Robot (P.all, R, P.Start (R), Closed => False,
                          Multiplier => P.Multiplier (R));
            end loop;
         end if;
         if Check (P.all) /= "" then
            raise Usage_Error with Name & ": " & Check (P.all);
         end if;
         if not Subsets_Set and then To_String (Solver) = "anneal"
           and then P.Tasks >= Auto_Subset_Min_Tasks
         then
            Opts.Subset_Share := Auto_Subset_Share;
            --  Only where Subsets.Applies: a pure makespan with 3+ robots
            --  (minsum, minave and TSP plans are unchanged).
         end if;
         if not Population_Set and then To_String (Solver) = "anneal"
           and then P.Tasks in Auto_Population_Min_Tasks .. Auto_Subset_Min_Tasks - 1
         then
            Opts.Population := Auto_Population;
            --  Only where Memetic.Applies: a pure makespan with 2+ robots
            --  (minsum, minave and TSP plans are unchanged).
         end if;
         declare
            S : constant String := To_String (Solver);
         begin
            if S = "anneal" and then Restarts = 1 then
               Annealers.Solve (P.all, (Opts with delta Report => Show'Access), Result, Stats);
            elsif S = "anneal" then
               declare
                  Runners : array (1 .. Restarts) of Runner;
                  Results : array (1 .. Restarts) of Result_Access;
                  Best_V  : Long_Float := Long_Float'Last;
                  use type Interfaces.Unsigned_64;
               begin
                  for K in 1 .. Restarts loop
                     Results (K) := new Run_Result (P.Robots, P.Tasks);
                     declare
                        O : Annealers.Options := Opts;
                     begin
                        O.Seed := Opts.Seed + Interfaces.Unsigned_64 (K - 1) * 7919;
                        O.Report := (if K = 1 then Show'Access else null);
                        Runners (K).Start (P, O, Results (K));
                     end;
                  end loop;
                  for K in 1 .. Restarts loop
                     Runners (K).Wait;
                     if Results (K).Error /= "" then
                        raise Program_Error with To_String (Results (K).Error);
                     end if;
                     if Results (K).Stats.Best < Best_V then
                        Best_V := Results (K).Stats.Best;
                        Result := Results (K).A;
                        Stats := Results (K).Stats;
                     end if;
                  end loop;
                  Stats.Moves := 0;
                  for K in 1 .. Restarts loop
                     Stats.Moves := Stats.Moves + Results (K).Stats.Moves;
                  end loop;
               end;
            elsif S = "exact" then
               if not Sancta.Allocation.Exact.Is_Pure (Crit) then
                  raise Usage_Error with "--solver exact: needs a pure criterion "
                    & "(minmax, minsum or minave)";
               end if;
               declare
                  Free_Tasks : Natural := 0;
               begin
                  for T in 1 .. P.Tasks loop
                     if not P.Is_Frozen (T) then
                        Free_Tasks := Free_Tasks + 1;
                     end if;
                  end loop;
                  if Free_Tasks <= Sancta.Allocation.Exact.Max_Tasks or else Has_Plan (P.all)
                  then
                     --  (With a plan, the active tasks of each selection
                     --  count: Held-Karp itself says when too many.)
                     Result := Sancta.Allocation.Exact.Solve (P.all, Crit);
                     Proven := True;
                     Exact_Note := To_Unbounded_String ("Held-Karp");
                  else
                     Solve_By_Branch_And_Cut (P.all, Free_Tasks, Crit, Opts, Result, Stats,
                                              Proven, Lower_Bound, Exact_Note);
                  end if;
               end;
            else
               Result := Sancta.Allocation.Baselines.Solve
                 (P.all, (if S = "greedy" then Sancta.Allocation.Baselines.Best_Pair
                          elsif S = "makespan" then Sancta.Allocation.Baselines.Min_Makespan
                          else Sancta.Allocation.Baselines.Auction), Crit);
            end if;
         end;
         if Has_Progress then
            New_Line (Standard_Error);
         end if;
         if Profile and then To_String (Solver) = "anneal" then
            Show_Profile (Stats);
         end if;

         declare
            E : constant Evaluation := Evaluate (P.all, Result, Crit);
            V : constant String := Validate (P.all, Result);
            Ave : constant Long_Float :=
              Long_Float (E.Completion_Sum) / Long_Float (Natural'Max (1, E.Active))
              / Scale_Factor;

            function Tour_Text (R : Positive; Sep : String) return String is
               T : Unbounded_String := To_Unbounded_String (Img (P.Start (R)));
            begin
               for K in 1 .. Result.Length (R) loop
                  Append (T, Sep & Img (Location_Of (P.all, Result.Tour (R, K),
                                                     Result.Choice (Result.Tour (R, K)))));
               end loop;
               if Is_Closed (P.all, R) then
                  Append (T, Sep & Img (P.Finish (R)));
               end if;
               return To_String (T);
            end Tour_Text;
         begin
            if V /= "" then
               Put_Line (Standard_Error, "sancta plan: warning: allocation not valid: " & V);
            end if;
            if not Quiet then
               for R in 1 .. P.Robots loop
                  Put_Line ("robot " & Img (R) & "  cost " & Cost_Img (E.Robot_Cost (R))
                            & "  tasks " & Img (Result.Length (R)) & "  tour "
                            & Tour_Text (R, " "));
               end loop;
               for O in 1 .. Or_Count (P.all) loop
                  Put_Line ("plan " & Or_Name (P.all, O)
                            & (if Or_Active (P.all, Result.Branch, O)
                               then " -> alternative " & Img (Result.Branch (O)) & " of "
                                    & Img (Alternatives (P.all, O)) & " ("
                                    & Chosen_Tasks (P.all, Result, O, ", ", "") & ")"
                               else " not reached"));
               end loop;
               for T in 1 .. P.Tasks loop
                  if P.Alt_Count (T) > 1 and then Is_Active (P.all, Result.Branch, T) then
                     Put_Line ("choice " & Task_Name (P.all, T) & " -> location "
                               & Img (Result.Choice (T)) & " of " & Img (P.Alt_Count (T)));
                  end if;
               end loop;
               Put_Line ("objective " & To_String (Crit_Name) & " = "
                         & Real_Img (E.Value / Scale_Factor, 3)
                         & "  makespan " & Cost_Img (E.Max) & "  total " & Cost_Img (E.Sum)
                         & "  mean completion " & Real_Img (Ave, 2));
               if To_String (Solver) = "exact" then
                  Put_Line ("exact: "
                            & (if Proven then "proven optimal"
                               elsif Lower_Bound = 0 then "time limit reached before a bound"
                               else "time limit reached: lower bound "
                                    & Cost_Img (Lower_Bound) & ", gap "
                                    & Real_Img (100.0 * Long_Float (E.Sum - Lower_Bound)
                                                / Long_Float (Lower_Bound), 3) & "%")
                            & " (" & To_String (Exact_Note) & ")");
               end if;
               if To_String (Solver) = "anneal" then
                  Put_Line ("moves " & Img (Stats.Moves) & "  ("
                            & Real_Img (Stats.Moves_Per_Second / 1.0E6, 2)
                            & " M/s)  time " & Real_Img (Long_Float (Stats.Elapsed), 2)
                            & " s  best found at " & Real_Img (Long_Float (Stats.Time_To_Best), 2)
                            & " s");
               end if;
            end if;
            if SVG /= "" then
               Write_SVG (To_String (SVG), P.all, Result);
            end if;
            if JSON /= "" then
               declare
                  J : Unbounded_String;
               begin
                  Append (J, "{""instance"": """ & Trim (P.Name) & """, ""file"": """ & Name
                          & """, ""solver"": """ & To_String (Solver)
                          & """, ""criterion"": """ & To_String (Crit_Name)
                          & """, ""weights"": [" & Real_Img (Crit.Max_Weight, 6) & ", "
                          & Real_Img (Crit.Sum_Weight, 6) & ", " & Real_Img (Crit.Ave_Weight, 6)
                          & "], ""seed"": " & Trim (Opts.Seed'Image)
                          & ", ""robots"": " & Img (P.Robots) & ", ""tasks"": " & Img (P.Tasks)
                          & ", ""objective"": " & Real_Img (E.Value / Scale_Factor, 4)
                          & ", ""makespan"": " & Cost_Img (E.Max)
                          & ", ""total"": " & Cost_Img (E.Sum)
                          & ", ""mean_completion"": " & Real_Img (Ave, 4)
                          & ", ""valid"": " & (if V = "" then "true" else "false")
                          & ", ""proven"": " & (if Proven then "true" else "false")
                          & ", ""lower_bound"": "
                          & (if Lower_Bound > 0 then Cost_Img (Lower_Bound) else "null")
                          & ", ""clock"": """ & Budget_Clocks.Image (Opts.Budget_Clock) & """"
                          & ", ""time_limit"": " & Real_Img (Long_Float (Opts.Time_Limit), 3)
                          & ", ""cpu_time"": " & Real_Img (CPU_Seconds, 3)
                          & ", ""time_used"": " & Real_Img (Long_Float (Stats.Elapsed), 3)
                          & ", ""time_to_best"": " & Real_Img (Long_Float (Stats.Time_To_Best), 3)
                          & ", ""moves"": " & Img (Stats.Moves)
                          & ", ""moves_per_second"": " & Real_Img (Stats.Moves_Per_Second, 0)
                          & ", ""tours"": [");
                  for R in 1 .. P.Robots loop
                     Append (J, (if R > 1 then ", " else "") & "{""robot"": " & Img (R)
                             & ", ""cost"": " & Cost_Img (E.Robot_Cost (R))
                             & ", ""tour"": [" & Tour_Text (R, ", ") & "], ""tasks"": [");
                     for K in 1 .. Result.Length (R) loop
                        Append (J, (if K > 1 then ", " else "") & """"
                                & JSON_Text (Task_Name (P.all, Result.Tour (R, K))) & """");
                     end loop;
                     Append (J, "]}");
                  end loop;
                  Append (J, "], ""active_tasks"": " & Img (E.Active) & ", ""plan"": [");
                  for O in 1 .. Or_Count (P.all) loop
                     Append (J, (if O > 1 then ", " else "") & "{""or"": """
                             & JSON_Text (Or_Name (P.all, O)) & """, ""reached"": "
                             & (if Or_Active (P.all, Result.Branch, O) then "true" else "false")
                             & ", ""alternative"": " & Img (Result.Branch (O))
                             & ", ""alternatives"": " & Img (Alternatives (P.all, O))
                             & ", ""tasks"": ["
                             & (if Or_Active (P.all, Result.Branch, O)
                                then Chosen_Tasks (P.all, Result, O, ", ", """") else "")
                             & "]}");
                  end loop;
                  Append (J, "], ""choices"": [");
                  declare
                     First : Boolean := True;
                  begin
                     for T in 1 .. P.Tasks loop
                        if P.Alt_Count (T) > 1 and then Is_Active (P.all, Result.Branch, T) then
                           Append (J, (if First then "" else ", ") & "{""task"": """
                                   & JSON_Text (Task_Name (P.all, T)) & """, ""location"": "
                                   & Img (Result.Choice (T)) & ", ""locations"": "
                                   & Img (P.Alt_Count (T)) & "}");
                           First := False;
                        end if;
                     end loop;
                  end;
                  Append (J, "]}");
                  if To_String (JSON) = "-" then
                     Put_Line (To_String (J));
                  else
                     declare
                        F : File_Type;
                     begin
                        Create (F, Out_File, To_String (JSON));
                        Put_Line (F, To_String (J));
                        Close (F);
                     end;
                  end if;
               end;
            end if;
         end;
      end;
   exception
      when E : Usage_Error =>
         Put_Line (Standard_Error, "sancta plan: " & Ada.Exceptions.Exception_Message (E));
         CL.Set_Exit_Status (CL.Failure);
      when E : Format_Error | Sancta.Configuration_Error =>
         Put_Line (Standard_Error, "sancta plan: " & Ada.Exceptions.Exception_Message (E));
         CL.Set_Exit_Status (CL.Failure);
      when E : Ada.Text_IO.Name_Error | Ada.Text_IO.Use_Error =>
         Put_Line (Standard_Error, "sancta plan: cannot write: "
                   & Ada.Exceptions.Exception_Message (E));
         CL.Set_Exit_Status (CL.Failure);
      when E : Constraint_Error =>
         Put_Line (Standard_Error, "sancta plan: " & Ada.Exceptions.Exception_Message (E));
         CL.Set_Exit_Status (CL.Failure);
   end Run;

end Sancta.Commands.Plan;
