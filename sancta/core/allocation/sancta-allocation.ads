--  Multi-robot task allocation: the problem model, exact integer costs, the
--  optimisation criteria, and (in the children) instance readers, the
--  simulated annealer, greedy and auction baselines and an exact solver.
--
--     P : constant Problem_Access := TSPLIB.Read_MTSP ("eil51.tsp", Robots => 5);
--     A : Assignment := Annealers.Solve (P.all, (others => <>) ...);
--
--  Costs are integers (TSPLIB nint distances) or fixed-point scaled integers
--  (real Euclidean distances times a power of ten), so that incremental sums
--  in the annealer are exact and never drift from a full recomputation.
package Sancta.Allocation
  with Pure
is

   subtype Cost is Long_Long_Integer;
   --  An exact cost: distance units or fixed-point units (see Problems).

   Infinity : constant Cost := 2 ** 40;
   --  The cost of an infeasible robot/task pair. Aggregates add it once per
   --  infeasible task, so a cost >= Infinity means "infeasible" and sums of
   --  a few thousand of them still fit in a Cost.

   function Is_Infinite (C : Cost) return Boolean is (C >= Infinity);

   Format_Error : exception;
   --  An instance or mission file is wrong; the message starts with
   --  "file:line: ".

   type Criterion is record
      Max_Weight : Long_Float := 0.0;
      --  Weight of the makespan (the largest robot cost).
      Sum_Weight : Long_Float := 0.0;
      --  Weight of the total cost of all robots.
      Ave_Weight : Long_Float := 0.0;
      --  Weight of the mean task completion time.
   end record;
   --  A weighted mix of the three classic criteria.

   Min_Max : constant Criterion := (1.0, 0.0, 0.0);
   Min_Sum : constant Criterion := (0.0, 1.0, 0.0);
   Min_Ave : constant Criterion := (0.0, 0.0, 1.0);
   Min_Mix : constant Criterion := (1.0, 1.0, 0.0);
   Min_Tim : constant Criterion := (1.0, 0.000_01, 0.0);
   --  The old presets: minmax, minsum, minmix, mintim (plus minave).

   function Value
     (C : Criterion; Max, Sum, Completion_Sum : Cost; Tasks : Natural)
      return Long_Float
   is (C.Max_Weight * Long_Float (Max) + C.Sum_Weight * Long_Float (Sum)
       + (if Tasks = 0 or else C.Ave_Weight = 0.0 then 0.0
          else C.Ave_Weight * Long_Float (Completion_Sum) / Long_Float (Tasks)));
   --  The objective, always computed afresh from exact integer parts (no
   --  division for a criterion without the mean: its term is 0.0 anyway).

   function Preset (Name : String; Found : out Boolean) return Criterion;
   --  minmax, minsum, minave, minmix, mintim; Found False otherwise.

end Sancta.Allocation;
