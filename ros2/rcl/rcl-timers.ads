--  Timers: periodic callbacks run by the executor spinning their node,
--  on a fixed grid (Next := Next + Period: no drift; missed periods are
--  skipped, not run in a burst).
--
--     T : Timers.Timer := Node.Timer_Add (0.5, Tick'Access);
--     T.Cancel;  T.Reset;  --  Reset restarts the grid from now
with Ada.Real_Time;
limited with RCL.Nodes;

package RCL.Timers is

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

   --  Not for users: the executor's side.

   protected type State (Period_Ns : Positive) is
      procedure Start;
      procedure Cancel;
      procedure Reset;
      function Canceled return Boolean;
      function Due_At return Ada.Real_Time.Time;
      procedure Fire (Now : Ada.Real_Time.Time; Fired : out Boolean; Elapsed : out Duration);
      --  When due at Now: Fired, the grid advances past Now.
   private
      Next, Last : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
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
