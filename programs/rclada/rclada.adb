--  rclada: the ROS 2 graph from the command line (nodes, topics, services,
--  parameters, interfaces), modelled on the "ros2" command; see
--  Rclada_Commands.Usage or "rclada --help".
with Ada.Command_Line;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Text_IO;
with RCL;
with RCL.Contexts;
with RCL.Names;
with ROSIDL;
with Rclada_Commands;

procedure Rclada is
   use Ada.Text_IO;
   use Rclada_Commands;
   package CL renames Ada.Command_Line;

   Args : Arguments;
   Verb : constant String := (if CL.Argument_Count >= 1 then CL.Argument (1) else "");
begin
   for I in 2 .. CL.Argument_Count loop
      Args.Append (CL.Argument (I));
   end loop;
   if Verb = "" or else Verb = "-h" or else Verb = "--help" then
      Put_Line (Usage (""));
      if Verb = "" then
         CL.Set_Exit_Status (2);
      end if;
      return;
   end if;
   if (for some A of Args => A = "-h" or else A = "--help") then
      Put_Line (Usage (Verb));
      return;
   end if;
   if Verb = "node" then
      Node_Command (Args);
   elsif Verb = "topic" then
      Topic_Command (Args);
   elsif Verb = "service" then
      Service_Command (Args);
   elsif Verb = "param" then
      Param_Command (Args);
   elsif Verb = "interface" then
      Interface_Command (Args);
   elsif Verb = "action" then
      Action_Command (Args);
   elsif Verb = "lifecycle" then
      Lifecycle_Command (Args);
   elsif Verb = "security" then
      Security_Command (Args);
   elsif Verb = "bag" then
      Bag_Command (Args);
   else
      raise Usage_Error with "unknown verb '" & Verb & "'";
   end if;
   RCL.Contexts.Shutdown;
exception
   when E : Usage_Error =>
      Put_Line (Standard_Error, "rclada: " & Ada.Exceptions.Exception_Message (E));
      Put_Line (Standard_Error, Usage ((if Verb in "node" | "topic" | "service" | "param"
                                          | "interface" | "action"
                                          | "lifecycle" | "security" | "bag" then Verb else "")));
      CL.Set_Exit_Status (2);
   when E : Command_Error | RCL.ROS_Exception | RCL.RCL_Timeout | ROSIDL.Unknown_Type
      | ROSIDL.Definition_Error | RCL.Names.Name_Error =>
      Put_Line (Standard_Error, "rclada: " & Ada.Exceptions.Exception_Message (E));
      CL.Set_Exit_Status (1);
   when Ada.IO_Exceptions.Device_Error =>
      null;  --  Our output was closed ("rclada topic echo /x | head"): done.
   when E : others =>
      --  Last resort: a bug, reported in one line instead of a traceback.
      Put_Line (Standard_Error, "rclada: internal error: "
                & Ada.Exceptions.Exception_Name (E) & ": "
                & Ada.Exceptions.Exception_Message (E));
      CL.Set_Exit_Status (70);
end Rclada;
