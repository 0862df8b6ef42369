--  `sancta run FILE --agent ID --managed`: each agent of the run is a ROS 2
--  managed (lifecycle) node, /sancta_<ID>, that a lifecycle manager or
--  `rclada lifecycle set` drives through the ROS 2 state machine:
--
--     configure    the agent's components are created (from FILE)
--     activate     they start: the agent runs as `sancta run` runs it
--     deactivate   they stop (reverse start order) and are created anew,
--                  so that the next activate starts fresh components
--     cleanup      they are discarded (back to unconfigured)
--     shutdown     stopped and discarded; the program ends when every
--                  agent is finalized (or on Ctrl-C, or after --for)
--
--  A transition whose work fails (a component that cannot be created) is
--  answered Failure and logged; the node stays where it was. Example:
--
--     sancta run share/config/team.xml --agent Ari --managed &
--     rclada lifecycle set /sancta_Ari configure
--     rclada lifecycle set /sancta_Ari activate
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Local_Databases;

package Sancta.Commands.Managed_Agents is

   function Node_Name (Agent_Id : String) return String;
   --  "sancta_" & Agent_Id, each character a ROS 2 node name cannot hold
   --  replaced by '_' ("r-1" gives "sancta_r_1").

   procedure Run
     (Config : Sancta.Runtime.Configurations.Configuration;
      Agents : Sancta.Runtime.Local_Databases.Key_Vectors.Vector;
      Clock  : Sancta.Runtime.Clocks.Clock_Access;
      Limit  : Duration)
     with Pre => not Agents.Is_Empty;
   --  Config has no errors and holds every agent of Agents. Returns on
   --  shutdown (Sancta.Runtime.Shutdown), every agent finalized, or after
   --  Limit seconds when Limit > 0; running agents are stopped first.

end Sancta.Commands.Managed_Agents;
