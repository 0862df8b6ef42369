--  Secured teams (DDS-Security, the SROS2 way): one keystore per team run,
--  an enclave per process, permissions that say who may write the mission.
--
--     /sancta/<team>/<id>   a team node's process (robot, operator, monitor)
--     /sancta/sim           the simulator
--
--  Operators (Task_Writers) may publish and subscribe every topic; every
--  other enclave may do everything but publish the mission's entries
--  (Networks.Tasks_Topic: "rt/sancta/<team>/tasks"); readers (a bag
--  recorder) may subscribe every topic and publish only what a node
--  publishes about itself (Reader_Rules): they cannot inject anything. Participants without
--  a certificate of the keystore's CA can neither join, read nor inject
--  (governance: authentication required, everything encrypted).
--
--     Create_Keystore ("out/demo/keystore", "team",
--                      Task_Writers => ["operator"], Other_Nodes => ["r1", "r2"],
--                      Readers => ["recorder"]);
--     Enable ("out/demo/keystore");          --  ROS_SECURITY_* for children
--     Spawn_With_Enclave (Enclave ("team", "r1"), ...);
with Ada.Strings.Unbounded;
with RCL.Security.Keystores;

package Sancta.Team.Security is

   use Ada.Strings.Unbounded;

   subtype Id_List is RCL.Security.Keystores.Name_List;

   function Enclave (Team, Id : String) return String is ("/sancta/" & Team & "/" & Id);
   Simulator_Enclave : constant String := "/sancta/sim";

   Reader_Rules : constant RCL.Security.Keystores.Topic_Rules :=
     [1 => (True, RCL.Security.Keystores.Subscribe, To_Unbounded_String ("*")),
      2 => (True, RCL.Security.Keystores.Publish, To_Unbounded_String ("ros_discovery_info")),
      3 => (True, RCL.Security.Keystores.Publish, To_Unbounded_String ("rt/rosout")),
      4 => (True, RCL.Security.Keystores.Publish, To_Unbounded_String ("rt/parameter_events")),
      5 => (True, RCL.Security.Keystores.Publish, To_Unbounded_String ("rr/*"))];
   --  A reader's permissions: every topic read; written only the graph
   --  information, its log, its parameter events and the replies of its
   --  own parameter services (every node has them).

   procedure Create_Keystore
     (Dir, Team : String; Task_Writers, Other_Nodes : Id_List;
      Readers : Id_List := [1 .. 0 => <>]);
   --  A new keystore in Dir (made if need be), an enclave for each id of
   --  the three lists (Enclave (Team, Id)) and Simulator_Enclave, with the
   --  permissions above. ROS_Exception when openssl fails.

   procedure Enable (Keystore : String);
   --  Sets ROS_SECURITY_ENABLE=true, ROS_SECURITY_STRATEGY=Enforce and
   --  ROS_SECURITY_KEYSTORE (absolute) in this process's environment, which
   --  child processes inherit; each names its enclave with
   --  ROS_SECURITY_ENCLAVE_OVERRIDE (Set_Child_Enclave).

   procedure Set_Child_Enclave (Name : String);
   --  ROS_SECURITY_ENCLAVE_OVERRIDE for the next child started ("" clears
   --  it); this process's own enclave is RCL.Security.Set_Enclave's.

end Sancta.Team.Security;
