--  Building and rebuilding tours: best insertion of single tasks (the
--  annealer's start and the "recreate" half of ruin and recreate) and the
--  removal of a set of tasks.
--
--     Construct (P, S, Min_Max, G);          --  a fresh start in S
--     Remove_Tasks (P, S, [4, 9]);  Best_Insert (P, S, W, 9);  Best_Insert (P, S, W, 4);
with Sancta.Allocation.Annealers.Moves; use Sancta.Allocation.Annealers.Moves;
with Sancta.Allocation.Annealers.Tours; use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Construction is

   procedure Best_Insert (P : Problem; S : in out State; W : Weights; T : Positive;
                          Only : Natural := 0);
   --  Inserts task T (in no tour) at its best place for W (on robot Only
   --  if not 0). Program_Error when no robot can do T.

   procedure Remove_Tasks (P : Problem; S : in out State; List : Count_Array);
   --  Takes the tasks of List out of their tours (they must be movable).

   procedure Construct (P : Problem; S : in out State; C : Criterion; G : in out Generator);
   --  The start: the cheapest selection of the plan tree, each robot's
   --  minimum count of tasks nearest its start, then the other active
   --  tasks in random order, each at its best insertion for C.

end Sancta.Allocation.Annealers.Construction;
