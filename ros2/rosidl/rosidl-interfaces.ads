--  The search path of interface folders and the cache of parsed definitions.
--
--  A folder on the path holds one sub-folder per interface package, each with
--  msg/, srv/ and action/ (the layout of a ROS 2 share/ directory). In
--  order: the bundled folder (share/ros2_interfaces of the installation:
--  $RCLADA_ROOT/share/ros2_interfaces when RCLADA_ROOT is set, else <folder
--  of the running program>/../share/ros2_interfaces); the share/ folder of
--  each prefix of AMENT_PREFIX_PATH (a ROS 2 installation or workspace, when
--  one is sourced); the folders of RCLADA_INTERFACE_PATH; the folders given
--  to Add_Folder. All lists are colon-separated and read at every look-up
--  of the path; folders that do not exist are skipped. The first folder
--  holding a package wins. Definitions are cached (and never freed) on
--  first use; every operation is task-safe.
--  Example:
--     Def : constant Message_Access := Message ("geometry_msgs", "Twist");
with ROSIDL.Definitions;

package ROSIDL.Interfaces is

   use ROSIDL.Definitions;

   Root_Variable : constant String := "RCLADA_ROOT";
   --  The installation prefix holding share/ros2_interfaces.

   Path_Variable : constant String := "RCLADA_INTERFACE_PATH";
   --  Extra interface folders, colon-separated.

   Ament_Variable : constant String := "AMENT_PREFIX_PATH";
   --  ROS 2 install prefixes, colon-separated: <prefix>/share is searched.

   procedure Add_Folder (Folder : String);
   --  Appends a folder to the search path. Raises Definition_Error when the
   --  folder does not exist.

   procedure Remove_Folder (Folder : String);
   --  Removes a folder added by Add_Folder (nothing when it was not added).
   --  Definitions already loaded from it stay cached.

   function Search_Path return String_Vectors.Vector;
   --  The folders searched, in order (bundled first).

   function Message (Package_Name, Name : String) return Message_Access;
   --  The definition of <Package_Name>/msg/<Name>, parsed on first use with
   --  everything it nests. Raises Unknown_Type when it is not on the path
   --  and Definition_Error when the file (or a nested one) is malformed.

   function Service (Package_Name, Name : String) return Service_Access;
   --  <Package_Name>/srv/<Name>, as Message.

   function Action (Package_Name, Name : String) return Action_Access;
   --  <Package_Name>/action/<Name>, as Message.

   function Message (Full_Name : String) return Message_Access;
   --  "pkg/msg/Name" or "pkg/Name".

   function Packages return String_Vectors.Vector;
   --  Every interface package found on the path, sorted.

   function Messages (Package_Name : String) return String_Vectors.Vector;
   function Services (Package_Name : String) return String_Vectors.Vector;
   function Actions (Package_Name : String) return String_Vectors.Vector;
   --  The type names a package defines, sorted. Raise Unknown_Type when the
   --  package is not on the path.

   function Message_By_DDS_Name (DDS_Name : String) return Message_Access;
   --  The definition whose DDS_Type_Name is DDS_Name:
   --  "std_msgs::msg::dds_::String_", "example_interfaces::srv::dds_::
   --  AddTwoInts_Request_", "example_interfaces::action::dds_::
   --  Fibonacci_SendGoal_Request_". Raises Unknown_Type otherwise.

end ROSIDL.Interfaces;
