with Ada.Real_Time;
with Sancta.Allocation.Random;
with Sancta.Allocation.Annealers.Construction;
with Sancta.Allocation.Annealers.Memetic;
with Sancta.Allocation.Annealers.Searches;
with Sancta.Allocation.Annealers.Subsets;
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

   --  The route search's options from the annealer's, for Time_Limit.
   function Route_Search_Options (Opts : Options; Time_Limit : Duration)
     return Local_Search.Search_Options is
     ((Time_Limit => Time_Limit, Budget_Clock => Opts.Budget_Clock, Seed => Opts.Seed,
       Neighbours => Opts.Neighbours, Check => Opts.Check, others => <>));

   --  The local search after the anneal, in the rest of the budget.
   procedure Improve_Tour
     (P : Problem; Opts : Options; Best : in out Assignment; Stats : in out Progress)
   is
      Search : Local_Search.Statistics;
      Before : constant Duration := Stats.Elapsed;
      Tour_Target : constant Cost :=
        (if Opts.Target > 0.0 then Cost (Long_Float'Floor (Long_Float'Min (Opts.Target, 1.0E15)))
         else 0);
   begin
      Local_Search.Improve
        (P, Best,
         (Route_Search_Options (Opts, Duration'Max (0.0, Opts.Time_Limit - Before))
          with delta Target => Tour_Target),
         Search);
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

   --  Every route shortened by the route search (Local_Search.Polish_Routes)
   --  in Budget (0.0: one descent each): for criteria without the mean
   --  completion time, which route order alone does not decide.
   procedure Polish_Routes
     (P : Problem; Opts : Options; Budget : Duration; Kicks : Boolean;
      Best : in out Assignment; Stats : in out Progress)
   is
      Search : Local_Search.Statistics;
      Before : constant Duration := Stats.Elapsed;
   begin
      Local_Search.Polish_Routes
        (P, Best, (Route_Search_Options (Opts, Budget) with delta Kicks => Kicks), Search);
      Stats.Elapsed := Before + Search.Elapsed;
      if Search.After < Search.Before then
         declare
            Old : constant Long_Float := Stats.Best;
         begin
            Stats.Best := Evaluate (P, Best, Opts.Criterion).Value;
            Stats.Current := Stats.Best;
            Stats.Polish_Gain := Stats.Polish_Gain + (Old - Stats.Best);
            Stats.Time_To_Best := Before + Search.Time_To_Best;
         end;
         if Opts.Box /= null then
            Opts.Box.Post (Best, Stats.Best);
         end if;
      end if;
   end Polish_Routes;

   Team_Polish_Share : constant := 0.05;
   --  The share of a time budget kept for the routes' descents (teams).

   procedure Solve
     (P      : Problem;
      Opts   : Options;
      Best   : in out Assignment;
      Stats  : out Progress)
   is
      Single_Tour : constant Boolean := Local_Search.Applies (P);
      Route_Polish : constant Boolean := Opts.Polish and then Opts.Criterion.Ave_Weight = 0.0;
      One_Route : constant Boolean :=
        Route_Polish and then P.Robots = 1 and then not Has_Plan (P)
        and then (for all T in 1 .. P.Tasks => P.Alt_Count (T) = 1)
        and then (P.Symmetric or else Has_Own_Costs (P, 1));
      --  One robot, nothing to choose but the order (open, frozen, other
      --  depot): the route search is the whole problem. With several
      --  robots, the anneal keeps the budget and the routes get one descent.
      --  Shared asymmetric costs (ATSP): the route search does not apply
      --  (Local_Search.Polish_Routes), so the anneal keeps the budget; a
      --  robot's own costs are checked on its route (symmetric or not).
      Share : constant Long_Float :=
        (if Opts.Local_Search > 0.0 and then Opts.Time_Limit > 0.0
           and then (Single_Tour or else One_Route)
         then Long_Float'Min (0.95, Opts.Local_Search) else 0.0);
      Subset_Share : constant Long_Float :=
        (if Subsets.Applies (P, Opts) and then (Opts.Time_Limit > 0.0 or else Opts.Iterations > 0)
         then Long_Float'Min (0.9, Opts.Subset_Share) else 0.0);
      --  The share of the budget for route-subset re-optimisation.
      Anneal_Opts : Options := Opts;
      Run : Searches.Search (P.Robots, P.Tasks);
   begin
      if Memetic.Applies (P, Opts) then
         Memetic.Search (P, Opts, Best, Stats);
         return;
      end if;
      if Share > 0.0 and then Single_Tour and then P.Tasks > Local_Search.Direct_Size then
         --  A large single tour: the search alone, from a nearest-neighbour tour.
         declare
            Started : constant Ada.Real_Time.Time := Budget_Clocks.Clock (Opts.Budget_Clock);
            use type Ada.Real_Time.Time;
         begin
            Best := Local_Search.Nearest_Neighbour_Tour (P);
            Stats := (others => <>);
            Stats.Best := Evaluate (P, Best, Opts.Criterion).Value;
            Stats.Current := Stats.Best;
            Stats.Elapsed := Ada.Real_Time.To_Duration
              (Budget_Clocks.Clock (Opts.Budget_Clock) - Started);
            Improve_Tour (P, Opts, Best, Stats);
            return;
         end;
      end if;
      Anneal_Opts.Time_Limit := Duration (Long_Float (Opts.Time_Limit)
                                          * (1.0 - (if Share > 0.0 then Share
                                                    elsif Route_Polish then Team_Polish_Share
                                                    else 0.0)
                                                - Subset_Share));
      if Opts.Iterations > 0 then
         Anneal_Opts.Iterations := Long_Long_Integer'Max
           (1, Long_Long_Integer (Long_Float (Opts.Iterations) * (1.0 - Subset_Share)));
      end if;
      Searches.Start (Run, P, Anneal_Opts, Best);
      Searches.Anneal (Run, P);
      Searches.Finish (Run, P, Best, Stats);
      if Opts.Target > 0.0 and then Stats.Best <= Opts.Target then
         return;
         --  Reached: no search after the anneal (Time_To_Best stays the
         --  time the target was reached).
      end if;
      if Share > 0.0 and then Single_Tour then
         Improve_Tour (P, Opts, Best, Stats);
      elsif Share > 0.0 then
         Polish_Routes (P, Opts, Duration'Max (0.001, Opts.Time_Limit - Stats.Elapsed), True,
                        Best, Stats);
      elsif Route_Polish then
         --  Descents only: in what is left of the budget (at least 1 ms),
         --  or unbounded under a move budget alone (deterministic).
         Polish_Routes
           (P, Opts,
            (if Opts.Time_Limit > 0.0
             then Duration'Max (0.001, Opts.Time_Limit - Stats.Elapsed) else 0.0),
            False, Best, Stats);
      end if;
      if Subset_Share > 0.0 then
         --  After the routes' descents: what is left of the budget.
         Subsets.Reoptimise
           (P, Opts,
            Moves => (if Opts.Iterations > 0
                      then Long_Long_Integer'Max (1, Opts.Iterations - Anneal_Opts.Iterations)
                      else 0),
            Time => (if Opts.Time_Limit > 0.0
                     then Duration'Max (0.001, Opts.Time_Limit - Stats.Elapsed)
                     else 0.0),
            Best => Best, Stats => Stats);
      end if;
   end Solve;

end Sancta.Allocation.Annealers;
