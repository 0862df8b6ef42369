--  The state of a timer, on the executors' side: its grid on its clock,
--  fired by the executor spinning its node (RCL.Timers has the rules). The
--  full view of RCL.Timers.Timer extends Handle. A private child of RCL:
--  RCL.Nodes makes the states, the executors fire them.
with Ada.Finalization;
with Ada.Real_Time;
with RCL.Clocks;
limited with RCL.Timers;

private package RCL.Timer_States is

   subtype Period_Nanoseconds is RCL.Clocks.Nanoseconds range 1 .. RCL.Clocks.Nanoseconds'Last;

   protected type State (Period_Ns : Period_Nanoseconds; Always_Steady : Boolean) is
      --  Always_Steady: on the steady clock even under simulated time
      --  (RCL.Timers.Steady_Clock), else on the node's clock.
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

   type Handle is abstract new Ada.Finalization.Controlled with record
      S : State_Access;
   end record;

   function To_Timer (S : not null State_Access) return RCL.Timers.Timer;
   --  A handle on S.

   function State_Of (This : RCL.Timers.Timer) return State_Access;

end RCL.Timer_States;
