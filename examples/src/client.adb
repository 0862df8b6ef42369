--  The RCLAda slides' Client example (synchronous version): calls
--  "add_two_ints" (example_interfaces/AddTwoInts) and prints the sum.
--     client [A B [TIMEOUT [SERVICE_NAME]]]    (defaults: 2 3 10 add_two_ints)
--  Exit status 1 when the service does not answer within TIMEOUT seconds.
with Ada.Command_Line;
with Ada.Exceptions;
with Example_Support; use Example_Support;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Logging;
with RCL.Names;
with RCL.Nodes;

procedure Client is

   use RCL;
   package CL renames Ada.Command_Line;

   Support : constant ROSIDL.Typesupport.Service_Support :=
     ROSIDL.Typesupport.Get_Service_Support ("example_interfaces", "AddTwoInts");

   Node    : constant Nodes.Node := Nodes.Init ("add_two_ints_client");
   Request : constant ROSIDL.Dynamic.Message :=
     ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support (Support));
   Timeout : Duration;

begin
   Request ("a").As_Int64 := ROSIDL.Int64'Value (Argument (1, "2"));
   Request ("b").As_Int64 := ROSIDL.Int64'Value (Argument (2, "3"));
   Timeout := Duration'Value (Argument (3, "10"));
   if Timeout < 0.0 then
      raise Constraint_Error;  --  A usage error.
   end if;
   declare
      Response : constant ROSIDL.Dynamic.Message :=
        Node.Client_Call (Support, Argument (4, "add_two_ints"), Request, Timeout);
   begin
      Logging.Info ("Got answer:" & ROSIDL.Int64'Image (Response ("sum").As_Int64));
   end;
exception
   when E : RCL.RCL_Timeout =>
      Logging.Error ("RCL_Timeout: " & Ada.Exceptions.Exception_Message (E));
      CL.Set_Exit_Status (1);
   when E : RCL.Names.Name_Error =>
      Logging.Error ("bad service name: " & Ada.Exceptions.Exception_Message (E));
      CL.Set_Exit_Status (2);
   when Constraint_Error =>
      Logging.Error ("usage: client [A B [TIMEOUT [SERVICE_NAME]]] (integers, seconds)");
      CL.Set_Exit_Status (2);
end Client;
