--  A scheduler clock on ROS time. With simulated time (use_sim_time) ROS
--  time is the time of the last /clock message, so the agents' scheduler and
--  components run at the rate of the simulator publishing /clock (faster or
--  slower than real time) instead of on the wall clock.
--
--     Sim : aliased ROS_Clock;
--     Sim.Follow_Clock_Topic;                   --  node "sancta_clock"
--     N.Create (Config, Index, Sim'Unchecked_Access);
--     ...
--     Sim.Stop;                                 --  before the program ends
with Ada.Strings.Unbounded;
with Sancta.Runtime.Clocks;

package Sancta.Standard_Components.ROS_Clocks is

   type ROS_Clock is limited new Runtime.Clocks.Clock with private;

   overriding function Now (This : ROS_Clock) return Runtime.Clocks.Time;
   --  Runtime.Clocks.Epoch + the ROS time (RCL.Clocks.Now (ROS)): with simulated
   --  time, 0 (Epoch) before the first /clock message.

   overriding procedure Wait_Until (This : in out ROS_Clock; Deadline : Runtime.Clocks.Time);
   --  Polls the ROS time (every millisecond of wall time) and returns when
   --  Now >= Deadline, or after at most Max_Wait of wall time even if it is
   --  not (when /clock stops): a scheduler then finds nothing due, notices a
   --  stop request if any, and waits again.

   Max_Wait : constant Duration := 0.1;

   procedure Follow_Clock_Topic (This : in out ROS_Clock; Node_Name : String := "sancta_clock");
   --  Enables simulated time (RCL.Clocks.Follow_Clock) on a node of its
   --  own receiving /clock, spun by a task of its own until Stop. Returns
   --  once the subscription exists.

   procedure Stop (This : in out ROS_Clock);
   --  Ends the task of Follow_Clock_Topic (ROS time keeps its last value).
   --  Required before the program ends if Follow_Clock_Topic was called.

private

   task type Spinner (Owner : not null access ROS_Clock) is
      entry Ready;
   end Spinner;

   type Spinner_Access is access Spinner;

   type ROS_Clock is limited new Runtime.Clocks.Clock with record
      Name     : Ada.Strings.Unbounded.Unbounded_String;
      Stopping : Boolean := False with Atomic;
      Worker   : Spinner_Access;
   end record;

end Sancta.Standard_Components.ROS_Clocks;
