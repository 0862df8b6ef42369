--  The sancta-sim program: the simulator (Simulators) driven by a clock and
--  exposed on ROS 2 through RCL. Per robot, under its namespace /NAME:
--     cmd_vel       geometry_msgs/msg/Twist                 in (default QoS)
--     odom          nav_msgs/msg/Odometry                   out, frame "NAME/odom"
--                   (starts at 0,0,0 where the robot starts), child "NAME/base_link"
--     scan          sensor_msgs/msg/LaserScan               out, sensor_data QoS
--     ground_truth  geometry_msgs/msg/PoseStamped           out, frame "map", each step
--                   of --truth-period (default 0.1 s)
--     gps           geometry_msgs/msg/PoseWithCovarianceStamped (gps=on), frame "map"
--  Globally: /clock (rosgraph_msgs/msg/Clock, clock QoS) every step,
--  /sancta_sim/events (std_msgs/msg/String: collisions, added / killed /
--  revived robots; also printed) and the service /sancta_sim/control
--  (sancta_msgs/srv/SimControl: add, kill, revive, teleport, list; an
--  added robot gets the configuration of the first robot listed at start,
--  or the default one).
--  Each robot is an RCL node "sancta_sim" in its namespace; its cmd_vel
--  subscription is read by the stepping loop itself (no executor), so the
--  loop stays single-threaded and the run deterministic for a seed given
--  the same commands.
--
--     sancta-sim office --robot "robot1 2 10 0" --rate 10x --seed 3
--     sancta-sim share/worlds/arena.yaml --robots team.txt --as-fast-as-possible
--     sancta-sim arena --robot "r1 5 5 0" --cmd-timeout 0.5   # stops without commands
package Sancta.Simulation.Sim_Tool is

   procedure Run;
   --  Reads the command line (see Usage); sets the exit status (failure
   --  with a message on standard error for bad arguments or files). Ends
   --  after --duration simulated seconds, on Ctrl-C / SIGTERM.

end Sancta.Simulation.Sim_Tool;
