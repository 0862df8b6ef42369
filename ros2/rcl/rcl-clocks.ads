--  Clocks: steady (monotonic), system (wall) and ROS time. ROS time is the
--  system time, or, with simulated time (use_sim_time), the last time
--  received on /clock (rosgraph_msgs/msg/Clock, clock QoS), 0 before the
--  first message.
--  Example:
--     T : constant RCL.Clocks.Nanoseconds := RCL.Clocks.Now (RCL.Clocks.ROS);
--     RCL.Clocks.Enable_Sim_Time (Node);  --  or --ros-args -p use_sim_time:=true
limited with RCL.Nodes;

package RCL.Clocks is

   type Clock_Kind is (Steady, System, ROS);

   type Nanoseconds is range -(2 ** 63) .. 2 ** 63 - 1;

   function Now (Kind : Clock_Kind := ROS) return Nanoseconds;
   --  Steady: since an arbitrary origin; System and ROS: since the Unix
   --  epoch.

   function To_Duration (Span : Nanoseconds) return Duration;

   procedure Enable_Sim_Time (Node : in out RCL.Nodes.Node'Class);
   --  ROS time follows /clock from now on, received by Node (spin it).

   procedure Follow_Clock (Node : in out RCL.Nodes.Node'Class);
   --  As Enable_Sim_Time, and Node subscribes to /clock even when another
   --  node already does: ROS time follows /clock while Node lives and is
   --  spun, whatever becomes of the first node that enabled simulated time.

   function Sim_Time_Enabled return Boolean;

   function Sim_Time_Requested return Boolean;
   --  The command line has "--ros-args ... -p use_sim_time:=true" (the
   --  first node then calls Enable_Sim_Time on itself).

end RCL.Clocks;
