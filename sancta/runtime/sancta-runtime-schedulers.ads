--  The periodic scheduler of a node: ONE task runs every periodic
--  component's Run in time order from a priority queue (ordered by due
--  time, ties in insertion order). Periods are drift-free because a
--  component computes its next due time from the previous due time, not
--  from the clock. Detected and logged (section "scheduler"):
--  * overrun: a Run returned a next time that is already past;
--  * "cannot keep up": a call started more than Keep_Up_Limit late
--    (logged at most once per 5 s of clock time);
--  * exceptions: logged with the component's name, then the component is
--    retried after its retry_after or dropped (on_error="stop"); a
--    component whose Start failed gets its Start retried before its Run.
--  Per-component statistics: calls, failures, overruns, run time, lateness.
--
--  Time comes from an injectable Clock: with a Manual_Clock a test calls
--  Run_Due / Step itself and checks the logical sequence of calls.
--
--     S.Initialize (Clock'Unchecked_Access, "Ari");
--     S.Add (Component, S.Now);
--     S.Start;    --  the task; S.Stop ends it (waits for the current call)
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;

private with Ada.Containers.Ordered_Sets;
private with Ada.Containers.Vectors;

package Sancta.Runtime.Schedulers is

   use Ada.Real_Time;

   type Statistics is record
      Calls          : Natural := 0;
      Failures       : Natural := 0;
      Overruns       : Natural := 0;
      Late_Calls     : Natural := 0;
      --  Calls started more than Keep_Up_Limit late.
      Total_Run      : Time_Span := Time_Span_Zero;
      Max_Run        : Time_Span := Time_Span_Zero;
      Total_Lateness : Time_Span := Time_Span_Zero;
      Max_Lateness   : Time_Span := Time_Span_Zero;
   end record;

   type Scheduler is tagged limited private;

   procedure Initialize
     (This          : in out Scheduler;
      Clock         : not null Clocks.Clock_Access;
      Name          : String;
      Keep_Up_Limit : Time_Span := Milliseconds (100));

   function Now (This : Scheduler) return Clocks.Time;

   procedure Add
     (This : in out Scheduler; Item : not null Components.Component_Access; Due : Clocks.Time);
   --  Queue Item's first Run at Due. Task-safe.

   function Next_Due (This : Scheduler) return Clocks.Time;
   --  The earliest due time queued (Components.Never when empty).

   function Queued (This : Scheduler) return Natural;

   procedure Run_Due (This : in out Scheduler);
   --  Run, in order, every queued call due at or before the clock's time at
   --  entry (re-queued calls included when still due by then: missed
   --  activations are caught up, periods keep their phase). Calls due after
   --  the entry time wait for the next Run_Due, so a component that always
   --  overruns cannot keep the scheduler in one round forever.

   procedure Step (This : in out Scheduler);
   --  Wait (on the clock) until the next due time, then Run_Due.

   procedure Start (This : in out Scheduler);
   --  Start the scheduler task (Step in a loop).

   procedure Stop (This : in out Scheduler);
   --  Ask the task to end and wait for it (at most one call plus 100 ms).
   --  Safe to call twice or without Start.

   function Stats (This : Scheduler; Item : not null Components.Component_Access)
     return Statistics;

   function Report (This : Scheduler) return String;
   --  One line per component: calls, failures, overruns, mean/max run time
   --  and lateness in microseconds.

private

   type Queue_Entry is record
      Due   : Clocks.Time;
      Seq   : Long_Long_Integer;
      Index : Positive;
   end record;

   function "<" (A, B : Queue_Entry) return Boolean is
     (A.Due < B.Due or else (A.Due = B.Due and then A.Seq < B.Seq));

   package Entry_Sets is new Ada.Containers.Ordered_Sets (Queue_Entry);

   type Member is record
      Item  : Components.Component_Access;
      Stats : Statistics;
   end record;

   package Member_Vectors is new Ada.Containers.Vectors (Positive, Member);

   protected type Queue is
      procedure Add (Item : Components.Component_Access; Due : Clocks.Time);
      procedure Put_Back (Index : Positive; Due : Clocks.Time);
      procedure Pop_Due (Now : Clocks.Time; Found : out Boolean; Next : out Queue_Entry);
      function Next_Due return Clocks.Time;
      function Length return Natural;
      function Get (Index : Positive) return Member;
      procedure Set_Stats (Index : Positive; Stats : Statistics);
      function Find (Item : Components.Component_Access) return Natural;
      function Members_Count return Natural;
      procedure Request_Stop;
      function Stop_Requested return Boolean;
   private
      Entries : Entry_Sets.Set;
      Members : Member_Vectors.Vector;
      Seq     : Long_Long_Integer := 0;
      Stopping : Boolean := False;
   end Queue;

   task type Runner (Owner : not null access Scheduler);

   type Runner_Access is access Runner;

   type Scheduler is tagged limited record
      Clock         : Clocks.Clock_Access;
      Name          : Ada.Strings.Unbounded.Unbounded_String;
      Keep_Up_Limit : Time_Span := Milliseconds (100);
      Last_Warning  : Clocks.Time := Time_First;
      Warned_Once   : Boolean := False;
      Calls         : Queue;
      Worker        : Runner_Access;
   end record;

end Sancta.Runtime.Schedulers;
