--  The simulator proper: N differential-drive robots in a World, stepped
--  by a simulation clock. Commands go in per robot (Set_Command, a Twist);
--  sensor readings come out as plain records (odometry, laser scans, GPS
--  fixes, ground truth) with a counter per robot that grows each time a new
--  reading is produced, so a driver publishes exactly the new ones.
--  Collisions (with walls or robots) stop the robot and are reported as
--  events, once per contact. A run is deterministic for a seed: each robot
--  draws its noise from its own generator.
--
--  Faster than real time is just calling Step faster; the simulator never
--  reads the wall clock.
--
--  ROS 2 exposure (done by the driver program, robot namespace = Name):
--     <name>/cmd_vel       geometry_msgs/Twist     -> Set_Command
--     <name>/odom          nav_msgs/Odometry       <- Latest_Odometry (Odometry_Count)
--     <name>/scan          sensor_msgs/LaserScan   <- Latest_Scan (Scan_Count)
--     <name>/ground_truth  geometry_msgs/PoseStamped <- Ground_Truth
--     <name>/gps           (fix + std dev)         <- Latest_GPS (GPS_Count)
--     /clock               rosgraph_msgs/Clock     <- Clock
--     add/kill/revive service                      -> Add_Robot, Kill, Revive, Teleport
--     collisions                                   <- Take_Events
--
--     S.Initialize (World, Seed => 7);
--     R := S.Add_Robot (Default_Robot, (1.0, 1.0, 0.0));
--     loop
--        S.Set_Command (R, Controller_Output);
--        S.Step (0.05);
--        if S.Scan_Count (R) /= Last then Publish (S.Latest_Scan (R)); ...
--     end loop;
with Ada.Containers.Vectors;
with Ada.Finalization;
with Ada.Strings.Unbounded;
with Interfaces;
with Sancta.Geometry;                  use Sancta.Geometry;
with Sancta.Robot.Sensors;             use Sancta.Robot.Sensors;
with Sancta.Simulation.Generators;
with Sancta.Simulation.Worlds;

