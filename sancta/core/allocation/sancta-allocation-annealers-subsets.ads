--  Route-subset re-optimisation for a pure makespan (a large neighbourhood
--  step after the anneal): the longest tour and Opts.Subset_Robots - 1
--  tours near it (robots owning many of its tasks' nearest neighbours) are
--  pooled into a problem of their own (those robots, those tasks), which
--  Solve anneals with its own seed for Opts.Subset_Moves x its tasks moves;
--  the new tours replace the old ones when the makespan of those robots
--  falls, or stays and their total falls. Repeated until the budget given
--  is spent.
--
--     if Subsets.Applies (P, Opts) then
--        Subsets.Reoptimise (P, Opts, Moves, Time, Best, Stats);
--     end if;
private package Sancta.Allocation.Annealers.Subsets is

   function Applies (P : Problem; Opts : Options) return Boolean;
   --  Pure makespan, Opts.Subset_Share > 0, at least 3 robots, no plan tree,
   --  one location per task, no frozen task, no robot costs of its own.

   procedure Reoptimise
     (P     : Problem;
      Opts  : Options;
      Moves : Long_Long_Integer;
      Time  : Duration;
      Best  : in out Assignment;
      Stats : in out Progress)
     with Pre => Applies (P, Opts) and then (Moves > 0 or else Time > 0.0);
   --  Re-optimisation steps on Best until Moves sub-anneal moves (0: no
   --  limit) or Time on Opts.Budget_Clock (0.0: none) are spent. Stats.Best,
   --  Moves, Elapsed and Time_To_Best follow; Opts.Box gets each better plan.

end Sancta.Allocation.Annealers.Subsets;
