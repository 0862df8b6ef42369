--  Team missions: what a team must do, read from XML and shared through the
--  team database.
--
--     <mission name="office-patrol" world="office.yaml">
--       <robot id="r1" x="1.0" y="2.0" yaw="0"/>      <!-- start (demo) -->
--       <goto id="t1" x="10" y="5"/>                  <!-- goto_pose / visit -->
--       <explore id="s1" x1="2" y1="2" x2="8" y2="2"/> <!-- segment, either way -->
--       <choose id="e1">                               <!-- one entry point -->
--         <at x="1" y="2"/> <at x="3" y="4"/>
--       </choose>
--     </mission>
--
--  An explore segment is an OR of its two directions (entering at one end,
--  leaving at the other); a choose task is an OR of its entry points. The
--  world attribute is relative to the mission file. Errors raise
--  Format_Error "file:line:column: reason".
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;
with Sancta.Geometry;

package Sancta.Team.Missions is

   use Ada.Strings.Unbounded;
   subtype Point is Sancta.Geometry.Point;

   Format_Error : exception;

   type Task_Kind is (Goto_Pose, Explore_Segment, Choose_Entry);

   package Point_Vectors is new Ada.Containers.Vectors
     (Positive, Point, Sancta.Geometry."=");

   type Mission_Task is record
      Id     : Unbounded_String;
      Kind   : Task_Kind := Goto_Pose;
      Points : Point_Vectors.Vector;
      --  Goto: 1 point; Explore: the 2 ends; Choose: the entry points.
   end record;

   function Alternatives (T : Mission_Task) return Positive is
     (case T.Kind is
         when Goto_Pose       => 1,
         when Explore_Segment => 2,
         when Choose_Entry    => Natural (T.Points.Length));

   function Entry_Point (T : Mission_Task; Choice : Positive) return Point;
   function Exit_Point (T : Mission_Task; Choice : Positive) return Point;
   function Inner_Length (T : Mission_Task; Choice : Positive) return Long_Float;
   --  The distance travelled inside the task (the segment's length).

   package Task_Vectors is new Ada.Containers.Vectors (Positive, Mission_Task);

   type Robot_Start is record
      Id    : Unbounded_String;
      Start : Sancta.Geometry.Pose;
   end record;
   package Robot_Vectors is new Ada.Containers.Vectors (Positive, Robot_Start);

   type Mission is record
      Name   : Unbounded_String;
      World  : Unbounded_String;
      Robots : Robot_Vectors.Vector;
      Tasks  : Task_Vectors.Vector;
   end record;

   Max_Entries : constant := 2_000;
   --  Robots and tasks of one mission (Read refuses more: every task is a
   --  database entry replicated on every node, and allocation grows with
   --  the square of the task count).
   Max_Coordinate : constant := 1.0E6;
   --  Metres from the world's origin.

   function Read (File : String) return Mission;

   function Encode (T : Mission_Task) return String;
   --  "kind;x,y;x,y..." (the team database's value of task/<id>).
   function Decode (Id, Text : String) return Mission_Task;
   --  Raises Format_Error naming the task on a malformed text.

end Sancta.Team.Missions;
