--  The simulated annealer. A solution is one tour per robot held in arrays
--  with prefix sums of forward and reverse arc costs and of arrival times;
--  every move is described as at most two new tours, each a short list of
--  segments of the current tours (forward or reversed) and single tasks, so
--  its exact cost change (length, completion times, infeasibility) is
--  computed in O(segments) = O(1) without applying it; the makespan comes
--  from a max segment tree over robot costs (O(log R)).
--
--  Moves: relocate / Or-opt (segments of 1..3 tasks, possibly reversed) next
--  to a candidate neighbour (k nearest), 2-opt within a tour, Or-3opt
--  (segment exchange of any lengths, both new arcs next to neighbours),
--  2-opt* between tours (tails swapped, or crossed with reversal: 2-opt
--  across two tours through a common depot), cross-exchange between tours,
--  the old moves (random move, move to another robot, guided move from the
--  worst robot, swap any, log auction, switch OR alternative), switch
--  subtree for plan trees (another alternative at an OR node: the leaving
--  tasks are removed, the coming ones inserted, cheapest or at random, the
--  touched robots' costs recomputed exactly), and ruin and recreate (a task
--  and some of its neighbours, for makespan often from the longest tour,
--  taken out and put back at their best places) on a fixed share of the
--  work, and for makespan criteria ejection chains (package Chains) after
--  the final descent (optionally on a share of the work); adaptive move
--  weights; geometric (optionally as several independent runs sharing the
--  budget), cyclic, the old re-heating schedule or a hybrid of geometric
--  and re-heating (the default for a pure makespan); budgets by time,
--  iterations and convergence; a final descent (polish) with the
--  neighbour moves. Per-kind statistics in Progress.Kinds.
--  On single closed tours, a share of the time may then go to iterated
--  local search (Opts.Local_Search, package Local_Search); otherwise, for
--  criteria without the mean completion time, every route is polished by
--  the same search (2-opt, Or-opt, LK chains of depth 5): one descent, or
--  iterated in that share of the time for a single robot. For those
--  criteria the current routes also get one such descent every
--  Route_Search_Interval x tasks moves during the anneal (kind
--  Route_Search), so that the inter-route moves work on short routes.
--
--     O : Options := (Criterion => Min_Max, Seed => 7, Time_Limit => 2.0, others => <>);
--     Solve (P.all, O, Best, Stats);
with Interfaces;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Budget_Clocks;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Annealers is

   type Schedule_Kind is (Automatic, Geometric, Cyclic, Reheat, Hybrid);
   --  Automatic: Hybrid for a pure makespan (Min_Max) with several robots
   --  when the budget leaves its reheats 5 M moves (estimated after 1% of
   --  it), Geometric otherwise.
   --  Geometric: T0 -> T1 over the budget. Cyclic: Cycles geometric runs,
   --  each from the best so far at a lower start temperature.
   --  Reheat: the old "manual" schedule: divide T by 1.85 after a stretch
   --  without improvement, back to T0 after a long stretch without a new best.
   --  Hybrid: Geometric over the first Geometric_Share of the budget, then
   --  Reheat from the best so far (at T1 first) for the rest.

   protected type Best_Box (Robots : Positive; Tasks : Positive) is
      --  Anytime access to a running annealer's best allocation: it posts
      --  it here at every progress report (Opts.Report_Every) and at the end.
      procedure Post (A : Assignment; V : Long_Float);
      function Has_Value return Boolean;
      function Value return Long_Float;
      function Best return Assignment;
   private
      Current : Assignment (Robots, Tasks);
      Current_Value : Long_Float := Long_Float'Last;
      Posted : Boolean := False;
   end Best_Box;

   type Move_Kind is
     (Or_Opt_Near, Two_Opt_Near, Or3_Near, Cross_Near, Random_Move, Move_Owner,
      Guided_Move, Log_Auction, Swap_Any, Switch_Or, Segment_Move, Random_Reverse,
      Switch_Subtree, Ruin_Recreate, Route_Search, Ejection_Chain);
   --  The annealer's neighbourhoods (see the package comment). Route_Search
   --  is not drawn: every Route_Search_Interval x tasks moves, the current
   --  routes get a descent of the route search (2-opt, Or-opt, LK chains;
   --  criteria without the mean completion time), so that the anneal goes
   --  on from shorter routes. Ejection_Chain is not drawn either: for
   --  makespan criteria the final descent ends with ejection chains (the
   --  longest tour gives a segment to a neighbouring tour, which gives one
   --  on, until a tour with slack takes it; kept only if the objective
   --  falls) until none helps, and Chain_Share of the anneal's work may
   --  go to them.

   type Kind_Flags is array (Move_Kind) of Boolean;

   Max_Runs : constant := 4;

   Route_Search_Interval : constant := 50;
   --  Moves per task between two route searches inside the anneal.

   type Kind_Stats is record
      Tries     : Long_Long_Integer := 0;
      --  Moves of this kind drawn.
      Legal     : Long_Long_Integer := 0;
      --  ... that gave a legal move (evaluated).
      Accepted  : Long_Long_Integer := 0;
      Improving : Long_Long_Integer := 0;
      --  ... accepted with a strict decrease of the search objective.
      New_Best  : Long_Long_Integer := 0;
   end record;
   type Kind_Stats_Array is array (Move_Kind) of Kind_Stats;
   --  What each neighbourhood achieved in the annealing phase (profiling).

   type Progress is record
      Best          : Long_Float := 0.0;
      Current       : Long_Float := 0.0;
      Temperature   : Long_Float := 0.0;
      Moves         : Long_Long_Integer := 0;
      Accepted      : Long_Long_Integer := 0;
      Elapsed       : Duration := 0.0;
      Moves_Per_Second : Long_Float := 0.0;
      Time_To_Best  : Duration := 0.0;
      Kinds         : Kind_Stats_Array;
      Polish_Gain   : Long_Float := 0.0;
      --  How much the final descent lowered the objective.
      Switches      : Long_Long_Integer := 0;
      --  Accepted switch subtree moves (plan trees).
   end record;

   type Reporter is access procedure (P : Progress);

   type Options is record
      Criterion    : Allocation.Criterion := Min_Sum;
      Seed         : Interfaces.Unsigned_64 := 1;
      Time_Limit   : Duration := 1.0;
      --  Time budget on Budget_Clock; 0.0 = none (then Iterations must be set).
      Budget_Clock : Budget_Clocks.Clock_Kind := Budget_Clocks.Wall_Time;
      --  CPU_Time: Time_Limit is CPU time of the calling task (the search
      --  runs in it), for figures that do not depend on the machine's load.
      Iterations   : Long_Long_Integer := 0;
      --  Move budget; 0 = none. With only this budget, runs are deterministic.
      Convergence  : Long_Long_Integer := 0;
      --  Stop after this many moves without a new best; 0 = never.
      Schedule     : Schedule_Kind := Automatic;
      Runs         : Natural := 0;
      --  Geometric: independent anneals, each from a fresh start, sharing
      --  the budget (the best is kept); 0 = automatic: as many (at most
      --  Max_Runs) as give each Run_Moves x tasks ** 2 moves, from the move
      --  rate measured over the first 2% of the budget.
      Run_Moves    : Long_Float := 1000.0;
      Geometric_Share : Long_Float := 0.5;
      --  Hybrid: the share of the budget cooled geometrically (0 .. 1;
      --  Solve raises Constraint_Error outside).
      Cycles       : Positive := 3;
      Cycle_Drop   : Long_Float := 3.0;
      --  Cyclic: each cycle restarts from the best at T0 / Cycle_Drop ** k.
      Start_Temperature : Long_Float := 0.0;
      End_Temperature   : Long_Float := 0.0;
      --  0.0 = automatic, from sampled move deltas: T0 = Start_Factor *
      --  mean uphill delta, T1 = T0 / End_Ratio.
      Start_Factor : Long_Float := 0.5;
      End_Ratio    : Long_Float := 2000.0;
      Neighbours   : Positive := 10;
      Adaptive     : Boolean := True;
      Polish       : Boolean := True;
      Check        : Boolean := False;
      --  Expensive check: after every applied move, recompute all costs
      --  from scratch and compare with the incremental ones and with the
      --  move's predicted costs; Program_Error on any difference.
      Initial      : Boolean := False;
      --  Start from Start_From (below) instead of best insertion.
      Report_Every : Duration := 0.5;
      Report       : Reporter := null;
      --  When set, called every Report_Every with the progress.
      Balance      : Long_Float := 0.05;
      --  Pure makespan only: weight of the total cost in the search
      --  objective (decaying to a tie-break if Balance_Decay); < 0 = 1 / Robots.
      Balance_Decay : Boolean := False;
      Square_Balance : Long_Float := 0.0;
      --  Pure makespan, every task feasible for every robot: weight of the
      --  sum of squared robot costs in the search objective, scaled so that
      --  a unit of a mean-length tour weighs this much (each tour pushed
      --  down by its size, not only the longest); 0 = none. Off by default:
      --  0.1 measured no better than the total-cost balance alone (kroA100,
      --  rat99, kroA200 with 5 robots).
      Excess_Weight : Long_Float := 1.0;
      Excess_Band   : Long_Float := 0.04;
      --  Pure makespan, every task feasible for every robot, Square_Balance
      --  0: the search objective adds the sum over tours of the squared
      --  excess over a floor Excess_Band x the best makespan so far below
      --  it, scaled so that the longest tour's excess weighs Excess_Weight
      --  per unit of cost (every tour near the makespan is pushed down, not
      --  only the longest: with many robots several tours sit within a few
      --  per cent of it); the floor follows each lower best makespan; the
      --  reported value and the best kept stay the makespan. 0 = none.
      --  Measured at 10 robots, 10 M moves on 6 unseen instances (2 seeds):
      --  -0.87% mean (band 0.02: -0.58%, 0.08: -0.79%; weight 2: -0.26%).
      Excess_In_Reheats : Boolean := False;
      --  Hybrid schedule: the excess term steers the reheats too; off, it
      --  leaves the search objective when they start, and the reheats
      --  from the best anneal on the makespan itself (+ Balance). The
      --  term's own optimum can differ from the makespan's: it penalizes
      --  tours tied at the makespan, which an optimal plan often has
      --  (berlin52, 3 robots, 30 M moves: 3070 = best-known on 5 of 6
      --  seeds without the term in the reheats, 3 of 6 with it). Short
      --  budgets (geometric cooling only) keep the term throughout: it
      --  gives most there (0.1 s of CPU, 700-1000 tasks, 10 robots: about
      --  10% lower makespans than when it stops half way).
      Enabled      : Kind_Flags := [others => True];
      --  The move kinds used (tests exercise one kind at a time).
      Ruin_Share   : Long_Float := 0.2;
      --  Share of the move evaluations spent in ruin and recreate moves
      --  (a task and some of its neighbours taken out and put back at their
      --  best places); 0 = none.
      Chain_Share  : Long_Float := 0.0;
      --  Makespan criteria: share of the move evaluations spent in
      --  ejection chains during the anneal (see Move_Kind); 0 = none (the
      --  final descent still ends with them). Off by default: 0.1 measured
      --  mixed at 10 robots (-1.6% to +5.4% at 350-750 tasks).
      Local_Search : Long_Float := 0.0;
      --  The share of Time_Limit given, after the anneal, to iterated 2-opt /
      --  Or-opt / LK search with candidate lists and don't-look bits: on the
      --  tour (one robot on a closed symmetric tour, Local_Search.Applies)
      --  or on one robot's route (Polish, no mean completion time, nothing
      --  to choose but the order); 0 = none. Teams get one route descent.
      Target       : Long_Float := 0.0;
      --  Stop as soon as the best value (of Criterion) is <= Target; 0 = none.
      Box          : access Best_Box := null;
      --  When set, the best so far is posted there (anytime use).
      Subset_Share : Long_Float := 0.0;
      --  Pure makespan, several robots (see Subsets.Applies): the share of
      --  the budget (moves and time) given after the anneal to route-subset
      --  re-optimisation: the longest tour and Subset_Robots - 1 tours near
      --  it pooled, re-annealed as a problem of their own (Subset_Moves x
      --  its tasks moves, own seed), put back when their makespan falls (or
      --  stays and their total falls); 0 = none. `sancta plan` uses 0.2 from
      --  200 tasks up when --subsets is not given. Measured against none at
      --  the same --time (the anneal alone stops at ~92% of a budget; with
      --  subsets the run spends all of it), session 15, 9 unseen instances
      --  of 150-1000 tasks x 3 / 5 / 10 robots: 10 s CPU, 250-1000 tasks
      --  -0.59% mean makespan (34 better / 12 worse / 2 equal; m = 3 -0.05%,
      --  5 -0.63%, 10 -1.10%), 150 tasks +0.26% (1 / 2 / 3); 10 M moves
      --  -0.12% (14 / 9); 1 s neutral (+0.04%, 50 / 43). Session 14 saw a
      --  loss at 1000 tasks (one unseen instance +0.20% at 10 s;
      --  pr2392-first1000 x 10 +1.35% -> +2.10% of LKH-3) that the new
      --  1000-task instances did not repeat (-0.56%, 8 / 4).
      Subset_Robots : Positive := 3;
      Subset_Moves  : Long_Float := 5000.0;
      Subset_Start_Factor : Long_Float := 0.05;
      --  The sub-anneals' Start_Factor (0.0: Start_Factor): low, so that
      --  they refine the current tours rather than scramble them.
      Subset_Total_Weight : Long_Float := 0.0;
      --  > 0: the sub-anneals minimise makespan + this x total, the subset
      --  starts from a random robot half the time (else the longest), and
      --  a result is kept when the whole plan's makespan falls, or stays
      --  and its total falls (lower totals give slack to later subsets).
      Subset_Fresh  : Boolean := False;
      --  The sub-anneal starts from its own construction (else from the
      --  current tours of those robots).
      Population : Natural := 0;
      --  Pure makespan, 2+ robots (see Memetic.Applies): a population
      --  search of this many plans instead of one anneal: independent
      --  anneals first (Population_Share of the budget), then children of
      --  two of them (order crossover of their giant tours, optimal split,
      --  an anneal of Child_Moves x tasks moves from there at
      --  Child_Start_Factor) replacing the worst; 0 or 1 = none. `sancta
      --  plan` uses 4 from 60 to 199 tasks when --population is not given.
      --  Measured against none (4, 0.5, 2000, 0.05), session 16, 10 unseen
      --  instances of 59-199 tasks x 3 / 5 / 10 robots (rat99/5 among
      --  them): 4 M moves -0.73% mean makespan (16 better / 4 worse, n 30;
      --  6 plans, 1000 moves per task: -0.69%, 16 / 4); 10 s CPU -0.35%
      --  (11 / 4, n 30; rat99/5 449 448 448 against 448 458 456); 1 s CPU
      --  -0.63% (33 / 6, n 60); 0.1 s CPU -0.48% (32 / 17, n 60).
      Population_Share : Long_Float := 0.5;
      --  The share of the budget for the first members (0 .. 1; Solve
      --  raises Constraint_Error outside).
      Child_Moves : Long_Float := 2000.0;
      --  Moves per task of a child's anneal.
      Child_Start_Factor : Long_Float := 0.05;
      --  The children's anneals' Start_Factor (0.0: Start_Factor): low, so
      --  that they repair the split child rather than scramble it.
   end record;

   procedure Solve
     (P      : Problem;
      Opts   : Options;
      Best   : in out Assignment;
      Stats  : out Progress)
     with Pre => Best.Robots = P.Robots and then Best.Tasks = P.Tasks
                 and then Check (P) = "";
   --  Anneals and returns the best allocation found in Best (read as the
   --  start when Opts.Initial).

   function Greedy_Start (P : Problem; C : Criterion; Seed : Interfaces.Unsigned_64)
     return Assignment;
   --  The annealer's start: tasks in random order, each at its best
   --  insertion for C (after giving each robot its minimum count).

end Sancta.Allocation.Annealers;
