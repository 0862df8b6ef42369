--  SANCTA's own ROS 2 interfaces on the search path of the ROS 2 library:
--  the sancta_msgs package (Installation.Share_File ("interfaces")) and the
--  folders of $SANCTA_INTERFACE_PATH (colon-separated). The ROS 2 library
--  knows nothing of SANCTA: every SANCTA program calls Ensure before it
--  looks up a type.
--
--     Sancta.Team.Interface_Paths.Ensure;
--     Support := ROSIDL.Typesupport.Get_Message_Support ("sancta_msgs", "Envelope");
package Sancta.Team.Interface_Paths is

   procedure Ensure;
   --  Adds the folders (once per process) with ROSIDL.Interfaces.Add_Folder:
   --  share/interfaces unless a folder of the path already holds
   --  sancta_msgs, then each existing folder of $SANCTA_INTERFACE_PATH.
   --  Raises Program_Error naming the folder when share/interfaces is
   --  needed and missing.

end Sancta.Team.Interface_Paths;
