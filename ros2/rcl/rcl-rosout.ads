--  Private child of RCL: republishes log records on /rosout
--  (rcl_interfaces/msg/Log, rosout QoS: reliable, transient local, keep
--  last 1000, lifespan 10 s), as rcl does. Enabled by the first node.
private package RCL.Rosout is

   procedure Enable;
   --  Idempotent; errors are logged to the console only.

end RCL.Rosout;
