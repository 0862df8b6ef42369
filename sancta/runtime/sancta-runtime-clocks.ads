--  Injectable time. The scheduler and the components read the time and
--  wait through a Clock, so tests replace the real monotonic clock by a
--  Manual_Clock whose waits return at once, having advanced the time: a test
--  then asserts on the logical sequence of activations, never on wall-clock
--  timing.
--
--     Real : aliased Real_Clock;           --  Ada.Real_Time, delay until
--     Fake : aliased Manual_Clock;         --  starts at Time_First + 1 h
--     Fake.Advance (Milliseconds (15));    --  a component "took" 15 ms
with Ada.Real_Time;

package Sancta.Runtime.Clocks is

   subtype Time is Ada.Real_Time.Time;

   type Clock is limited interface;
   type Clock_Access is access all Clock'Class;

   function Now (This : Clock) return Time is abstract;

   procedure Wait_Until (This : in out Clock; Deadline : Time) is abstract;
   --  Return when Now >= Deadline (at once if it already is).

   type Real_Clock is limited new Clock with null record;
   --  The monotonic clock of Ada.Real_Time; Wait_Until is "delay until".

   overriding function Now (This : Real_Clock) return Time;
   overriding procedure Wait_Until (This : in out Real_Clock; Deadline : Time);

   type Manual_Clock is limited new Clock with private;
   --  A logical clock: Now changes only by Advance, Set, or a Wait_Until
   --  that jumps to its deadline. Task-safe.

   overriding function Now (This : Manual_Clock) return Time;
   overriding procedure Wait_Until (This : in out Manual_Clock; Deadline : Time);
   --  Jumps the time to Deadline when it is later, and returns.

   procedure Advance (This : in out Manual_Clock; By : Ada.Real_Time.Time_Span);
   --  Moves the time forward (a component pretending to compute for By).

   function Epoch return Time;
   --  The initial time of every Manual_Clock (a fixed, arbitrary instant).

private

   protected type Manual_Time is
      function Get return Time;
      procedure Move_To (T : Time);
      --  Never backwards.
   private
      Current : Time := Ada.Real_Time."+" (Ada.Real_Time.Time_First, Ada.Real_Time.Seconds (3600));
   end Manual_Time;

   type Manual_Clock is limited new Clock with record
      Current : Manual_Time;
   end record;

end Sancta.Runtime.Clocks;
