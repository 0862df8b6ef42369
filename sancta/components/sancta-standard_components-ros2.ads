--  The ROS 2 bridges: components that connect database keys to ROS 2
--  topics of any message type (through RCL's raw publish/subscribe and the
--  dynamic message layer ROSIDL.Dynamic / ROSIDL.CDR). This is how robots,
--  simulators and other ROS 2 software plug into a SANCTA node.
--
--     <component name="ros2_subscriber" topic="/odom" msg_type="nav_msgs/msg/Odometry">
--       <provides data="message" as="odometric_pose" type="types.pose"/>
--     </component>
--     <component name="ros2_publisher" topic="/sancta/pose"
--                msg_type="geometry_msgs/msg/Pose2D">
--       <requires data="message" as="corrected_pose"/>
--     </component>
--
--  Options of both: topic (required; relative names are under "/"),
--  msg_type (required; "pkg/msg/Type" or "pkg/Type", checked against the
--  interface path when the configuration is loaded), reliability
--  (reliable | best_effort, default reliable), depth (default 10).
--  ros2_subscriber also: convert (auto | message, default auto).
--  ros2_publisher also: frame_id (header.frame_id of stamped messages).
--
--  Conversions ("auto"; anything else travels as a Message_Value):
--    geometry_msgs/msg/Pose2D, Pose, PoseStamped, nav_msgs/msg/Odometry
--       <-> types.pose (x, y, yaw; quaternions about z);
--    std_msgs/msg/Float32, Float64 <-> types.real (publisher: also
--       types.integer);
--    std_msgs/msg/Int8 .. Int64, UInt8 .. UInt64 <-> types.integer;
--    std_msgs/msg/Bool <-> types.boolean;
--    std_msgs/msg/String <-> types.string (publisher: any value's Image).
--  A ros2_publisher also accepts a Message_Value of its own msg_type.
--
--  Each bridge owns one RCL node named "sancta_<agent>_<component>_<rank>".
--  A subscriber spins its node in its own task (asynchronous component,
--  its death reported by Sancta.Runtime.Tasks) and stores each message in
--  that task (so the key's listeners run there); a publisher publishes in
--  the task that stored its input. The ROS 2 context's Ctrl-C handling
--  (RCL.Contexts) also requests the SANCTA shutdown.
with ROSIDL.Dynamic;

package Sancta.Standard_Components.ROS2 is

   type Message_Value is new Runtime.Values.Value with record
      Message : ROSIDL.Dynamic.Message;
   end record;
   --  A ROS 2 message of any type; its configuration type name is
   --  "ros2:" and the message's full name ("ros2:sensor_msgs/msg/LaserScan").

   overriding function Image (This : Message_Value) return String;
   --  The message as "ros2 topic echo" prints it, one line ("a: 1, b: x").

   overriding function Type_Name (This : Message_Value) return String;

   function To_Value
     (Msg : ROSIDL.Dynamic.Message; Convert : Boolean := True) return Runtime.Values.Value'Class;
   --  The SANCTA value of a message (see the conversions above); a
   --  Message_Value when Convert is False or no conversion applies.

   function To_Message
     (Item     : Runtime.Values.Value'Class;
      Type_Of  : ROSIDL.Dynamic.Message;
      Frame_Id : String := "") return ROSIDL.Dynamic.Message;
   --  A message of the type of Type_Of (an initialised message) holding
   --  Item. Raises Runtime.Type_Error naming both types when Item cannot be
   --  converted.

end Sancta.Standard_Components.ROS2;
