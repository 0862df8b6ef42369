--  The verbs of the "rclada" command (see rclada.adb): the ROS 2 graph from
--  the command line, modelled on the "ros2" command. Each procedure takes
--  the arguments after its verb ("topic list -t" -> ["list", "-t"]).
with Ada.Containers.Indefinite_Vectors;

package Rclada_Commands is

   package Argument_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);
   subtype Arguments is Argument_Vectors.Vector;

   Usage_Error : exception;
   --  Bad command line; the message says what, and the verb's usage is
   --  printed after it (exit status 2).

   Command_Error : exception;
   --  The command could not be done (unknown type, timeout...): exit 1.

   procedure Node_Command (Args : Arguments);
   procedure Topic_Command (Args : Arguments);
   procedure Service_Command (Args : Arguments);
   procedure Param_Command (Args : Arguments);
   procedure Interface_Command (Args : Arguments);
   procedure Action_Command (Args : Arguments);
   procedure Lifecycle_Command (Args : Arguments);
   procedure Security_Command (Args : Arguments);
   procedure Bag_Command (Args : Arguments);

   function Usage (Verb : String) return String;
   --  The help text of a verb ("" for the command itself).

   function Resolve_Message_Type (Name : String) return String;
   --  "std_msgs/msg/String" or "std_msgs/String" -> "std_msgs/msg/String";
   --  Command_Error naming up to three close known types when unknown.

end Rclada_Commands;
