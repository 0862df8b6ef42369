--  Team agents: a node of the team (a robot or the operator) with its team
--  network, its replica of the team database and its part of the
--  distributed allocation.
--
--  Team database keys:
--     task/<id>          the task (Missions.Encode)
--     mission            comma-separated ids of every mission task
--     robot/<id>         "robot": the node is a robot of the team
--     pose/<id>          "x,y": the robot's latest position
--     done/<task>        id of the robot that did the task
--     round              the current re-planning round (Plans.Snapshot)
--     proposal/<node>    a plan for a round (Plans.Plan)
--
--  Rounds. The coordinator (the alive robot with the smallest id) opens a
--  new round when the alive robots differ from the current round's, or a
--  mission task is neither done nor in the round: the round holds every
--  alive robot's position and every task not done. A robot lost (silent
--  for its lease) thus returns its unfinished tasks to the plan, a robot
--  joining gets tasks, and tasks done stay done. A node opens no round in
--  its first two leases (it has not heard the others yet).
--
--  Allocation of a round, as configured:
--  * Annealing: every robot anneals the round (its own seed) and publishes
--    its proposal; then, a few times, it anneals again from the best
--    proposal known and publishes only when it found a better one.
--  * Auctions: the coordinator runs sequential single-item auctions on the
--    "auction" channel (offer the unallocated tasks to the group "robots";
--    each robot bids the cost of its tour with its best insertion of its
--    cheapest task; the lowest bid wins; award with the winner's new
--    tour); a bidder silent for 1 s is skipped; the result is the
--    coordinator's proposal.
--  Every node adopts the same plan: among the proposals for the current
--  round, the lowest Value (ties: the smallest proposer id).
--
--  Execution (robots): Current_Goal gives the next point of the first task
--  of the robot's tour in the adopted plan that is not done; Arrived marks
--  progress (an explore segment has two points) and finally done/<task>.
--  A robot's annealing runs in a task of its own, so the agent's task
--  keeps following the team's plan meanwhile: a robot takes its first task
--  as soon as another robot's proposal is adopted, not when its own first
--  annealing ends. With A* leg costs (Config.Costs), the annealing task
--  first costs the legs between the mission's tasks, once the mission is
--  known: the coordinator opens no round in its first two leases, and the
--  first annealing then finds them in the cache (demo: 0.3-0.6 s instead
--  of 1.2-5 s of wall time).
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Ordered_Sets;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Interfaces;
with Sancta.Geometry;
with Sancta.Team.Replicated_Databases;
with Sancta.Team.Grid_Costs;
with Sancta.Team.Missions;
with Sancta.Team.Networks;
with Sancta.Team.Plans;

