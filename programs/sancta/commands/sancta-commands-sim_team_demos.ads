--  The team demo with every robot a SANCTA agent of one configuration
--  file, each in its own process, driving a robot of sancta-sim over ROS 2
--  topics: the path of the README's run command (sancta demo).
--
--     Config : Sim_Demo_Config;   --  share/config/sim-team.xml, 4x, kill one
--     Result : Team_Demos.Demo_Result;
--     Run (Config, Result);       --  progress lines, then the report
--     Team_Demos.Print_Summary (Result);
--
--  Run reads the configuration: its robots are the agents with a
--  team_member component, the operator the agent with a team_operator
--  component (its "mission" option names the mission, whose <robot>
--  elements give each robot's start), the world is the robots' path_costs
--  "world" option (else the mission's). It starts, as child processes
--  with their output in Out_Dir/<id>.log and Out_Dir/sim.log:
--     sancta-sim WORLD --robot "ID X Y YAW"... --rate RATE --cmd-timeout 0.5
--     sancta run CONFIG --agent ID [--sim-time] [--set NAME=VALUE]...
--  (one per agent of the file). This process observes over DDS only: a
--  non-robot team node ("demo_monitor") following the replicated team
--  database (tasks done and by whom, rounds, adopted plans) and a ROS 2
--  node following /<id>/ground_truth (trajectories, distances, simulated
--  time) and /sancta_sim/events (collisions). When Kill_Fraction of the
--  tasks are done, it kills the process of one robot's agent (SIGKILL: its
--  host dies) and the robot in the simulator (service /sancta_sim/control);
--  the survivors notice the silence after the lease and re-plan. It ends
--  when every task is done (or on a limit or Ctrl-C), stops the processes
--  (SIGINT, then SIGKILL after 5 s), counts the "did TASK" lines of every
--  robot's log (a task done twice shows there) and writes the report of
--  Team_Demos.Write_Report.
--
--  Simulated time starts with sancta-sim, before the agents are up, and
--  runs at Rate through their start and the first planning, the robots
--  idle: the report's "first plan at N s" is that wait, at the demo's rate.
--  sancta-sim does not race to make up time it lost while starved of CPU
--  (the agents' first annealing takes the machine's cores): it runs slower
--  instead (its last line in sim.log says by how much), so simulated time
--  advances smoothly from the start and a robot's grey ("stopped") time in
--  the Gantt chart is time it really stood still at that rate. A robot
--  takes its first task as soon as the first plan is adopted (its agent
--  anneals in a task of its own), not when its own first annealing ends.
with Ada.Strings.Unbounded;
with Sancta.Runtime.Components;
with Sancta.Commands.Team_Demos;

package Sancta.Commands.Sim_Team_Demos is

   use Ada.Strings.Unbounded;

   type Sim_Demo_Config is record
      Config_File   : Unbounded_String :=
        To_Unbounded_String ("share/config/sim-team.xml");
      Overrides     : Runtime.Components.String_Maps.Map;
      --  --set NAME=VALUE for every agent (e.g. method=auctions).
      Rate          : Long_Float := 4.0;
      --  Simulated seconds per wall second (sancta-sim --rate).
      Sim_Time      : Boolean := True;
      --  The agents run on /clock (sancta run --sim-time).
      Run           : Team_Demos.Run_Options := (Kill_Fraction => 0.25, others => <>);
      --  Kill, Kill_Robot, Kill_Fraction, Max_Seconds (simulated time
      --  limit), Out_Dir, Verbose.
      Max_Wall      : Duration := 900.0;
      --  Wall-clock limit.
      Bin_Dir       : Unbounded_String;
      --  Where sancta and sancta-sim are; empty: next to this program,
      --  else on PATH.
      Secure        : Boolean := False;
      --  DDS-Security (Sancta.Team.Security): a keystore in Out_Dir/keystore,
      --  an enclave per process; only the non-robot agents (the operator)
      --  may publish the mission's tasks.
      Record_Bag    : Boolean := True;
      --  Record every topic into the bag Out_Dir/mission ("rclada bag record
      --  -a", its output in Out_Dir/recorder.log): ground truth, scans,
      --  odometry, cmd_vel, /tf, /map, the team database, plans, markers,
      --  events. Not under Secure (the recorder has no enclave).
      View          : Boolean := False;
      --  Also start the live view (sancta-view --world WORLD, its output in
      --  Out_Dir/view.log) when a display is set (DISPLAY or
      --  WAYLAND_DISPLAY), else say so and run without it; the view is
      --  left open at the end (closing it is the user's).
   end record;

   procedure Run (Config : Sim_Demo_Config; Result : out Team_Demos.Demo_Result);
   --  Runs the demo (see above) and writes the report unless Out_Dir is
   --  empty. Raises Constraint_Error with a message naming the file and
   --  the problem for a configuration that cannot run the demo (errors in
   --  it, no team_operator, fewer than two robots, a robot without a start
   --  in the mission) or a program that cannot be started.

end Sancta.Commands.Sim_Team_Demos;