package Sancta.Simulation.Simulators is

   type Laser_Config is record
      Beams         : Positive := 360;
      Field_Of_View : Real := 2.0 * Pi;
      --  Beams are spread evenly: a full circle gets no duplicate beam.
      Max_Range     : Real := 8.0;
      Min_Range     : Real := 0.05;
      Noise_Std_Dev : Real := 0.01;
      --  Gaussian range noise, m.
      Rate          : Real := 10.0;
      --  Scans per simulated second (0: no laser).
   end record;

   type Odometry_Config is record
      Rate                : Real := 20.0;
      Linear_Scale_Error  : Real := 0.0;
      --  Measured distance = (1 + error) * true distance.
      Angular_Scale_Error : Real := 0.0;
      Angular_Bias        : Real := 0.0;
      --  Drift of the measured heading, rad/s while moving or turning.
      Linear_Noise        : Real := 0.0;
      --  Standard deviation of the distance noise per metre travelled.
      Angular_Noise       : Real := 0.0;
      --  Standard deviation of the heading noise per radian turned.
   end record;

   type GPS_Config is record
      Enabled : Boolean := False;
      Rate    : Real := 1.0;
      Std_Dev : Real := 0.5;
   end record;

   type Robot_Config is record
      Radius            : Real := 0.2;
      Max_Linear        : Real := 1.0;
      Max_Angular       : Real := 2.0;
      Max_Linear_Accel  : Real := 2.0;
      Max_Angular_Accel : Real := 6.0;
      Laser             : Laser_Config;
      Odometry          : Odometry_Config;
      GPS               : GPS_Config;
   end record;

   Default_Robot : constant Robot_Config := (others => <>);

   function Is_Valid (Config : Robot_Config) return Boolean is
     (Config.Radius > 0.0 and then Config.Max_Linear >= 0.0
      and then Config.Max_Angular >= 0.0 and then Config.Max_Linear_Accel > 0.0
      and then Config.Max_Angular_Accel > 0.0
      and then Config.Laser.Beams <= 10_000
      and then Config.Laser.Field_Of_View in 0.0 .. 2.0 * Pi
      and then Config.Laser.Max_Range > Config.Laser.Min_Range
      and then Config.Laser.Min_Range >= 0.0 and then Config.Laser.Noise_Std_Dev >= 0.0
      and then Config.Laser.Rate >= 0.0 and then Config.Odometry.Rate >= 0.0
      and then Config.Odometry.Linear_Noise >= 0.0
      and then Config.Odometry.Angular_Noise >= 0.0
      and then Config.GPS.Rate >= 0.0 and then Config.GPS.Std_Dev >= 0.0);
   --  Positive sizes and limits, sane sensor settings.

   type Robot_Id is new Positive;
   --  Robots are numbered from 1 in order of addition; a killed robot keeps
   --  its number.

   type Event_Kind is
     (Wall_Collision, Robot_Collision, Robot_Added, Robot_Killed, Robot_Revived);

   type Event is record
      Kind  : Event_Kind := Wall_Collision;
      Stamp : Real := 0.0;
      Robot : Robot_Id := 1;
      Other : Robot_Id := 1;
      --  The other robot of a Robot_Collision (else = Robot).
      Where : Point;
      --  Where Robot stood.
   end record;

   package Event_Vectors is new Ada.Containers.Vectors (Positive, Event);

   type Simulator is tagged limited private;

   procedure Initialize
     (This           : in out Simulator;
      World          : Worlds.World;
      Seed           : Interfaces.Unsigned_64 := 0;
      Physics_Period : Real := 0.01)
     with Pre => Physics_Period > 0.0;
   --  Empties the simulator and sets its world; the clock restarts at 0.

   function Clock (This : Simulator) return Real;
   --  Simulated seconds since Initialize.

   function World (This : Simulator) return Worlds.World;

   procedure Add_Robot
     (This   : in out Simulator;
      Config : Robot_Config;
      Start  : Pose;
      Id     : out Robot_Id;
      Name   : String := "")
     with Pre => Is_Valid (Config);
   --  A new robot (named "robot_<Id>" by default), alive, at rest at Start.
   --  A start inside a wall or another robot is reported as a collision at
   --  the first step.

   function Robot_Count (This : Simulator) return Natural;

   function Name (This : Simulator; Id : Robot_Id) return String
     with Pre => Natural (Id) <= This.Robot_Count;

   function Is_Alive (This : Simulator; Id : Robot_Id) return Boolean
     with Pre => Natural (Id) <= This.Robot_Count;

   procedure Kill (This : in out Simulator; Id : Robot_Id)
     with Pre => Natural (Id) <= This.Robot_Count;
   --  The robot stops, vanishes from the world (no sensing, no collision)
   --  and ignores commands.

   procedure Revive (This : in out Simulator; Id : Robot_Id)
     with Pre => Natural (Id) <= This.Robot_Count;
   --  The robot comes back where it died, at rest.

   procedure Teleport (This : in out Simulator; Id : Robot_Id; Where : Pose)
     with Pre => Natural (Id) <= This.Robot_Count;
   --  Puts the robot at Where, at rest (its odometry does not notice: a
   --  kidnapped robot, for fault-injection tests).

   procedure Set_Command (This : in out Simulator; Id : Robot_Id; Command : Twist)
     with Pre => Natural (Id) <= This.Robot_Count;
   --  The velocity the robot tries to reach (clamped to its limits).

   procedure Step (This : in out Simulator; Dt : Real)
     with Pre => Dt >= 0.0;
   --  Advances the clock by Dt (rounded to whole physics periods, at least
   --  one when Dt > 0): motion, collisions, sensors due in the interval.

   function Ground_Truth (This : Simulator; Id : Robot_Id) return Pose_Stamped
     with Pre => Natural (Id) <= This.Robot_Count;

   function Is_Colliding (This : Simulator; Id : Robot_Id) return Boolean
     with Pre => Natural (Id) <= This.Robot_Count;
   --  The robot's last move was blocked.

   function Collision_Count (This : Simulator; Id : Robot_Id) return Natural
     with Pre => Natural (Id) <= This.Robot_Count;

   function Odometry_Count (This : Simulator; Id : Robot_Id) return Natural
     with Pre => Natural (Id) <= This.Robot_Count;
   function Latest_Odometry (This : Simulator; Id : Robot_Id) return Odometry
     with Pre => Natural (Id) <= This.Robot_Count;

   function Scan_Count (This : Simulator; Id : Robot_Id) return Natural
     with Pre => Natural (Id) <= This.Robot_Count;
   function Latest_Scan (This : Simulator; Id : Robot_Id) return Laser_Scan
     with Pre => Natural (Id) <= This.Robot_Count;

   function GPS_Count (This : Simulator; Id : Robot_Id) return Natural
     with Pre => Natural (Id) <= This.Robot_Count;
   function Latest_GPS (This : Simulator; Id : Robot_Id) return GPS_Fix
     with Pre => Natural (Id) <= This.Robot_Count;

   procedure Take_Events (This : in out Simulator; Events : out Event_Vectors.Vector);
   --  The events since the last call, oldest first.

   function Cast
     (This      : Simulator;
      From      : Point;
      Angle     : Real;
      Max_Range : Real;
      Ignore    : Robot_Id'Base := 0) return Real;
   --  A noiseless ray against walls and live robots (but Ignore).

private

   type Range_Access is access Range_Array;

   type Robot_State is record
      Name         : Ada.Strings.Unbounded.Unbounded_String;
      Config       : Robot_Config;
      Alive        : Boolean := True;
      Truth        : Pose;
      Velocity     : Twist;
      Command      : Twist;
      Odom         : Pose;
      Odom_Velocity : Twist;
      Odom_Var     : Real := 0.0;
      Yaw_Var      : Real := 0.0;
      Colliding    : Boolean := False;
      Collisions   : Natural := 0;
      Random       : Generators.Generator;
      Next_Odom    : Real := 0.0;
      Next_Scan    : Real := 0.0;
      Next_GPS     : Real := 0.0;
      Odom_Count   : Natural := 0;
      Odom_Stamp   : Real := 0.0;
      Last_Odom    : Odometry;
      Scan_Count   : Natural := 0;
      Scan_Stamp   : Real := 0.0;
      Ranges       : Range_Access;
      GPS_Count    : Natural := 0;
      Last_GPS     : GPS_Fix;
   end record;

   type Robot_Array is array (Robot_Id range <>) of Robot_State;
   type Robot_Array_Access is access Robot_Array;
   --  A plain array (grown by doubling): the hot loops index it directly.

   type Simulator is new Ada.Finalization.Limited_Controlled with record
      The_World : Worlds.World;
      Seed      : Interfaces.Unsigned_64 := 0;
      Period    : Real := 0.01;
      Ticks     : Long_Long_Integer := 0;
      Robots    : Robot_Array_Access;
      Count     : Natural := 0;
      Events    : Event_Vectors.Vector;
   end record;

   overriding procedure Finalize (This : in out Simulator);

end Sancta.Simulation.Simulators;
