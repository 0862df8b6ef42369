--  What both Fibonacci action servers (fibonacci_server, typed_fibonacci)
--  do with the goals they accept: keep each goal's Work and, on every tick
--  of a timer, advance every goal one step, forgetting the goals that are
--  done. Several goals run at once.
--
--     package Running is new Stepped_Goals (Work, Advance);
--     Running.Add (W);                               --  in On_Accepted
--     Node.Timer_Add (Period, Running.Step'Access);
with RCL.Nodes;
with RCL.Timers;

generic
   type Work is private;
   with procedure Advance
     (Node : in out RCL.Nodes.Node'Class; W : in out Work; Done : out Boolean);
   --  One step of W's goal (feedback, say), or its end (Done).
package Stepped_Goals is

   procedure Add (W : Work);
   --  W's goal advances from the next tick on.

   procedure Step
     (Node    : in out RCL.Nodes.Node'Class;
      Timer   : in out RCL.Timers.Timer;
      Elapsed : Duration);
   --  The timer's callback: Advance on every goal in the order they were
   --  added; the goals found Done are forgotten.

end Stepped_Goals;
