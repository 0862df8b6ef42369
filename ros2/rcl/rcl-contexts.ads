--  The process's ROS 2 context: one DDS participant (USER_DATA
--  "enclave=/;") on ROS_DOMAIN_ID, loopback-only when ROS_LOCALHOST_ONLY=1
--  or ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST (CYCLONEDDS_URI applied over
--  it), shared by every node of the process; and orderly shutdown.
--
--  The context is created by the first node (or Init) and lives until the
--  end of the program; Init also installs handlers for SIGINT and SIGTERM
--  (blocking them in the calling task). Shutdown (also on Ctrl-C / SIGTERM)
--  makes every Spin return; publishing afterwards raises
--  ROS_Exception, which ends publisher tasks such as the slides' talker's.
--  Another Ctrl-C more than a second later exits the process at once
--  (status 130).
with RCL.DDS;

package RCL.Contexts is

   procedure Init;
   --  Creates the participant if not done yet; raises ROS_Exception on a
   --  bad ROS_DOMAIN_ID (naming the variable and its value) or a DDS error.

   procedure Init (Domain : RCL.DDS.Domain_Id; Localhost_Only : Boolean)
     with Pre => not Is_Initialized;
   --  The same with an explicit domain and discovery range instead of the
   --  environment's (before the first node).

   procedure Init (Participant_Lease : Duration)
     with Pre => not Is_Initialized and then Participant_Lease >= 0.1;
   --  Init, the participant's lease being Participant_Lease instead of the
   --  DDS configuration's (10 s by default): peers drop this process after
   --  that long without hearing it, and it announces itself every 0.8 x
   --  Participant_Lease (below 10 s; every 8 s by default), so that a peer
   --  that dropped it (a network cut, then healed) finds it again within that
   --  time (RCL.DDS.Create). E.g. Init (Participant_Lease => 2.0).

   function Is_Initialized return Boolean;

   function Domain return RCL.DDS.Domain_Id;
   --  The context's domain: ROS_DOMAIN_ID (default 0) unless Init said.

   function Localhost_Only return Boolean;

   procedure Shutdown;
   --  Stops every spin of the process (idempotent).

   function Is_Shutdown return Boolean;

   procedure Install_Signal_Handlers;
   --  SIGINT and SIGTERM call Shutdown (done by Init).

   function Enclave return String;
   --  The security enclave of the participant ("/" unless --ros-args -e).

   function Parse_Domain_Id (Image : String) return RCL.DDS.Domain_Id;
   --  "" -> 0; raises ROS_Exception naming ROS_DOMAIN_ID and the bad value.

end RCL.Contexts;
