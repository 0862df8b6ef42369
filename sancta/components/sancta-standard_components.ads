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
end Sancta.Standard_Components;
