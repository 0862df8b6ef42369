--  The search path of interface folders and the cache of parsed definitions.
--
--  A folder on the path holds one sub-folder per interface package, each with
--  msg/, srv/ and action/ (the layout of a ROS 2 share/ directory). The
--  bundled folder (share/ros2_interfaces of the installation) comes first;
--  folders named in the environment variable SANCTA_INTERFACE_PATH
--  (colon-separated) and through Add_Folder follow. The first folder holding
--  a package wins.
--
--     Def : constant Message_Access := Message ("geometry_msgs", "Twist");
with ROSIDL.Definitions;

package ROSIDL.Interfaces is

   use ROSIDL.Definitions;

   Path_Variable : constant String := "SANCTA_INTERFACE_PATH";

   procedure Add_Folder (Folder : String);
   --  Appends a folder to the search path. Raises Definition_Error when the
   --  folder does not exist.

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
   --  The type names a package defines, sorted.

end ROSIDL.Interfaces;
