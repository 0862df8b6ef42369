--  Baseline allocators: greedy assigners and sequential single-item
--  auctions simulated centrally.
--
--  Best_Pair: repeatedly give the (robot, task) pair of least cost from the
--  robot's last task (appending), as the old greedy assigner did.
--  Min_Makespan: repeatedly insert, at its best position, the task whose
--  insertion leaves the smallest robot cost (ties: least added cost).
--  Auction: the Bidder's protocol: each round every robot bids, for every
--  unallocated task, the cost of inserting it at the best place of its own
--  plan (added cost for MinSum/MinAve, resulting tour cost for MinMax); the
--  lowest bid wins and is inserted there. Robots below the minimum task
--  count are served first. Tasks keep their first alternative location.
--  Plan trees: the alternative of every OR node is fixed first, cheapest
--  first (Problems.Cheapest_Selection: the least estimated start -> task ->
--  end trip cost, bottom-up), then only the active tasks are allocated.
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Baselines is

   type Method is (Best_Pair, Min_Makespan, Auction);

   function Solve (P : Problem; How : Method; C : Criterion := Min_Sum) return Assignment
     with Pre => Check (P) = "";

end Sancta.Allocation.Baselines;
