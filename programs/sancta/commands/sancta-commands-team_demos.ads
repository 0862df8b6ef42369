--  The end-to-end team demo: a mission for a team of robots in the bundled
--  simulator world. Each robot is a team agent (Sancta.Team.Agents) with
--  its own team network node; the agents and the operator talk only over
--  DDS (the team topics). The simulator is driven in this process (the
--  simros branch's sancta-sim ROS 2 interface was not available): each
--  step it moves the robots, gives each robot's position to its agent and
--  drives it to the goal its agent chooses (A* path plus laser avoidance).
--  Mid-mission one robot is killed (simulator kill and its agent stopped,
--  as a host dying); the survivors detect the loss after the lease,
--  re-plan and finish.
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;
with Sancta.Geometry;
with Sancta.Robot.Path_Costs;
with Sancta.Simulation.Rendering;
with Sancta.Simulation.Worlds;
with Sancta.Team.Agents;
with Sancta.Team.Missions;
with Sancta.Team.Plans;
with Sancta.Team;
use Sancta.Team;  --  the team library's units by their short names (Agents, Plans, ...)

package Sancta.Commands.Team_Demos is

   use Ada.Strings.Unbounded;

   type Run_Options is record
      Kill          : Boolean := True;
      Kill_Robot    : Unbounded_String;
      --  Empty: the robot with the most tasks left when the kill happens.
      Kill_Fraction : Long_Float := 0.3;
      --  Kill when this fraction of the tasks is done.
      Max_Seconds   : Long_Float := 1200.0;
      --  Simulated time limit.
      Out_Dir       : Unbounded_String := To_Unbounded_String ("out/demo");
      Verbose       : Boolean := True;
      Check         : Boolean := False;
      --  The command checks the result (every task done exactly once).
   end record;
   --  What the two team demos (this one, in one process, and the processes'
   --  Sim_Team_Demos) set alike from their command lines.

   function Take_Run_Option
     (Option : String; Index : in out Positive; Into : in out Run_Options) return Boolean;
   --  When Option (the command-line argument at Index) is one of --kill ID,
   --  --no-kill, --kill-at FRACTION, --max SECONDS, --out DIR, --quiet, --check: sets
   --  Into from it (Index then on the option's value, if any) and returns
   --  True; else False. Bad values raise Constraint_Error or
   --  Options.Usage_Error with a message naming the option.
   --  Example: if Take_Run_Option ("--no-kill", I, Config.Run) then ...

   function F1 (X : Long_Float) return String;
   --  X with one decimal ("-0.5", "12.0").

   type Demo_Config is record
      Mission_File  : Unbounded_String;
      World_File    : Unbounded_String;
      --  Empty: the mission's world.
      How           : Agents.Method := Agents.Annealing;
      Rate          : Long_Float := 25.0;
      --  Simulated seconds per wall-clock second.
      Run           : Run_Options;
      Lease         : Duration := 0.5;
      Team          : Unbounded_String := To_Unbounded_String ("team");
      --  The team's topics (/sancta/<team>/...).
      Cut_For       : Duration := 0.0;
      --  > 0: a partition. When Cut_Fraction of the tasks is done, one
      --  robot (the last alive in the mission's order) is cut off from the
      --  team (Networks.Isolate) for Cut_For wall-clock seconds; after the
      --  heal the demo measures how long until every replica holds the
      --  newest entry, as of the heal, of every key (Converge_Wall).
      Cut_Fraction  : Long_Float := 0.5;
   end record;

   type Completion is record
      Task_Id : Unbounded_String;
      Robot   : Unbounded_String;
      Time    : Long_Float := 0.0;
      Reached : Long_Float := -1.0;
      --  When the robot reached the task (arrived at its point, or at the
      --  end of the segment it explored from); negative: not known. Set by
      --  Note_Arrivals.
   end record;
   package Completion_Vectors is new Ada.Containers.Vectors (Positive, Completion);

   type Track_Sample is record
      Time  : Long_Float := 0.0;
      Where : Sancta.Geometry.Pose;
   end record;
   package Track_Vectors is new Ada.Containers.Vectors (Positive, Track_Sample);

   Track_Period : constant Long_Float := 0.1;
   --  Simulated seconds between two samples of a robot's track (sancta-sim
   --  publishes ground truth every 0.1 s: every pose it sends). A sample
   --  is taken when 0.9 periods have passed since the last, so that a
   --  rounding error never skips one.

   type Span is record
      From, To : Long_Float := 0.0;
   end record;
   package Span_Vectors is new Ada.Containers.Vectors (Positive, Span);

   type Robot_Summary is record
      Id       : Unbounded_String;
      Tasks    : Natural := 0;
      Distance : Long_Float := 0.0;
      Alive    : Boolean := True;
      Track    : Track_Vectors.Vector;
      --  Ground-truth poses every Track_Period (until the robot's loss).
      Stops    : Span_Vectors.Vector;
      --  Spans of at least Min_Stop seconds in which it did not move
      --  (Note_Arrivals).
      Travel, At_Task, Stopped : Long_Float := 0.0;
      --  Seconds from the first plan to its last completion: going to its
      --  tasks, at them (from reaching a task to its completion: along an
      --  explored segment), not moving (out of the other two).
   end record;
   package Robot_Summary_Vectors is new Ada.Containers.Vectors (Positive, Robot_Summary);

   type Demo_Result is record
      Tasks_Total     : Natural := 0;
      Tasks_Done      : Natural := 0;
      Duplicates      : Natural := 0;
      --  Tasks completed more than once.
      All_Done        : Boolean := False;
      Completions     : Completion_Vectors.Vector;
      Robots          : Robot_Summary_Vectors.Vector;
      Makespan        : Long_Float := 0.0;
      Killed          : Unbounded_String;
      Kill_Time       : Long_Float := 0.0;
      Replan_Wall     : Long_Float := 0.0;
      --  Wall seconds from the kill to the survivors' adopted new plan
      --  (includes the loss detection, i.e. the lease).
      Replan_Sim      : Long_Float := 0.0;
      Replanned       : Boolean := False;
      Plan_Time       : Long_Float := 0.0;
      --  Simulated seconds when the first plan was adopted (before it, the
      --  robots wait: the allocation is under way).
      Planned_Total   : Long_Float := 0.0;
      Planned_Makespan : Long_Float := 0.0;
      --  The first adopted plan's costs in the planners' model (straight
      --  legs between task points).
      Grid_Total      : Long_Float := 0.0;
      Grid_Makespan   : Long_Float := 0.0;
      --  The same plan with A* path lengths on the world's grid (robot
      --  radius 0.3 m) for the legs: comparable to the executed distance.
      Executed_Total  : Long_Float := 0.0;
      Rounds          : Natural := 0;
      Collisions      : Natural := 0;
      Plan_Before     : Plans.Plan;
      Round_Before    : Plans.Snapshot;
      Plan_After      : Plans.Plan;
      Round_After     : Plans.Snapshot;
      Cut_Robot       : Unbounded_String;
      --  The robot cut off (Cut_For > 0); empty: no partition.
      Converged       : Boolean := False;
      Converge_Wall   : Long_Float := 0.0;
      --  Wall seconds from the heal until every node's replica held, for
      --  every key, the newest (revision, writer) any node held at the heal.
      Converge_Keys   : Natural := 0;
      --  Keys compared.
      Orphans         : Completion_Vectors.Vector;
      --  The killed robot's tasks not done at the kill (its tour in the
      --  plan before the loss), each with the robot that finally did it
      --  (Resolve_Orphans; empty Robot: nobody).
      Last_Leg        : Completion;
      --  The killed robot from its last completion (or the first plan) to
      --  its loss (Time): Task_Id the first of its Orphans (the task it was
      --  going to or at; empty: none), Reached as for a completion
      --  (Note_Arrivals; empty Robot: no such leg).
   end record;

   function Unfinished
     (S      : Plans.Snapshot;
      P      : Plans.Plan;
      Robot  : String;
      Is_Done : not null access function (Task_Id : String) return Boolean)
      return Completion_Vectors.Vector;
   --  The tasks of Robot's tour in plan P of round S not done yet.

   procedure Follow_Replan (Result : in out Demo_Result; Adopted : Plans.Plan)
     with Pre => Result.Replanned;
   --  Keeps as Plan_After the best plan adopted for the re-plan's round: the
   --  round's first plan is the previous one carried over (the team's
   --  anytime start), annealed ones follow. Replan_Wall stays the time to
   --  that first plan.

   procedure Resolve_Orphans (Result : in out Demo_Result);
   --  Fills each orphan's Robot and Time from Result.Completions.

   Reach_Radius : constant Long_Float := 0.5;
   --  Metres from a task's point at which a robot counts as there (the
   --  team members' arrival tolerance is 0.35 m).
   Min_Stop     : constant Long_Float := 1.0;
   Still_Speed  : constant Long_Float := 0.05;
   Still_Turn   : constant Long_Float := 0.1;
   --  A robot is stopped while it moves slower than Still_Speed m/s and
   --  turns slower than Still_Turn rad/s, for Min_Stop seconds or more.

   procedure Note_Arrivals
     (Result : in out Demo_Result;
      Tasks  : Missions.Task_Vectors.Vector);
   --  From each robot's Track: its Stops, each completion's Reached (the
   --  start of the last stay within Reach_Radius of the task's entry
   --  point (for a segment, the end away from where it finished; for a
   --  choice, the point nearest to it) after the robot's previous
   --  completion or the first plan, up to Grace seconds after the
   --  completion: the observer may hear of a completion before the pose
   --  that made it), and its Travel, At_Task, Stopped; Last_Leg (call
   --  after Resolve_Orphans).

   Grace : constant Long_Float := 0.5;

   function Planned_Scene
     (S   : Plans.Snapshot;
      P   : Plans.Plan;
      Ids : Robot_Summary_Vectors.Vector;
      Map : access Sancta.Robot.Path_Costs.Planner := null)
      return Sancta.Simulation.Rendering.Scene;
   --  The planned tours as polylines from each robot's position (with Map:
   --  the legs along A* paths on it; without, straight), with a marker
   --  "task>robot" per task.

   procedure Write_Report
     (Result : Demo_Result;
      World  : Sancta.Simulation.Worlds.World;
      Scene  : Sancta.Simulation.Rendering.Scene;
      Dir    : String);
   --  Dir/summary.json, trajectories.svg/png (World with Scene: executed
   --  trajectories, tasks, robots), plan-before and plan-after .svg/.png
   --  (when the result has those plans; legs along A* paths on World).
   --  Creates Dir.

   procedure Run (Config : Demo_Config; Result : out Demo_Result);
   --  Runs the mission and, unless Out_Dir is empty, writes the report:
   --  Out_Dir/summary.json, trajectories.svg/png (world, executed
   --  trajectories, tasks), plan-before.svg/png and plan-after.svg/png (the
   --  planned tours before and after the loss). Raises Missions.Format_Error
   --  (bad mission) or Constraint_Error with a message (unreachable task,
   --  fewer than two robots).

   procedure Print_Summary (Result : Demo_Result);

   function Check_Passed (Result : Demo_Result) return Boolean;
   --  What "--check" asserts: every task done exactly once and, when a
   --  robot was lost, a re-planning round and each of its unfinished tasks
   --  done by a survivor.

   procedure Note_First_Plan
     (Result : in out Demo_Result;
      S      : Plans.Snapshot;
      P      : Plans.Plan;
      Grid   : Sancta.Simulation.Worlds.World);
   --  Sets the planned costs of Result from plan P of round S (Grid: the
   --  world whose occupancy gives the A* legs).

   function Summary_JSON (Result : Demo_Result) return String;

   subtype Point is Sancta.Geometry.Point;

end Sancta.Commands.Team_Demos;
