--  An exact solver for small problems (up to Max_Tasks free tasks): a
--  Held-Karp dynamic programme per robot over subsets of tasks and OR
--  choices (shortest tour, or least completion-time sum), then a programme
--  over robots that splits the task set (O (R 3^n)). Supports the pure
--  criteria MinSum, MinMax and MinAve, heterogeneous robots, open and closed
--  tours, infeasible pairs, frozen prefixes and minimum task counts. Used to
--  validate the annealer and the baselines. Plan trees: every selection of
--  alternatives at the OR nodes is enumerated (up to Max_Selections) and
--  solved for its active tasks; the best one is returned.
--
--     A : constant Assignment := Exact.Solve (P.all, Min_Max);
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Exact is

   Max_Tasks : constant := 12;
   Max_Selections : constant := 4096;

   function Is_Pure (C : Criterion) return Boolean is
     ((if C.Max_Weight /= 0.0 then 1 else 0) + (if C.Sum_Weight /= 0.0 then 1 else 0)
      + (if C.Ave_Weight /= 0.0 then 1 else 0) = 1);

   function Solve (P : Problem; C : Criterion) return Assignment
     with Pre => Is_Pure (C) and then Check (P) = "";
   --  An optimal allocation. Constraint_Error when there are more than
   --  Max_Tasks free (non-frozen) active tasks in some selection, or more
   --  than Max_Selections selections.

end Sancta.Allocation.Exact;
