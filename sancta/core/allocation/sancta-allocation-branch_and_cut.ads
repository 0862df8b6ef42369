--  An exact solver by branch and cut (the role Concorde played for the
--  original SANCTA): the LP relaxation of the symmetric TSP (degree
--  equations, subtour-elimination cuts found by minimum-cut separation:
--  connected components, then every cut of the phase of Stoer-Wagner below
--  2; blossoms by the odd-component heuristic and by Padberg-Rao's exact
--  minimum odd cut; combs from blocks), solved by GLPK's simplex on a
--  sparse edge set priced against all edges, a pool of purged cuts,
--  reduced-cost fixing against the heuristic's tour at every node, strong
--  branching and best-bound node selection. It returns the best tour with a
--  proof (lower bound = tour cost) or, at its time limit, the best tour
--  and the lower bound reached (the gap).
--
--  Transformations (as the paper did): robots become depot nodes of one
--  Hamiltonian cycle (arc robot -> task from the robot's start, arc task ->
--  depot to the common finish; depot -> depot = an idle robot, forbidden
--  when every robot must work); open tours end "nowhere" at cost 0; an
--  asymmetric cycle is solved as a symmetric one on 2 N nodes (each node an
--  in/out pair joined by a fixed edge).
--
--     R : Result (P.Robots, P.Tasks);
--     Solve (P.all, Start => Greedy, Outcome => R, Config => (Time_Limit => 60.0, others => <>));
--     --  R.Proven, R.Upper, R.Lower, R.Best
--
--  Supported (Supports returns ""): the MinSum criterion (for one robot
--  every pure criterion but MinAve), no OR alternatives or plan tree, no
--  frozen prefix, Min_Tasks <= 1; with several robots also one shared cost
--  function, equal multipliers, all pairs feasible and one finish for all
--  (the same depot, or open tours). Limit: Max_Nodes cycle nodes.
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Branch_And_Cut is

   Max_Nodes : constant := 1_200;
   --  Nodes of the symmetric cycle (2 x (tasks + robots) when asymmetric).

   function Supports (P : Problem) return String;
   --  "" when P can be solved here; else why not.

   type Cut_Class is (Subtour, Blossom, Comb);
   type Cut_Counts is array (Cut_Class) of Natural;

   type Settings is record
      Heuristic_Blossoms : Boolean := True;
      --  Odd components of the fractional edges (Groetschel-Holland).
      Exact_Blossoms     : Boolean := True;
      --  Padberg-Rao minimum odd cuts, when the heuristic finds none.
      Combs              : Boolean := True;
      --  Combs from the blocks of the fractional support, when no blossom.
      Pricing            : Boolean := True;
      --  Start from the 8 cheapest edges of each node and the tour's, add
      --  edges of negative reduced cost; False: every edge from the start.
      Node_Fixing        : Boolean := True;
      --  Reduced-cost fixing at every node (the root's, global, always).
      Strong_Branching   : Natural := 8;
      --  Candidates tried by a few dual simplex steps per child; 0 = the
      --  most fractional edge.
      Best_Bound         : Boolean := True;
      --  The open node of least bound next; False: depth first.
      Purge              : Boolean := True;
      --  Cuts slack for 3 rounds leave the LP for a pool (checked first).
      Time_Limit         : Duration := 60.0;
      --  At the limit, the best tour so far and the lower bound reached.
      CPU_Time_Limit     : Boolean := False;
      --  Time_Limit counts the calling task's CPU time (benchmarks on a
      --  shared machine), not wall-clock time.
   end record;

   Default_Settings : constant Settings := (others => <>);

   type Result (Robots, Tasks : Positive) is record
      Best    : Assignment (Robots, Tasks);
      Upper   : Cost := 0;
      --  The cost (total of the tours) of Best.
      Lower   : Cost := 0;
      --  A proven lower bound on every allocation's total (0: none yet).
      Proven  : Boolean := False;
      --  Lower = Upper: Best is optimal.
      Nodes   : Natural := 0;
      --  Branch-and-bound nodes solved.
      Cuts    : Natural := 0;
      --  Cuts added (every class; a pooled cut added again counts again).
      By_Class : Cut_Counts := [others => 0];
      --  Cuts found by each separator.
      Purged  : Natural := 0;
      --  Cuts moved from the LP to the pool.
      Fixed   : Natural := 0;
      --  Edges fixed by reduced cost (at the root and below).
      Edges   : Natural := 0;
      --  Edges in the LP at the end (after reduced-cost fixing).
      Root_Bound : Long_Float := 0.0;
      --  The root LP's value after its cutting (0: not reached).
      Elapsed : Duration := 0.0;
      CPU     : Duration := 0.0;
      --  Wall-clock and CPU time of the calling task.
   end record;

   procedure Solve
     (P       : Problem;
      Start   : Assignment;
      Outcome : out Result;
      Config  : Settings := Default_Settings)
     with Pre => Supports (P) = "" and then Start.Robots = P.Robots
                 and then Start.Tasks = P.Tasks
                 and then Outcome.Robots = P.Robots and then Outcome.Tasks = P.Tasks;
   --  Start is a complete allocation (the first upper bound; a good one
   --  from the annealer makes reduced-cost fixing effective).

end Sancta.Allocation.Branch_And_Cut;
