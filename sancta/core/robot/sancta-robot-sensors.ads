--  Sensor and command records of a differential-drive robot. Each maps one
--  to one onto a ROS 2 message (the frames are named by the wrapper):
--     Twist        geometry_msgs/Twist (linear.x, angular.z; others zero)
--     Odometry     nav_msgs/Odometry (pose in "odom", twist in "base_link")
--     Laser_Scan   sensor_msgs/LaserScan
--     Pose_Stamped geometry_msgs/PoseStamped (ground truth, frame "map")
--     GPS_Fix      an absolute position with its standard deviation
--  Stamps are seconds of the simulation (or ROS) clock.
--
--     Scan : Laser_Scan (360);
--     for I in Scan.Ranges'Range loop
--        if Is_Valid (Scan, I) then Use (Beam_Point (Scan, I)); end if;
--     end loop;
with Sancta.Geometry; use Sancta.Geometry;

package Sancta.Robot.Sensors
  with Pure
is

   type Twist is record
      Linear_X  : Real := 0.0;
      --  Forward speed, m/s.
      Angular_Z : Real := 0.0;
      --  Turn rate, rad/s, counter-clockwise.
   end record;

   type Odometry is record
      Stamp         : Real := 0.0;
      Pose          : Geometry.Pose;
      --  Pose in the odometry frame (starts at the robot's start pose).
      Velocity      : Twist;
      --  Measured velocity in the robot frame.
      Pose_Variance : Real := 0.0;
      --  Diagonal of the position covariance (m^2), same for x and y.
      Yaw_Variance  : Real := 0.0;
   end record;

   type Range_Array is array (Positive range <>) of Real;

   type Laser_Scan (Beams : Natural) is record
      Stamp           : Real := 0.0;
      Angle_Min       : Real := 0.0;
      --  Angle of beam 1 in the robot frame.
      Angle_Max       : Real := 0.0;
      --  Angle of the last beam.
      Angle_Increment : Real := 0.0;
      Time_Increment  : Real := 0.0;
      Scan_Time       : Real := 0.0;
      Range_Min       : Real := 0.0;
      Range_Max       : Real := 0.0;
      Ranges          : Range_Array (1 .. Beams) := [others => 0.0];
      --  A beam that hit nothing reads Range_Max (not valid).
   end record;

   function Beam_Angle (Scan : Laser_Scan; Beam : Positive) return Real is
     (Scan.Angle_Min + Real (Beam - 1) * Scan.Angle_Increment)
     with Pre => Beam <= Scan.Beams;

   function Is_Valid (Scan : Laser_Scan; Beam : Positive) return Boolean is
     (Scan.Ranges (Beam) >= Scan.Range_Min
        and then Scan.Ranges (Beam) < Scan.Range_Max)
     with Pre => Beam <= Scan.Beams;
   --  The beam hit something within the sensor's range.

   function Beam_Point (Scan : Laser_Scan; Beam : Positive) return Point
     with Pre => Beam <= Scan.Beams;
   --  Where the beam ended, in the robot frame.

   type Pose_Stamped is record
      Stamp : Real := 0.0;
      Pose  : Geometry.Pose;
   end record;

   type GPS_Fix is record
      Stamp    : Real := 0.0;
      Position : Point;
      Std_Dev  : Real := 0.0;
      --  Standard deviation of each coordinate, m.
   end record;

end Sancta.Robot.Sensors;
