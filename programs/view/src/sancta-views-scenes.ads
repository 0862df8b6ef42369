--  What the view knows of a team: robots (pose, trail, scan, tour, costs,
--  alive or lost), the mission's tasks and their states, the current
--  allocation's figures, an event log, and the world map. Samples come in
--  as plain records (Feeds decodes the DDS messages); whatever is out of
--  range in them (non-finite or huge coordinates, arrays of unequal
--  lengths, empty names) is dropped and noted once in the event log, so a
--  malformed or hostile sample never disturbs the picture.
--
--     Store.Update_Robot (Sample);       --  from the DDS task
--     S : constant Scene := Store.Get;   --  a copy, for drawing
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Sancta.Geometry;
with Sancta.Robot.Grids;

package Sancta.Views.Scenes is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;

   package Point_Vectors is new Ada.Containers.Vectors (Positive, Point);
   package Text_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);
   package Choice_Vectors is new Ada.Containers.Vectors (Positive, Positive);

   Max_Robots : constant := 32;
   Max_Tasks  : constant := 2_000;
   Max_Points : constant := 64;
   --  Per task. Larger samples are cut (and noted).
   Max_Trail  : constant := 4_000;
   Max_Events : constant := 200;
   Max_Text   : constant := 80;
   --  Names and status texts are cut to this length.

   --  Samples (decoded messages) ----------------------------------------------

   type Robot_Sample is record
      Robot        : Unbounded_String;
      Where        : Pose;
      Status       : Unbounded_String;
      Current_Task : Unbounded_String;
      Round        : Natural := 0;
      Plan_Round   : Natural := 0;
      Done         : Text_Vectors.Vector;
      Tour         : Text_Vectors.Vector;
      Choices      : Choice_Vectors.Vector;
      Planned_Cost : Real := 0.0;
      Distance     : Real := 0.0;
   end record;
   --  sancta_msgs/msg/RobotState.

   type Task_Sample is record
      Id     : Unbounded_String;
      Kind   : Unbounded_String;
      Points : Point_Vectors.Vector;
      Choice : Natural := 0;
      State  : Unbounded_String;
      Robot  : Unbounded_String;
   end record;
   package Task_Vectors is new Ada.Containers.Vectors (Positive, Task_Sample);

   type Plan_Sample is record
      Team       : Unbounded_String;
      Source     : Unbounded_String;
      Round      : Natural := 0;
      Plan_Round : Natural := 0;
      Proposer   : Unbounded_String;
      Makespan   : Real := 0.0;
      Total      : Real := 0.0;
      Robots     : Text_Vectors.Vector;
      Tasks      : Task_Vectors.Vector;
   end record;
   --  sancta_msgs/msg/TeamPlan.

   --  The scene -----------------------------------------------------------------

   type Task_State is (Pending, Assigned, Active, Done, Reallocated);

   function Parse_State (Text : String) return Task_State;
   --  Unknown texts read as Pending.

   type Robot_View is record
      Id           : Unbounded_String;
      Colour       : Natural := 0;
      --  Index into the palette (Drawing.Colour_Of).
      Where        : Pose;
      Trail        : Point_Vectors.Vector;
      Scan         : Point_Vectors.Vector;
      --  Laser hits in the world frame (the latest scan).
      Status       : Unbounded_String;
      Current_Task : Unbounded_String;
      Done, Left   : Natural := 0;
      Tour         : Text_Vectors.Vector;
      Choices      : Choice_Vectors.Vector;
      Planned_Cost : Real := 0.0;
      Distance     : Real := 0.0;
      Plan_Round   : Natural := 0;
      --  The round of the plan its tour comes from.
      Last_Heard   : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
      Killed       : Boolean := False;
      --  The simulator reported it killed (and not revived since).
      Lost         : Boolean := False;
      --  Killed, silent for longer than Lost_After, or left out of the
      --  team's current round.
   end record;
   package Robot_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Robot_View);

   type Task_View is record
      Id     : Unbounded_String;
      Kind   : Unbounded_String;
      Points : Point_Vectors.Vector;
      Choice : Natural := 0;
      State  : Task_State := Pending;
      Robot  : Unbounded_String;
   end record;
   package Task_View_Vectors is new Ada.Containers.Vectors (Positive, Task_View);

   type Event is record
      At_Time : Duration;
      --  Seconds since the view started.
      Text    : Unbounded_String;
   end record;
   package Event_Vectors is new Ada.Containers.Vectors (Positive, Event);

   type Grid_Access is access constant Sancta.Robot.Grids.Grid;

   type Scene is record
      Team         : Unbounded_String;
      Robots       : Robot_Maps.Map;
      Tasks        : Task_View_Vectors.Vector;
      Round        : Natural := 0;
      Plan_Round   : Natural := 0;
      Proposer     : Unbounded_String;
      Makespan     : Real := 0.0;
      Total        : Real := 0.0;
      Round_Robots : Text_Vectors.Vector;
      Events       : Event_Vectors.Vector;
      Map          : Grid_Access;
      Map_Version  : Natural := 0;
      Samples      : Natural := 0;
      Rejected     : Natural := 0;
      --  Samples dropped as malformed.
      Age          : Duration := 0.0;
      --  Seconds since the view started, when this copy was taken.
   end record;

   function Tasks_In (S : Scene; State : Task_State) return Natural;
   function Tasks_Done (S : Scene) return Natural;

   function Find_Task (S : Scene; Id : String) return Natural;
   --  The index in S.Tasks, 0 when absent.

   function Colour_Index (Robot : String) return Natural;
   --  The palette entry of a robot: the number its name ends with (r3 -> 3)
   --  when it has one, else a hash of the name; stable across runs.

   protected type Store is
      procedure Set_Lost_After (Seconds : Duration);
      procedure Update_Robot (Sample : Robot_Sample);
      procedure Update_Plan (Sample : Plan_Sample);
      procedure Update_Scan (Robot : String; Hits : Point_Vectors.Vector);
      --  Hits relative to the robot (its frame); placed at its pose.
      procedure Sim_Event (Text : String);
      --  A line of /sancta_sim/events ("killed r2 at ...").
      procedure Set_Map (Map : Grid_Access);
      procedure Note (Text : String);
      --  An event of the view itself (an operator action's outcome).
      procedure Reject (What : String);
      --  A malformed sample: counted, noted once per kind of problem.
      procedure Refresh;
      --  Marks the silent robots lost (called periodically).
      function Get return Scene;
   private
      Current    : Scene;
      Lost_After : Duration := 3.0;
      Noted      : Text_Vectors.Vector;
      --  Problems already noted in the event log.
      In_Round   : Text_Vectors.Vector;
      --  Robots that were in some round of the team.
      Round_Seen : Duration := 0.0;
      --  When the current round was first seen.
      Mission_Over : Boolean := False;
   end Store;

   function Image (X : Real) return String;
   --  X with one decimal ("12.3", "-0.5").

   function Elapsed return Duration;
   --  Seconds since the program started.

end Sancta.Views.Scenes;
