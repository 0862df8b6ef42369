--  Iterated local search on one closed symmetric tour (the TSP): 2-opt and
--  Or-opt moves (segments of 1 .. 3 tasks, both orientations) over
--  candidate lists (the K nearest tasks) with don't-look bits, and
--  Or-opt style kicks (a double bridge inside a window of nearby
--  positions) accepted when the tour does not get longer. Memory and work
--  per move are O(n K) and O(K) (a 2-opt reversal is O(n) at worst, the
--  shorter side); distances come from the problem's matrix.
--
--     if Applies (P.all) then
--        Improve (P.all, A, Time_Limit => 5.0, Seed => 1);   --  A: one robot's tour
--     end if;
with Interfaces;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
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

   procedure Improve
     (P          : Problem;
      A          : in out Assignment;
      Time_Limit : Duration;
      Seed       : Interfaces.Unsigned_64;
      Stats      : out Statistics;
      Neighbours : Positive := 8;
      Check      : Boolean := False)
     with Pre => Applies (P) and then A.Robots = 1 and then A.Tasks = P.Tasks
                 and then A.Length (1) = P.Tasks;
   --  A's tour improved for Time_Limit (0.0: one descent, no kicks).
   --  Check: after every move the tour length is recomputed and compared
   --  with the incremental one (Program_Error on a difference).

end Sancta.Allocation.Local_Search;
