--  Where SANCTA's bundled data lives: the share/ folder of the installation
--  (worlds, configurations, missions, the sancta_msgs interfaces). It is
--  $SANCTA_ROOT/share when SANCTA_ROOT is set and not empty, else
--  <folder of the running program>/../share (bin/../share in the repository
--  and in an installation), else share/ of the current directory.
--
--     Installation.Share_File ("worlds/office.yaml")
--       --  "/home/me/sancta/bin/../share/worlds/office.yaml"
package Sancta.Installation is

   Root_Variable : constant String := "SANCTA_ROOT";

   Interface_Path_Variable : constant String := "SANCTA_INTERFACE_PATH";
   --  Extra ROS 2 interface folders, colon-separated: read by
   --  Sancta.Team.Interface_Paths, which hands them to the ROS 2 library.

   function Share_Folder return String;
   --  Without a trailing "/".

   function Share_File (Relative : String) return String is
     (Share_Folder & "/" & Relative);

end Sancta.Installation;
