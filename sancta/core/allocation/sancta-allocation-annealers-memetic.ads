--  A population search for a pure makespan (Options.Population): the
--  population's first members are independent anneals (own seeds, sharing
--  Population_Share of the budget); then, until the budget is spent, two
--  parents drawn by binary tournament are crossed on their giant tours
--  (order crossover: a random slice of the first parent's sequence kept in
--  place, the other tasks in the second parent's order from after the
--  slice), the child's sequence split optimally into tours
--  (Giant_Tours.Split), the child annealed from there (Solve, Initial, a
--  low start temperature, Child_Moves x tasks moves) and put in the
--  population in place of its worst member when better than that one
--  (makespan, then total) and not a copy of a member (same makespan and
--  total). The best member is returned: never worse than the best of the
--  first members.
--
--     if Memetic.Applies (P, Opts) then
--        Memetic.Search (P, Opts, Best, Stats);
--     end if;
private package Sancta.Allocation.Annealers.Memetic is

   function Applies (P : Problem; Opts : Options) return Boolean;
   --  Opts.Population >= 2, a pure makespan, 2+ robots, a start not given
   --  (not Opts.Initial), a budget of moves or time, and Giant_Tours.Applies
   --  (one location per task, all feasible, no plan tree, no frozen task, no
   --  robot costs of their own; distinct depots and multipliers are split
   --  with the robots in their order).

   procedure Search
     (P     : Problem;
      Opts  : Options;
      Best  : in out Assignment;
      Stats : out Progress)
     with Pre => Applies (P, Opts);
   --  The whole run within Opts' budget (Iterations: deterministic).

end Sancta.Allocation.Annealers.Memetic;
