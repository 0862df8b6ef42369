--  Iterated local search on symmetric tours: 2-opt, Or-opt moves (segments
--  of 1 .. 3 tasks, both orientations) and Lin-Kernighan chains (sequential
--  moves of depth up to 5 built of 2-opt steps, breadth 5, 3, 1, 1, 1) over
--  candidate lists (the K nearest tasks) with don't-look bits, and
--  Or-opt style kicks (a double bridge inside a window of nearby
--  positions) accepted when the tour does not get longer. Memory and work
--  per move are O(n K) and O(K) (a 2-opt reversal is O(n) at worst, the
--  shorter side); distances come from the problem's matrix (a route of at
--  most 1000 nodes of a problem with a matrix: a 32-bit copy of the
--  route's own, filled with the candidate lists).
--
--     if Applies (P.all) then
--        Improve (P.all, A, (Time_Limit => 5.0, others => <>), Stats);   --  one robot's tour
--     end if;
--     Polish_Routes (P.all, A, (others => <>), Stats);   --  any team: each route shortened
--
--  Polish_Routes works on every robot's own route (after its frozen
--  prefix, to its end: its start, another depot or anywhere): route
--  lengths never grow, so the makespan and the total cost never get worse
--  (not for the mean completion time, which depends on the order).
with Interfaces;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Budget_Clocks;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Local_Search is

   function Applies (P : Problem) return Boolean;
   --  One robot on a closed tour back to its start, symmetric shared
   --  costs, no OR alternatives or plan tree, no frozen prefix, at least 8
   --  tasks.

   type Statistics is record
      Kicks     : Long_Long_Integer := 0;
      Improving : Long_Long_Integer := 0;
      --  Kicks after which the tour got shorter.
      Before, After : Cost := 0;
      Elapsed       : Duration := 0.0;
      Time_To_Best  : Duration := 0.0;
      --  Since the call: the whole search, the last improvement.
   end record;

   type Search_Options is record
      Time_Limit   : Duration := 0.0;
      --  0.0: one descent, no kicks, however long it takes.
      Budget_Clock : Budget_Clocks.Clock_Kind := Budget_Clocks.Wall_Time;
      --  The clock Time_Limit is measured on.
      Seed         : Interfaces.Unsigned_64 := 1;
      --  Of the kicks' random choices.
      Neighbours   : Positive := 8;
      --  Length of each task's candidate list (its nearest tasks).
      Kicks        : Boolean := True;
      --  False: descents only, each stopped at the end of the budget.
      Target       : Cost := 0;
      --  > 0: stop as soon as the tour is no longer than Target.
      Check        : Boolean := False;
      --  After every move the tour length is recomputed and compared with
      --  the incremental one (Program_Error on a difference).
   end record;

   procedure Improve
     (P : Problem; A : in out Assignment; Opts : Search_Options; Stats : out Statistics)
     with Pre => Applies (P) and then A.Robots = 1 and then A.Tasks = P.Tasks
                 and then A.Length (1) = P.Tasks;
   --  A's tour improved for Opts.Time_Limit, the descents included
   --  (Stats.Time_To_Best: when it got to its best, or to Opts.Target).

   Direct_Size : constant := 1_000;
   --  Above this many tasks, a single tour (Applies) is not annealed first:
   --  the annealer's set-up and moves cost too much at that size, the
   --  search starts from Nearest_Neighbour_Tour with the whole budget.

   function Nearest_Neighbour_Tour (P : Problem) return Assignment
     with Pre => Applies (P);
   --  From the depot, always on to the nearest task not yet visited
   --  (O (n^2) distance reads, no matrix of its own).

   procedure Polish_Routes
     (P : Problem; A : in out Assignment; Opts : Search_Options; Stats : out Statistics;
      Distance : access function (R : Positive; From, To : Natural) return Cost := null)
     with Pre => A.Robots = P.Robots and then A.Tasks = P.Tasks and then Opts.Target = 0;
   --  Each route of A with at least 5 free tasks and symmetric distances
   --  for its robot (the shared matrix, or its own on the route's
   --  locations) improved by the same search, Opts.Time_Limit shared among
   --  the routes by their task counts (0.0: one descent each, unbounded;
   --  a route whose candidate lists, O (M^2) for M tasks, are not built
   --  within its share is left as it is); route R's kicks draw from seed
   --  Opts.Seed + R. Tasks, their robots, choices and frozen prefixes stay;
   --  Stats.Before / After are the sums of the searched routes' base
   --  lengths. Distance, when not null, must return Robot_Distance (P, R,
   --  From, To) (the same integers; the annealer's compact copy): a route's
   --  own matrix is then filled from it, not from P's (at 1000 tasks, the
   --  8 MB problem matrix read at random): in the anneal (release, MinMax,
   --  fixed move budget, min of 3 runs, plans identical) CPU -2.6% at 500
   --  tasks x 10 robots, -4.5% at 1000 x 10, -3.0% at 1000 x 5.

end Sancta.Allocation.Local_Search;
