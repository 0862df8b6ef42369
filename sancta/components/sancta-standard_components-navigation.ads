--  Robot-side navigation components (wrapping Sancta.Robot.*; the ROS 2
--  side is done by the ros2_subscriber / ros2_publisher bridges):
--
--  "transformer" (event-driven on "pose"): requires "pose" (types.pose, the
--  robot in its odometry frame), optional "origin" (types.pose, the
--  odometry frame in the world; else options x, y, yaw); provides "pose"
--  (types.pose, the robot in the world frame: origin composed with pose).
--  (The runtime's "transform" is the paper's Table 1 Transformer: a local
--  pose to the world given the robot's world pose.)
--
--  "executor" (event-driven on "pose" and "tasks"): the robot's task list
--  as successive goals (Sancta.Robot.Goal_Sequencers). Requires "pose"
--  (types.pose, world); optional "tasks" (types.string "x1,y1; x2,y2",
--  replaces the list; option goals gives the initial list). Provides
--  "goal" (types.pose; yaw 0), "progress" (types.real, 0 .. 1),
--  "completed" (types.integer), "done" (types.boolean), "status"
--  (types.string: "goal 2/3 (4.0,10.0)", "done 3/3", "no task").
--  Options: goals (text), tolerance (m, default 0.3). A bad task list is
--  logged (with its position) and ignored.
--
--  "path_costs" (event-driven on "goal" and "pose"): A* on a world map
--  (Sancta.Robot.Path_Costs) from the robot to its goal. Requires "pose",
--  "goal" (types.pose); provides "waypoint" (types.pose: the next point of
--  the line-of-sight shortened path, the goal itself when straight
--  reachable or unreachable) and "cost" (types.real: path length in m, -1
--  when unreachable). Options: world (required: bundled name or file,
--  checked when loaded), robot_radius (default 0.25). Planners use
--  Cost_Of (Agent, From, To) as their cost callback (below).
--
--  "go_to_goal" (event-driven on "scan"): go-to-goal control with laser
--  obstacle avoidance (Sancta.Robot.Controllers). Requires "pose"
--  (types.pose, world), "scan" (ros2:sensor_msgs/msg/LaserScan), optional
--  "goal" (types.pose; none: stand still). Provides "cmd_vel"
--  (ros2:geometry_msgs/msg/Twist, one per scan) and "reached"
--  (types.boolean). Options: max_linear (0.5), max_angular (1.5), radius
--  (0.2), margin (0.12), tolerance (0.2), look_ahead (1.0).
with Sancta.Geometry;

package Sancta.Standard_Components.Navigation is
   pragma Elaborate_Body;

   function Cost_Of (Agent : String; From, To : Geometry.Point) return Geometry.Real;
   --  The A* path length (m) between two points on the map of the running
   --  path_costs component of Agent (Geometry.Real'Last when unreachable),
   --  the shape of the task planner's cost callback. Raises Program_Error
   --  when Agent has no running path_costs component.

end Sancta.Standard_Components.Navigation;
