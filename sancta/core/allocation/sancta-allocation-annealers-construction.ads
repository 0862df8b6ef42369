--  Building and rebuilding tours: best insertion of single tasks (the
--  annealer's start and the "recreate" half of ruin and recreate) and the
--  removal of a set of tasks.
--
--     Construct (P, S, Min_Max, G);          --  a fresh start in S
--     Remove_Tasks (P, S, [4, 9]);  Best_Insert (P, S, W, 9);  Best_Insert (P, S, W, 4);
with Sancta.Allocation.Annealers.Moves; use Sancta.Allocation.Annealers.Moves;
with Sancta.Allocation.Annealers.Tours; use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Construction is

   Candidate_Insertion_Above : constant := 500;
   --  Above this many tasks, Best_Insert tries a task that has some of its
   --  nearest tasks in a tour only next to them and at each robot's first
   --  and last free place (O (K) places instead of all: the start of a
   --  2392-task team took ~70% of its set-up with every place tried).

   procedure Best_Insert (P : Problem; S : in out State; W : Weights; T : Positive;
                          Only : Natural := 0);
   --  Inserts task T (in no tour) at its best place for W (on robot Only
   --  if not 0) among the places above. Program_Error when no robot can
   --  do T.

   procedure Remove_Tasks (P : Problem; S : in out State; List : Count_Array);
   --  Takes the tasks of List out of their tours (they must be movable;
   --  their owner and position become 0).

   procedure Construct (P : Problem; S : in out State; C : Criterion; G : in out Generator);
   --  The start: the cheapest selection of the plan tree, each robot's
   --  minimum count of tasks nearest its start, then the other active
   --  tasks in random order, each at its best insertion for C.

end Sancta.Allocation.Annealers.Construction;
