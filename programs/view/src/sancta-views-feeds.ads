--  The view's DDS side: one task owning a ROS 2 node that follows
--     /sancta/<team>/gui/robots   sancta_msgs/msg/RobotState  (GUI relays)
--     /sancta/<team>/gui/plan     sancta_msgs/msg/TeamPlan    (GUI relays)
--     /sancta_sim/events          std_msgs/msg/String         (sancta-sim)
--     <map topic>                 nav_msgs/msg/OccupancyGrid  (transient-local)
--     /<robot>/scan               sensor_msgs/msg/LaserScan   (once scans are shown)
--  into Scene_Store, and carries out the operator's actions through the
--  existing interfaces: kill/revive a simulated robot (service
--  /sancta_sim/control) and load a mission (published in the team
--  database as team_operator does, by a non-robot team node
--  "view_operator"). Outcomes of actions go to the event log.
--
--     Feeds.Start ((Team => +"team", World => +"office", others => <>));
--     ... Feeds.Scene_Store.Get ...
--     Feeds.Request_Control ("kill", "r2");
--     Feeds.Stop;
with Ada.Strings.Unbounded;
with Sancta.Views.Scenes;

package Sancta.Views.Feeds is

   use Ada.Strings.Unbounded;

   type Feed_Config is record
      Team       : Unbounded_String := To_Unbounded_String ("team");
      World      : Unbounded_String;
      --  A bundled world (office, arena) or a map file; "" none.
      Map_Topic  : Unbounded_String := To_Unbounded_String ("/map");
      --  "" follows no map topic.
      Lost_After : Duration := 3.0;
      --  A robot whose relay is silent this long is shown lost.
   end record;

   Scene_Store : Scenes.Store;

   procedure Start (Config : Feed_Config);
   --  Loads the world (Constraint_Error naming it when it cannot) and
   --  starts the DDS task.

   procedure Request_Control (Command, Robot : String);
   --  "kill" or "revive" Robot in sancta-sim (asynchronous).

   procedure Request_Mission (File : String);
   --  Publishes the mission of File to the team (asynchronous).

   procedure Show_Scans;
   --  Subscribes to the robots' laser scans (the first time it is asked).

   procedure Stop;
   --  Ends the DDS task (waits for it).

   function Interrupted return Boolean;
   --  The ROS 2 context was shut down (Ctrl-C, SIGTERM).

end Sancta.Views.Feeds;
