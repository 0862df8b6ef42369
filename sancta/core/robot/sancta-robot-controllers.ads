--  Go-to-goal control with laser obstacle avoidance for a differential
--  drive. Each candidate heading (every 5 degrees) gets the free distance
--  the robot's disk (radius plus a margin) can sweep along it before
--  touching a scan point; the controller steers towards the free heading
--  closest to the goal's bearing (ties broken to the right, so robots that
--  meet pass each other), slows down with the clearance ahead, turns in
--  place when the chosen heading is far off, and stops at the goal.
--
--     T : constant Twist := Command (Config, Current_Pose, Goal, Scan);
with Sancta.Geometry;       use Sancta.Geometry;
with Sancta.Robot.Sensors;  use Sancta.Robot.Sensors;

package Sancta.Robot.Controllers
  with Pure
is

   type Controller_Config is record
      Max_Linear     : Real := 0.6;
      Max_Angular    : Real := 1.5;
      Robot_Radius   : Real := 0.2;
      Margin         : Real := 0.12;
      --  Kept between the robot's disk and any scan point.
      Goal_Tolerance : Real := 0.15;
      Look_Ahead     : Real := 1.0;
      --  A heading is free when the robot can sweep this far along it
      --  (or to the goal if nearer).
      Slow_Down      : Real := 1.0;
      --  Full speed only with this much clearance ahead.
      Heading_Gain   : Real := 2.0;
   end record;

   function Reached
     (Config : Controller_Config; Current : Pose; Goal : Point) return Boolean is
     (Distance (Position (Current), Goal) <= Config.Goal_Tolerance);

   function Free_Distance
     (Config : Controller_Config; Scan : Laser_Scan; Heading : Real) return Real;
   --  How far the robot can move along Heading (robot frame) before its
   --  disk plus margin reaches a scan point (capped at the scan's range).

   function Command
     (Config  : Controller_Config;
      Current : Pose;
      Goal    : Point;
      Scan    : Laser_Scan) return Twist;
   --  The velocity to send now (zero once the goal is reached).

end Sancta.Robot.Controllers;
