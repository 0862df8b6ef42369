--  The first links of the pose-correction chain of the paper's Figure 2,
--  so that its Listing 1.1 runs as written:
--
--  "odometry": a dead-reckoning pose source. Every "period" seconds it
--  integrates a unicycle moving at linear speed v (m/s) and angular speed
--  w (rad/s) from the initial pose (x, y, yaw), and stores output "pose"
--  (types.pose). v and w come from the options of the same names, or from
--  the optional inputs "v" and "w" (types.real) when they hold a value.
--  Options: period (default 0.1), x, y, yaw, v, w (default 0).
--
--  "scan_matching" (Listing 1.1's second component) is registered by
--  Sancta.Standard_Components.Localization, next to the ICP it runs.
--
--  "transform" (the Transformer of the paper's Table 1): a pose given in
--  robot coordinates (input "local") expressed in world coordinates, given
--  the robot's pose in the world (input "frame"): output "world" is
--  Geometry.Compose (frame, local). All types.pose; event driven, once
--  both inputs hold a value.
package Sancta.Standard_Components.Pose_Chain is
   pragma Elaborate_Body;
end Sancta.Standard_Components.Pose_Chain;
