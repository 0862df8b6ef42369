--  Timers: periodic callbacks run by the executor spinning their node,
--  on a fixed grid (Next := Next + Period: no drift; missed periods are
--  skipped, not run in a burst).
--
--  A timer runs on its node's clock, as rclcpp's create_timer: ROS time,
--  which under simulated time (use_sim_time) is the time received on
--  /clock, and otherwise the steady clock; or on the steady clock always
--  (Steady_Clock, rclcpp's create_wall_timer). Time jumps are handled as
--  rcl does: after a forward jump past the next call the timer fires once
--  and continues on its grid; after a backward jump behind its last call it
--  restarts one period from the new time; when the clock switches between
--  simulated and steady time the timer restarts one period from now.
--  Example:
--     T : Timers.Timer := Node.Timer_Add (0.5, Tick'Access);
--     T.Cancel;  T.Reset;  --  Reset restarts the grid from now
with Ada.Finalization;
limited with RCL.Nodes;

private with RCL.Timer_States;

package RCL.Timers is

   type Timer_Clock is (Node_Clock, Steady_Clock);

   type Timer is new Ada.Finalization.Controlled with private;
   --  A handle on a timer owned by its node (copies designate the same
   --  timer); valid while the node exists.

   type Callback is access procedure
     (Node    : in out RCL.Nodes.Node'Class;
      Timer   : in out Timers.Timer;
      Elapsed : Duration);
   --  Elapsed: time since the previous call (or since creation / Reset).

   procedure Cancel (This : in out Timer);
   --  No more calls until Reset.

   procedure Reset (This : in out Timer);
   --  Uncancels; the next call is one period from now.

   function Is_Canceled (This : Timer) return Boolean;

   function Period (This : Timer) return Duration;

   function Time_Until_Next (This : Timer) return Duration;
   --  Negative when overdue; Duration'Last when canceled.

   function Clock (This : Timer) return Timer_Clock;

private

   type Timer is new RCL.Timer_States.Handle with null record;
   --  Copies designate the same state (RCL.Timer_States).

end RCL.Timers;
