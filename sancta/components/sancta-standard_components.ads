--  The standard components of SANCTA, one child package each, registering
--  themselves with Sancta.Runtime.Factory when elaborated:
--     Logger      "logger"          inputs to a CSV / JSON-lines file
--     Watchdog    "watchdog"        abort or alarm when a key goes stale
--     Plumbing    "copy", "merge", "switch"
--     Sources     "value"           a configured value, once or periodically
--     Pose_Chain  "odometry", "scan_matching" (PARTIAL, see there), "transform"
--     ROS2        "ros2_subscriber", "ros2_publisher" (ROS 2 bridges)
--  A program gets them all with "with Sancta.Standard_Components.All_Standard;".
--
--  Every component here is written against the runtime's component API
--  (components, their factory, values): the with_clauses below are for the
--  child units, in whose scope they are.
pragma Warnings (Off, "unit * is not referenced");
with Sancta.Runtime.Components;
with Sancta.Runtime.Factory;
with Sancta.Runtime.Values;
pragma Warnings (On, "unit * is not referenced");

package Sancta.Standard_Components is
end Sancta.Standard_Components;
