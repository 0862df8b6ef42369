--  Goal-to-velocity navigation: plans a path on the path-cost grid (A*),
--  follows its waypoints with the go-to-goal controller (which keeps
--  avoiding what the laser sees), and replans when the robot makes no
--  progress for a while. A* knows only the map, so a robot standing in a
--  gap would get the same path through it again: the stall replan also
--  blocks what the laser sees where the map is free (other robots),
--  inflated like the walls. That layer is temporary: it is dropped once
--  the robot has got Clear_Progress closer to the goal, and the next
--  replan builds it afresh from the scan of that moment (so a robot that
--  has moved away leaves no ghost).
--
--     N.Set_Goal (Planner, Pose, Goal);
--     loop
--        Cmd := N.Command (Planner, Pose, Scan, Now);
--        exit when N.Arrived;
--     end loop;
with Sancta.Geometry;            use Sancta.Geometry;
with Sancta.Robot.Controllers;
with Sancta.Robot.Path_Costs;
with Sancta.Robot.Sensors;       use Sancta.Robot.Sensors;

package Sancta.Robot.Navigators is

   type Navigator is tagged private;

   procedure Configure
     (This : in out Navigator; Config : Controllers.Controller_Config);

   procedure Set_Goal
     (This    : in out Navigator;
      Map     : Path_Costs.Planner;
      Current : Pose;
      Goal    : Point);
   --  Plans at once; without a path the robot heads straight for the goal.

   function Has_Path (This : Navigator) return Boolean;

   function Command
     (This    : in out Navigator;
      Map     : Path_Costs.Planner;
      Current : Pose;
      Scan    : Laser_Scan;
      Now     : Real) return Twist;
   --  The velocity to send; zero once arrived.

   function Arrived (This : Navigator) return Boolean;

   function Waypoint (This : Navigator) return Point;
   --  The point the robot is heading for now.

private

   type Navigator is tagged record
      Config     : Controllers.Controller_Config;
      Goal       : Point;
      Active     : Boolean := False;
      Done       : Boolean := False;
      Planned    : Boolean := False;
      Path       : Path_Costs.Point_Vectors.Vector;
      Next       : Positive := 1;
      Best       : Real := Real'Last;
      --  Closest distance to the goal so far.
      Best_Time  : Real := 0.0;
      Seen       : Path_Costs.Point_Vectors.Vector;
      --  The temporary obstacle layer (laser points off the map's walls
      --  at the last stall replan); empty when not in use.
      Seen_From  : Real := 0.0;
      --  Distance to the goal when Seen was taken.
   end record;

end Sancta.Robot.Navigators;
