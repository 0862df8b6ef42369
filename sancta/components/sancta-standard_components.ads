--  The standard components of SANCTA, one child package each, registering
--  themselves with Sancta.Runtime.Factory when elaborated:
--     Logger      "logger"          inputs to a CSV / JSON-lines file
--     Watchdog    "watchdog"        abort or alarm when a key goes stale
--     Plumbing    "copy", "merge", "switch"
--     Sources     "value"           a configured value, once or periodically
--     Pose_Chain  "odometry", "scan_matching" (PARTIAL, see there), "transform"
--     ROS2        "ros2_subscriber", "ros2_publisher" (ROS 2 bridges)
--  A program gets them all with "with Sancta.Standard_Components.All_Standard;".
package Sancta.Standard_Components is
   pragma Pure;

   function Name_Token (Text : String) return String is
     [for I in Text'Range =>
        (if Text (I) in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_' then Text (I) else '_')];
   --  Text with every character other than a letter, a digit or '_'
   --  replaced by '_': a token of a ROS 2 node or topic name.
   --  Example: Name_Token ("r-1.b") = "r_1_b"
end Sancta.Standard_Components;
