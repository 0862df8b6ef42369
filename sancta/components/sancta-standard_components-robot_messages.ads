--  Conversions between ROS 2 messages (dynamic messages, as the ROS 2
--  bridge components carry them in Message_Value) and the records of the
--  robot algorithms (Sancta.Robot.Sensors), plus the goal-list text of the
--  executor component. Used by the robot components (Navigation,
--  Localization); pure functions, tested without processes.
--
--     Scan : constant Laser_Scan := To_Scan (Message_Value (Item).Message);
--     This.Output ("cmd_vel", Message_Value'(Message => Twist_Message (Cmd)));
with ROSIDL.Dynamic;
with Sancta.Geometry;
with Sancta.Robot.Goal_Sequencers;
with Sancta.Robot.Mappers;
with Sancta.Robot.Grids;
with Sancta.Robot.Sensors;

package Sancta.Standard_Components.Robot_Messages is

   Scan_Type  : constant String := "ros2:sensor_msgs/msg/LaserScan";
   Twist_Type : constant String := "ros2:geometry_msgs/msg/Twist";
   GPS_Type   : constant String := "ros2:geometry_msgs/msg/PoseWithCovarianceStamped";
   Map_Type   : constant String := "ros2:nav_msgs/msg/OccupancyGrid";
   --  Configuration type names of the messages the robot components use.

   function Stamp_Of (Header : ROSIDL.Dynamic.Field_Ref) return Geometry.Real;
   --  header.stamp in seconds.

   function To_Scan (Msg : ROSIDL.Dynamic.Message) return Robot.Sensors.Laser_Scan;
   --  A sensor_msgs/LaserScan (Field_Error for another type). NaN and
   --  infinite ranges read as range_max (no hit).

   function Scan_Message
     (Scan : Robot.Sensors.Laser_Scan; Frame_Id : String) return ROSIDL.Dynamic.Message;
   --  The sensor_msgs/LaserScan of Scan (no intensities).

   function Fix_Message (Fix : Robot.Sensors.GPS_Fix) return ROSIDL.Dynamic.Message;
   --  A geometry_msgs/PoseWithCovarianceStamped in frame "map": the
   --  position, variances Std_Dev^2 for x and y, 1e6 for the (unobserved)
   --  heading.

   procedure Set_Time (Stamp : ROSIDL.Dynamic.Field_Ref; T : Geometry.Real);
   --  A builtin_interfaces/Time of T seconds (T >= 0).

   procedure Set_Pose (Target : ROSIDL.Dynamic.Field_Ref; P : Geometry.Pose);
   --  A geometry_msgs/Pose of a planar pose (quaternion about z).

   function Twist_Message (Command : Robot.Sensors.Twist) return ROSIDL.Dynamic.Message;
   --  A geometry_msgs/Twist with linear.x and angular.z set.

   function To_Twist (Msg : ROSIDL.Dynamic.Message) return Robot.Sensors.Twist;

   function To_Fix (Msg : ROSIDL.Dynamic.Message) return Robot.Sensors.GPS_Fix;
   --  A geometry_msgs/PoseWithCovarianceStamped: the position, and the
   --  standard deviation sqrt of the mean of the x and y variances.

   function Grid_Message
     (Frame    : Robot.Grids.Frame;
      Data     : Robot.Mappers.Cell_Value_Array;
      Stamp    : Geometry.Real;
      Frame_Id : String) return ROSIDL.Dynamic.Message
     with Pre => Data'Length = Frame.Width * Frame.Height;
   --  A nav_msgs/OccupancyGrid of the mapper's cells (origin at the lower
   --  left corner of cell (0, 0), no rotation).

   Goal_Error : exception;
   --  Message: "goal N (column C): what was expected, what was found".

   function Parse_Goals (Text : String) return Robot.Goal_Sequencers.Point_Array;
   --  "x1,y1; x2,y2; ..." (blanks allowed; "" gives no goal).

   function Goals_Problem (Text : String) return String;
   --  "" when Parse_Goals accepts Text, else its Goal_Error message.

   function Goals_Image (Goals : Robot.Goal_Sequencers.Point_Array) return String;
   --  The inverse of Parse_Goals.

end Sancta.Standard_Components.Robot_Messages;
