--  The state behind RCL.Contexts that the library's own units share: the
--  process's DDS participant (every node, publisher, service, client and
--  graph query creates its entities in it), and the waitsets of the
--  spinning executors, woken by Shutdown and when simulated time advances.
--  A private child of RCL: the library's units use it, programs cannot.
with RCL.DDS;

private package RCL.Process_Context is

   function Participant return not null access RCL.DDS.Participant;
   --  Created first if need be, on RCL.Contexts.Domain and
   --  RCL.Contexts.Localhost_Only.

   procedure Ensure_Participant
     (Domain         : RCL.DDS.Domain_Id;
      Localhost_Only : Boolean;
      Lease          : Duration := RCL.DDS.Configured_Lease);
   --  Creates the participant if not done yet: secured as the environment
   --  says (RCL.Security), USER_DATA "enclave=<enclave>;", with Lease
   --  (RCL.DDS.Create) (RCL.Contexts.Init).

   function Is_Initialized return Boolean;
   function Domain return RCL.DDS.Domain_Id
     with Pre => Is_Initialized;
   function Localhost_Only return Boolean
     with Pre => Is_Initialized;

   type Waitset_Access is access all RCL.DDS.Waitset;

   procedure Register_Waker (Set : not null Waitset_Access; Key : out Positive);
   procedure Unregister_Waker (Key : Positive);
   --  Executors register their waitset to be woken by Shutdown.

   procedure Wake_Executors;
   --  Wakes every spinning executor once (simulated time advanced: their
   --  timers may be due).

   procedure Shutdown;
   --  From now on Is_Shutdown; wakes every spinning executor.

   function Is_Shutdown return Boolean;

end RCL.Process_Context;
