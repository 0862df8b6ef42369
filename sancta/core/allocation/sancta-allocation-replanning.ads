--  Anytime re-planning after the loss of a robot. The survivors keep the
--  tasks they have done or are doing (frozen prefixes); the tasks the lost
--  robot had not finished go to their cheapest places in the survivors'
--  current tours (the current plan is the start, not a fresh one); the
--  annealer then improves that plan within the budget, and the quality is
--  recorded over time (the start's value at 0 s, then every report).
--
--     Kept : constant Count_Array := Remaining_Tasks (P.all, A, Lost => 2, Done => D);
--     Q : constant Problem_Access := Without_Robot (P.all, A, 2, D, Kept);
--     S : Assignment := Carried_Over (P.all, Q.all, A, 2, D, Kept, Min_Max);
--     Improve (Q.all, S, Opts, T);   --  T.Samples (1 .. T.Last): (seconds, value)
--
--  Known limit: problems with a plan tree are not handled (the tree would
--  have to be renumbered with the tasks).
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Assignments; use Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;    use Sancta.Allocation.Problems;

package Sancta.Allocation.Replanning is

   function Done_Fits (P : Problem; Current : Assignment; Done : Count_Array) return Boolean
   is (Done'First = 1 and then Done'Last = P.Robots
       and then (for all R in 1 .. P.Robots =>
                   Done (R) in P.Frozen_Length (R) .. Current.Length (R)));
   --  Done (R): how many tasks at the head of robot R's tour are done or
   --  under way (at least its frozen prefix).

   function Remaining_Tasks
     (P : Problem; Current : Assignment; Lost : Positive; Done : Count_Array)
      return Count_Array
     with Pre => Lost <= P.Robots and then Done_Fits (P, Current, Done);
   --  The tasks still in the problem (all but those the lost robot has
   --  done), increasing: the new problem's task I is the old task Kept (I).

   function Without_Robot
     (P : Problem; Current : Assignment; Lost : Positive; Done : Count_Array;
      Kept : Count_Array) return Problem_Access
     with Pre => P.Robots >= 2 and then Lost <= P.Robots and then not Has_Plan (P)
                 and then Kept'Length >= 1 and then Done_Fits (P, Current, Done);
   --  P for the other robots (robot R > Lost becomes R - 1) and the tasks
   --  Kept, every survivor's first Done tasks frozen.

   function Carried_Over
     (P, Q : Problem; Current : Assignment; Lost : Positive; Done : Count_Array;
      Kept : Count_Array; C : Criterion) return Assignment
     with Pre => Q.Robots = P.Robots - 1 and then Q.Tasks = Kept'Length;
   --  The current plan in Q: the survivors' tours as they are, then each
   --  task the lost robot had not finished inserted where it adds least
   --  (for a makespan criterion: where the robot's cost after is least).

   type Sample is record
      Elapsed : Duration := 0.0;
      Value   : Long_Float := 0.0;
   end record;
   type Sample_Array is array (Positive range <>) of Sample;

   type Quality_Trace (Capacity : Positive) is record
      Samples : Sample_Array (1 .. Capacity);
      Last    : Natural := 0;
   end record;
   --  The best value of the criterion over time: Samples (1 .. Last).

   procedure Improve
     (Q     : aliased Problem;
      Plan  : in out Assignment;
      Opts  : Annealers.Options;
      Trace : out Quality_Trace)
     with Pre => Plan.Robots = Q.Robots and then Plan.Tasks = Q.Tasks
                 and then Opts.Time_Limit >= 0.05 and then Trace.Capacity >= 2;
   --  Plan improved by the annealer started from it (budget
   --  Opts.Time_Limit, at least 50 ms; reports every tenth of it), its
   --  value at 0 s, the value of the annealer's best plan at every report
   --  and the final value in Trace (samples beyond its capacity are
   --  dropped but for the last). The annealer ranks plans
   --  by its search objective, which for a makespan adds a small share of
   --  the total cost: the makespan may rise a little between samples.
   --  Re-plans run one at a time (the reports go through one recorder;
   --  Opts.Box and Opts.Report are replaced by the recorder's).

end Sancta.Allocation.Replanning;
