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
with Ada.Real_Time;
with RCL.Clocks;
limited with RCL.Nodes;

package RCL.Timers is

   type Timer_Clock is (Node_Clock, Steady_Clock);

   type Timer is tagged private;
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

   --  Not for users: the executor's side.

   subtype Period_Nanoseconds is RCL.Clocks.Nanoseconds range 1 .. RCL.Clocks.Nanoseconds'Last;

   protected type State (Period_Ns : Period_Nanoseconds; On : Timer_Clock) is
      procedure Start;
      procedure Cancel;
      procedure Reset;
      function Canceled return Boolean;
      function Due_At return Ada.Real_Time.Time;
      --  On the steady clock; Time_Last when canceled or following
      --  simulated time (the executors are woken by each /clock message).
      function Until_Next return Duration;
      procedure Fire (Fired : out Boolean; Elapsed : out Duration);
      --  When due now: Fired, the grid advances past now.
      procedure Fire_At
        (Now : RCL.Clocks.Nanoseconds; Simulated : Boolean;
         Fired : out Boolean; Elapsed : out Duration);
      --  Fire with the clock read as Now (on simulated time or not).
      function Next_Call return RCL.Clocks.Nanoseconds;
   private
      Next, Last  : RCL.Clocks.Nanoseconds := 0;
      Simulated   : Boolean := False;
      --  The clock Next and Last are on.
      Is_Canceled : Boolean := False;
   end State;

   type State_Access is access all State;

   function To_Timer (S : not null State_Access) return Timer;

   function State_Of (This : Timer) return State_Access;

private

   type Timer is tagged record
      S : State_Access;
   end record;

end RCL.Timers;
