--  Ejection chains for makespan criteria: a compound move that lowers the
--  longest tour when no single move can. The longest tour (the donor) gives
--  a segment (Or-opt of 1 to 3 tasks, or a tail by 2-opt*) to a tour that
--  holds one of the segment's candidate neighbours, so that the donor falls
--  below the makespan; if the receiving tour is now above it, it becomes the
--  donor of the next step, towards a tour not yet in the chain, until a
--  tour with slack absorbs the segment (depth-first, the few most promising
--  steps at the first levels, at most Max_Depth steps). When several tours
--  share the makespan, one chain per tour (at most Max_Rounds). Every step is an ordinary move
--  (segment lists, evaluated from the prefix sums, applied with Apply);
--  the whole chain is kept only if it lowers the search objective, and
--  otherwise undone step by step.
--
--     Space : Workspace_Access := New_Workspace (P);
--     Ejection_Chain (P, S, W, Space.all, Check => False, Improved => Improved,
--                     Evaluations => Count);
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Annealers.Moves; use Sancta.Allocation.Annealers.Moves;
with Sancta.Allocation.Annealers.Tours; use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Chains is

   Max_Depth : constant := 8;
   --  Steps (moves) in one chain; also bounded by the number of robots - 1.

   Max_Rounds : constant := 4;
   --  Chains in one call (one per tour at the makespan; with more tours
   --  there, the call gives up).

   type Workspace (Robots, Positions, Rows : Positive) is record
      --  Rows = 2 x Max_Depth x Max_Rounds.
      Visited     : Boolean_Array (1 .. Robots) := [others => False];
      --  The tours in the current chain (a step never goes back to one).
      Saved_Robot : Count_Array (1 .. Rows) := [others => 0];
      Saved_Length : Count_Array (1 .. Rows) := [others => 0];
      Saved_Tasks : Position_Grid (1 .. Rows, 0 .. Positions) := [others => [others => 0]];
      --  For each applied step, its two tours before it.
      Applied     : Natural := 0;
      --  Steps applied (in all chains of this call).
   end record;
   --  The undo record of the steps applied so far (the two touched tours
   --  of each step as they were before it).

   type Workspace_Access is access Workspace;

   function New_Workspace (P : Problem) return Workspace_Access;

   procedure Free is new Ada.Unchecked_Deallocation (Workspace, Workspace_Access);

   procedure Ejection_Chain
     (P           : Problem;
      S           : in out State;
      W           : Weights;
      Space       : in out Workspace;
      Check       : Boolean;
      Improved    : out Boolean;
      Evaluations : in out Long_Long_Integer)
     with Pre => Space.Robots = S.Robots and then Space.Positions = S.Positions;
   --  One ejection chain from the longest tour of S for the objective W (a
   --  makespan criterion): applied if it lowers Current_Value (P, S, W)
   --  (Improved True), else S is left as it was. Evaluations counts the
   --  moves evaluated. Check: the expensive check (Moves.Verify) after
   --  every applied and every undone step. Nothing is done (Improved
   --  False) without a makespan weight or with one robot.

end Sancta.Allocation.Annealers.Chains;
