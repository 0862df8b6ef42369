--  The clocks a search budget can be measured on: wall-clock time, or the
--  CPU time of the task running the search (Ada.Execution_Time), which buys
--  the same work on a busy machine as on an idle one.
--
--     Started : constant Time := Clock (CPU_Time);
--     ...  --  search
--     Used : constant Duration := To_Duration (Clock (CPU_Time) - Started);
--
--  Both clocks are read as Ada.Real_Time.Time values; only differences of
--  readings of the same kind, in the same task, mean anything.
with Ada.Real_Time;

package Sancta.Allocation.Budget_Clocks is

   type Clock_Kind is (Wall_Time, CPU_Time);

   function Clock (Kind : Clock_Kind) return Ada.Real_Time.Time;
   --  Wall_Time: Ada.Real_Time.Clock. CPU_Time: the calling task's CPU time
   --  since it started, as a time after Ada.Real_Time's epoch.

   function Image (Kind : Clock_Kind) return String
   is (case Kind is when Wall_Time => "wall", when CPU_Time => "cpu");
   --  Example: Image (CPU_Time) = "cpu".

end Sancta.Allocation.Budget_Clocks;
