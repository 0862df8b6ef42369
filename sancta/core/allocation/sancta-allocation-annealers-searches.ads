--  The annealing run: a Search record holds everything one run of Solve
--  shares (the tours, the best so far, temperatures, move weights,
--  counters) and small procedures do one job each: the set-up, the budget
--  and temperature schedule, one move (drawn, evaluated, accepted or not),
--  ruin and recreate, the final descent, the reports.
--
--     Run : Search (P.Robots, P.Tasks);
--     Start (Run, P, Opts, Best);
--     Anneal (Run, P);
--     Finish (Run, P, Best, Stats);
with Ada.Finalization;
with Ada.Real_Time;
with Sancta.Allocation.Random;
with Sancta.Allocation.Annealers.Chains;
with Sancta.Allocation.Annealers.Moves;      use Sancta.Allocation.Annealers.Moves;
with Sancta.Allocation.Annealers.Plan_Trees; use Sancta.Allocation.Annealers.Plan_Trees;
with Sancta.Allocation.Annealers.Tours;      use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Searches is

   type Kind_Reals is array (Move_Kind) of Long_Float;

   type Search (Robots, Tasks : Positive) is new Ada.Finalization.Limited_Controlled with
   record
      Opts            : Options;
      Tours           : State_Access;
      --  The current solution.
      Switch          : Switch_Access;
      Locked          : Boolean_Array (1 .. Tasks) := [others => False];
      --  Plan trees: the switch subtree move's new tours, and the OR
      --  ordinals it must not switch (above a frozen task).
      Best            : Assignment (Robots, Tasks);
      Best_Value      : Long_Float := Long_Float'Last;
      --  The best solution and its value for Goal.
      Best_Saved      : Boolean := True;
      --  Best holds the best solution; False while the current solution is
      --  a better one not yet copied (copied before leaving it).
      Backup          : Assignment (Robots, Tasks);
      --  The solution before a ruin and recreate.
      Neighbours      : Positive := 1;
      Log_Tries       : Positive := 1;
      --  Candidate neighbours per task; tries of the best-of-a-few moves.
      Generator       : Random.Generator;
      Started, Next_Report : Ada.Real_Time.Time;
      Guide, Goal     : Weights;
      --  Guide steers the search, Goal is the criterion (with its tie-break).
      Initial_Balance : Long_Float := 0.0;
      --  Pure makespan: Guide adds Balance x total cost, Balance decaying
      --  from Initial_Balance to Goal.Tie over the budget.
      Current         : Long_Float := 0.0;
      --  The current solution's value for Guide.
      Excess_Floor    : Boolean := False;
      Excess_Makespan : Cost := 0;
      --  Guide has the squared-excess term (Options.Excess_Weight), its
      --  floor set from this best makespan (until the hybrid schedule's
      --  reheats, unless Options.Excess_In_Reheats).
      Moves, Accepted, Last_Best_Move, Switches : Long_Long_Integer := 0;
      Ruin_Evaluations : Long_Long_Integer := 0;
      --  Move evaluations spent in ruin and recreate (best insertions).
      Chain_Space     : Chains.Workspace_Access;
      Chain_Evaluations : Long_Long_Integer := 0;
      --  Ejection chains (makespan criteria; null otherwise): their undo
      --  record and the move evaluations spent in them.
      Start_Temperature, End_Temperature, Temperature : Long_Float := 0.0;
      Reheat_Temperature : Long_Float := 0.0;
      Since_Improve   : Long_Long_Integer := 0;
      Cycle_Best      : Long_Float := 0.0;
      Cycle           : Natural := 0;
      Reheating       : Boolean := False;
      Automatic_Hybrid : Boolean := False;
      --  Reheat and cyclic schedules; Hybrid: past its geometric share, and
      --  chosen by Automatic (not yet checked against the budget).
      Runs            : Positive := 1;
      Run             : Natural := 0;
      Runs_Decided    : Boolean := False;
      --  Geometric schedule: Runs independent anneals share the budget, each
      --  from a fresh start; Run is the current one (from 0).
      Elapsed, Best_Time : Duration := 0.0;
      Weight          : Kind_Reals := [others => 0.0];
      Score, Tries    : Kind_Reals := [others => 0.0];
      --  Adaptive move weights: draws and successes since the last update.
      Weight_Total    : Long_Float := 0.0;
      --  The sum of Weight (Sum_Of), set wherever Weight changes: what
      --  Pick_Kind draws against (checked under Options.Check).
      Only_Ruin       : Boolean := False;
      --  No drawn move kind is enabled: every move is a ruin and recreate.
      Kinds           : Kind_Stats_Array;
      Polish_Gain     : Long_Float := 0.0;
      Route_Searches  : Boolean := False;
      Next_Route_Search : Long_Long_Integer := 0;
      --  Route search inside the anneal (see Move_Kind): on, and the move
      --  count of the next one.
      Stop            : Boolean := False;
   end record;

   overriding procedure Finalize (This : in out Search);

   procedure Start
     (This   : in out Search;
      P      : Problem;
      Opts   : Options;
      Best   : Assignment);
   --  Checks the budget, the move kinds and the initial allocation (Best
   --  when Opts.Initial), builds the start and samples the temperatures.

   procedure Anneal (This : in out Search; P : Problem);
   --  The annealing loop, until the budget is spent or the target reached.

   procedure Finish
     (This : in out Search; P : Problem; Best : in out Assignment; Stats : out Progress);
   --  The final descent (Opts.Polish), the last report, the results.

end Sancta.Allocation.Annealers.Searches;
