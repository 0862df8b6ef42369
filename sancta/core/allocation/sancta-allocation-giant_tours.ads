--  Giant tours of makespan allocations: all the tasks in one sequence (the
--  robots' tours one after the other) and the optimal split of such a
--  sequence back into one tour per robot, the representation of the
--  population search (Annealers.Options.Population): two plans are crossed
--  on their giant tours, and the child's giant tour is split.
--
--     Order : constant Count_Array := Giant_Tour (A);
--     Split (P, Order, B, Makespan, Total);
--     --  B's makespan <= A's makespan when the robots are alike
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Giant_Tours is

   function Applies (P : Problem) return Boolean;
   --  Every task has one location and no robot is forbidden it, no plan
   --  tree, no frozen task or prefix, no robot has costs of its own; the
   --  robots may differ in start, end (open tours too) and multiplier.

   function Giant_Tour (A : Assignment) return Count_Array
     with Post => Giant_Tour'Result'Length = Assigned (A);
   --  Robot 1's tour, then robot 2's, and so on.

   procedure Split
     (P        : Problem;
      Order    : Count_Array;
      Result   : out Assignment;
      Makespan : out Cost;
      Total    : out Cost)
     with Pre => Applies (P) and then Order'Length = P.Tasks
                 and then Result.Robots = P.Robots and then Result.Tasks = P.Tasks
                 and then P.Tasks >= P.Robots * P.Min_Tasks;
   --  Order (every task once) cut into P.Robots consecutive segments, the
   --  K-th one robot K's tour (at least P.Min_Tasks tasks each, possibly
   --  none), at the cut of the least makespan and, among those, the least
   --  total cost: optimal among the plans that keep the sequence and give
   --  its segments to the robots in their order, hence among all the plans
   --  that keep it when the robots are alike (same start, end, multiplier).
   --  Dynamic programme over robots x positions: O(Robots x Tasks ** 2)
   --  distance look-ups (10 robots, 200 tasks: 0.4 M).

end Sancta.Allocation.Giant_Tours;
