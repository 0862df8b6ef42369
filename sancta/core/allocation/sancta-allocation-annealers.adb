with Sancta.Allocation.Random;
with Sancta.Allocation.Annealers.Construction;
with Sancta.Allocation.Annealers.Searches;
with Sancta.Allocation.Annealers.Tours;
with Sancta.Allocation.Local_Search;

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

   --  The local search after the anneal, in the rest of the budget.
   procedure Improve_Tour
     (P : Problem; Opts : Options; Best : in out Assignment; Stats : in out Progress)
   is
      Search : Local_Search.Statistics;
      Before : constant Duration := Stats.Elapsed;
   begin
      Local_Search.Improve (P, Best, Duration'Max (0.0, Opts.Time_Limit - Before), Opts.Seed,
                            Search, Neighbours => Opts.Neighbours, Check => Opts.Check);
      Stats.Elapsed := Before + Search.Elapsed;
      if Search.After < Search.Before then
         Stats.Best := Evaluate (P, Best, Opts.Criterion).Value;
         Stats.Current := Stats.Best;
         Stats.Time_To_Best := Before + Search.Time_To_Best;
      end if;
      if Opts.Box /= null then
         Opts.Box.Post (Best, Stats.Best);
      end if;
   end Improve_Tour;

   procedure Solve
     (P      : Problem;
      Opts   : Options;
      Best   : in out Assignment;
      Stats  : out Progress;
      Report : Reporter := null)
   is
      Share : constant Long_Float :=
        (if Opts.Local_Search > 0.0 and then Opts.Time_Limit > 0.0
           and then Local_Search.Applies (P)
         then Long_Float'Min (0.95, Opts.Local_Search) else 0.0);
      Anneal_Opts : Options := Opts;
      Run : Searches.Search (P.Robots, P.Tasks);
   begin
      Anneal_Opts.Time_Limit := Duration (Long_Float (Opts.Time_Limit) * (1.0 - Share));
      Searches.Start (Run, P, Anneal_Opts, Best, Report);
      Searches.Anneal (Run, P);
      Searches.Finish (Run, P, Best, Stats);
      if Share > 0.0 then
         Improve_Tour (P, Opts, Best, Stats);
      end if;
   end Solve;

end Sancta.Allocation.Annealers;
