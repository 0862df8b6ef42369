--  The project's own ROS 2 interfaces (share/interfaces, package sancta_msgs)
--  on the ROSIDL search path.
package Sancta.Team.Interfaces is

   procedure Ensure;
   --  Adds <installation>/share/interfaces (the sibling of the bundled
   --  share/ros2_interfaces) to the search path once. Raises Program_Error
   --  naming the folder when it does not exist.

end Sancta.Team.Interfaces;
