--  The project's own ROS 2 interfaces (share/interfaces, package sancta_msgs)
--  on the ROSIDL search path.
package Sancta.Team.Interfaces is

   procedure Ensure;
   --  Makes sure sancta_msgs is found: when no folder of the search path
   --  holds it (ROSIDL.Interfaces searches share/interfaces itself since
   --  the simros merge), adds <installation>/share/interfaces, the sibling
   --  of the bundled share/ros2_interfaces. Raises Program_Error naming the
   --  folder when it does not exist.

end Sancta.Team.Interfaces;
