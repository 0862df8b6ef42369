with Sancta.Allocation.Random;
with Sancta.Allocation.Annealers.Construction;
with Sancta.Allocation.Annealers.Searches;
with Sancta.Allocation.Annealers.Tours;

package body Sancta.Allocation.Annealers is

   --  The annealer lives in private children: Tours (the solution and its
   --  cached costs), Moves (moves as segment lists, their evaluation and
   --  application, the expensive check), Neighbourhoods (the move
   --  generators), Plan_Trees (the switch subtree move), Construction (best
   --  insertion, the start), Searches (the annealing run).

   protected body Best_Box is
      procedure Post (A : Assignment; V : Long_Float) is
      begin
         Current := A;
         Current_Value := V;
         Posted := True;
      end Post;

      function Has_Value return Boolean is (Posted);
      function Value return Long_Float is (Current_Value);
      function Best return Assignment is (Current);
   end Best_Box;

   function Greedy_Start (P : Problem; C : Criterion; Seed : Interfaces.Unsigned_64)
     return Assignment
   is
      S : Tours.State_Access := Tours.New_State (P, Neighbours => 1);
      G : Tours.Generator := Random.Seeded (Seed);
   begin
      return A : Assignment (P.Robots, P.Tasks) do
         Construction.Construct (P, S.all, C, G);
         Tours.Store (S.all, A);
         Tours.Free (S);
      end return;
   end Greedy_Start;

   procedure Solve
     (P      : Problem;
      Opts   : Options;
      Best   : in out Assignment;
      Stats  : out Progress;
      Report : Reporter := null)
   is
      Run : Searches.Search (P.Robots, P.Tasks);
   begin
      Searches.Start (Run, P, Opts, Best, Report);
      Searches.Anneal (Run, P);
      Searches.Finish (Run, P, Best, Stats);
   end Solve;

end Sancta.Allocation.Annealers;
