--  RCL: the ROS 2 client library for Ada.
--
--  Nodes, publishers, subscriptions, services, clients, timers, executors,
--  graph queries, logging and parameters, speaking the ROS 2 conventions
--  directly on Eclipse Cyclone DDS (no ROS 2 installation needed). Package
--  names follow RCLAda so that RCLAda programs port with little change.
--
--  This root package holds the exceptions shared by the whole hierarchy.
package RCL is

   ROS_Exception : exception;
   --  Any failure reported by the middleware or the library itself; the
   --  message says what was attempted and why it failed.

   RCL_Timeout : exception;
   --  A blocking call (service call, wait for service...) ran out of time.

end RCL;