package Sancta.Team.Agents is

   use Ada.Strings.Unbounded;

   type Method is (Annealing, Auctions);

   function Parse_Method (Text : String) return Method;
   --  "annealer"/"annealing" or "auction"/"auctions"; Constraint_Error
   --  naming the text otherwise.

   type Agent_Config is record
      Id         : Unbounded_String;
      Team       : Unbounded_String := To_Unbounded_String ("team");
      --  The team's topics (/sancta/<team>/...).
      Is_Robot   : Boolean := True;
      Lease      : Duration := 1.0;
      How        : Method := Annealing;
      Budget     : Duration := 0.25;
      --  Annealer wall-clock time per attempt.
      Rounds     : Natural := 3;
      --  Improvement attempts from the best proposal (annealing).
      Seed       : Interfaces.Unsigned_64 := 1;
      Verbose    : Boolean := True;
      --  Rounds, auctions and annealing results on standard error.
      Costs      : Grid_Costs.Cost_Access := null;
      --  Leg costs of the allocation (annealing, bids): A* lengths on the
      --  world's grid; null: straight lines. Every robot of a team must
      --  use the same (plans' values are compared across robots).
   end record;

   type Agent is tagged limited private;
   type Agent_Access is access all Agent'Class;

   function Create (Config : Agent_Config) return Agent_Access;
   --  Makes and starts the agent (its network, database and task).

   function Create
     (Config : Agent_Config;
      Net    : not null Networks.Network_Access;
      Db     : not null Replicated_Databases.Team_Database_Access) return Agent_Access
     with Pre => Networks.Id (Net.all) = To_String (Config.Id);
   --  The same on a network made by the caller (not started: the agent
   --  subscribes, then starts it) and its database, attached to Net (the
   --  XML components network and global_database make them).

   function Id (This : Agent) return String;
   function Database (This : Agent) return Replicated_Databases.Team_Database_Access;
   function Network (This : Agent) return Networks.Network_Access;

   function Find (Id : String) return Agent_Access;
   --  The agent of this process made by Create with that id, or null: how
   --  another component of the same SANCTA agent reaches its team agent
   --  (gui_relay reads the plan of team_member's agent).

   procedure Stop (This : in out Agent);
   --  Stops everything (the team sees the node lost after its lease).

   --  Operator ------------------------------------------------------------------

   procedure Publish_Mission (This : in out Agent; M : Missions.Mission);
   --  Writes every task, then the mission key.

   --  Robots ----------------------------------------------------------------------

   procedure Set_Pose (This : in out Agent; Where : Sancta.Geometry.Point);
   --  The robot's position; the agent's task writes the latest one to the
   --  team database (pose/<id>) at most every Pose_Period of wall-clock
   --  time: a simulation run 25 times faster than real time would
   --  otherwise write 25 times as many poses (20 robots: 1,000 writes a
   --  second, each delivered to every node).

   Pose_Period : constant Duration := 0.25;

   procedure Current_Goal
     (This    : in out Agent;
      Found   : out Boolean;
      Goal    : out Sancta.Geometry.Point;
      Task_Id : out Unbounded_String);
   procedure Arrived (This : in out Agent; Task_Id : String; Completed : out Boolean);
   --  At the point Current_Goal gave for Task_Id; Completed when that
   --  finished the task (now done/<task> = this robot).

   --  Observation (every node) ---------------------------------------------------

   function Round (This : Agent) return Plans.Snapshot;
   function Adopted (This : Agent) return Plans.Plan;
   --  The adopted plan of the current round (Generation 0: none yet).
   function Mission_Tasks (This : Agent) return Natural;
   function Done_Tasks (This : Agent) return Natural;
   function All_Done (This : Agent) return Boolean;
   --  The mission is known and every task is done.

   function Has_Quorum (This : Agent'Class) return Boolean;
   --  The partition rule: the voters are the robots of the current round
   --  and the operator (the writer of "mission"); a node opens rounds and
   --  starts tasks only while it hears a strict majority of them, itself
   --  included. A side cut off from the majority finishes the task under
   --  way and starts nothing new until the link heals. True before the
   --  first round.

private

   package Name_Sets is new Ada.Containers.Indefinite_Ordered_Sets (String);

   type Bid is record
      Robot  : Unbounded_String;
      Task_Id : Unbounded_String;
      Cost   : Long_Float := Long_Float'Last;
      Pos    : Positive := 1;
      Choice : Positive := 1;
   end record;

   protected type Bid_Box is
      procedure Open (Generation, Step : Natural);
      procedure Add (Generation, Step : Natural; B : Bid);
      function Count return Natural;
      function Best return Bid;
   private
      Gen, Item : Natural := 0;
      N         : Natural := 0;
      Winner    : Bid;
   end Bid_Box;

   type View is record
      Round   : Plans.Snapshot;
      Adopted : Plans.Plan;
   end record;

   protected type View_Box is
      procedure Set (V : View);
      function Get return View;
   private
      Current : View;
   end View_Box;

   type Pose_Note is record
      Where   : Sancta.Geometry.Point := (0.0, 0.0);
      Pending : Boolean := False;
   end record;

   protected type Pose_Box is
      procedure Set (Where : Sancta.Geometry.Point);
      procedure Take (Note : out Pose_Note);
      --  The latest position not yet written (Pending), and clears it.
   private
      Latest : Pose_Note;
   end Pose_Box;

   type Progress is record
      Active : Unbounded_String;
      Phase  : Natural := 0;
      Done   : Name_Sets.Set;
   end record;

   protected type Progress_Box is
      procedure Set (P : Progress);
      function Get return Progress;
   private
      Current : Progress;
   end Progress_Box;

   task type Worker (Owner : not null access Agent'Class) is
      entry Go;
   end Worker;
   type Worker_Access is access Worker;

   type Job_Kind is (Anneal, Warm_Legs);
   --  Warm_Legs: only the legs between the tasks of Round (no robots),
   --  through Costs, whose cache then answers the first annealing's.

   type Anneal_Job is record
      Kind     : Job_Kind := Anneal;
      Round    : Plans.Snapshot;
      Seed     : Interfaces.Unsigned_64 := 1;
      Budget   : Duration := 0.25;
      Start    : Plans.Plan;
      Proposer : Unbounded_String;
      Costs    : Grid_Costs.Cost_Access := null;
   end record;
   --  One annealing of a round (Plans.Anneal's arguments), by value.

   type Anneal_Outcome is record
      Result  : Plans.Plan;
      Took    : Duration := 0.0;
      Failure : Unbounded_String;
      --  The exception's information when the annealing failed.
   end record;

   protected type Anneal_Box is
      --  The hand-over between the agent's task (Worker), which submits an
      --  annealing and collects its outcome, and its Annealer task, which
      --  runs it: the agent task goes on reading the team's plan (and the
      --  robot on taking its tasks) while its own proposal is annealed.
      --  At most one job at a time: Submit only after Collect gave the
      --  previous one's outcome.
      procedure Submit (Job : Anneal_Job);
      entry Take (Job : out Anneal_Job; Quit : out Boolean);
      --  The Annealer's next job; Quit once Shut was called.
      procedure Finish (Outcome : Anneal_Outcome);
      procedure Collect (Ready : out Boolean; Outcome : out Anneal_Outcome);
      --  The finished job's outcome (Ready), once.
      procedure Shut;
   private
      Pending  : Boolean := False;
      Finished : Boolean := False;
      Closing  : Boolean := False;
      Next     : Anneal_Job;
      Last     : Anneal_Outcome;
   end Anneal_Box;

   task type Annealer (Jobs : not null access Anneal_Box);
   type Annealer_Access is access Annealer;

   type Auction_Consumer (Owner : not null access Agent) is
     limited new Networks.Consumer with null record;
   overriding procedure On_Message
     (This : in out Auction_Consumer; Sender, Channel, Payload : String);

   type Proposal_Entry is record
      Revision : Long_Long_Integer := 0;
      Writer   : Unbounded_String;
      Round    : Natural := 0;
      --  The entry (revision, writer) decoded for that round's snapshot.
      Fits     : Boolean := False;
      Proposal : Plans.Plan;
   end record;
   package Proposal_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Proposal_Entry);

   type Agent is tagged limited record
      Config   : Agent_Config;
      Net      : Networks.Network_Access;
      Db       : Replicated_Databases.Team_Database_Access;
      Bids     : Bid_Box;
      Views    : View_Box;
      Steps    : Progress_Box;
      Poses    : Pose_Box;
      Next_Pose_Write : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
      Auction  : aliased Auction_Consumer (Agent'Access);
      Bundle   : Plans.Step_Vectors.Vector;
      --  The auction tour (bidder side), of Bundle_Gen.
      Bundle_Gen : Natural := 0;
      Bid_Round  : Plans.Snapshot;
      Runner   : Worker_Access;
      Jobs     : aliased Anneal_Box;
      Anneals  : Annealer_Access;
      --  Robots: the agent's proposals are annealed there.
      Annealing : Boolean := False;
      --  A job of this agent is in Jobs (the agent task's own).
      Warming   : Boolean := False;
      Warmed    : Boolean := False;
      --  The job in Jobs is a Warm_Legs one; one was submitted (the agent
      --  task's own).
      Job_Published : Long_Float := Long_Float'Last;
      --  The value of this agent's proposal for the job's round when the
      --  job was submitted (the agent task's own).
      Stopping : Boolean := False
        with Atomic;
      Mismatch_Since : Ada.Real_Time.Time := Ada.Real_Time.Time_Last;
      Last_Round_Text : Unbounded_String;
      Improved_Rounds : Natural := 0;
      Previous        : View;
      --  The last round with its adopted plan, kept when a new round opens:
      --  a re-plan starts from that plan (Plans.Carried_Over).
      Started_At : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
      Proposals : Proposal_Maps.Map;
      --  Decoded proposals by key (the agent task's cache).
   end record;

end Sancta.Team.Agents;
