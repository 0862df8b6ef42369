--  Small helpers for ROS 2 programs (as in RCLAda).
package RCL.Utils is

   function Command_Name return String;
   --  The program's simple name, usable as a node name: "talker" for
   --  "/usr/bin/talker"; characters invalid in node names become '_'.

end RCL.Utils;
