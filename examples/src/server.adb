--  The RCLAda slides' Server example: offers example_interfaces/AddTwoInts
--  as "add_two_ints" and answers until Ctrl-C (or SIGTERM).
--     server [SERVICE_NAME]
with Ada.Command_Line;
with Ada.Exceptions;
with Example_Support; use Example_Support;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Logging;
with RCL.Names;
with RCL.Nodes;

procedure Server is

   use RCL;

   Support : constant ROSIDL.Typesupport.Service_Support :=
     ROSIDL.Typesupport.Get_Service_Support ("example_interfaces", "AddTwoInts");

   Node : Nodes.Node := Nodes.Init ("add_two_ints_server");

   procedure Adder
     (Node : in out Nodes.Node'Class;
      Req  : ROSIDL.Dynamic.Message;
      Resp : in out ROSIDL.Dynamic.Message)
   is
      pragma Unreferenced (Node);
      use type ROSIDL.Int64;
      A : constant ROSIDL.Int64 := Req ("a").As_Int64;
      B : constant ROSIDL.Int64 := Req ("b").As_Int64;
   begin
      if (B > 0 and then A > ROSIDL.Int64'Last - B)
        or else (B < 0 and then A < ROSIDL.Int64'First - B)
      then
         --  No answer rather than a wrong one; the executor logs this message.
         raise Constraint_Error with "a + b overflows int64 (a:" & A'Image & " b:" & B'Image
           & "): no answer";
      end if;
      Resp ("sum").As_Int64 := A + B;
      Logging.Info ("Incoming request a:" & A'Image & " b:" & B'Image);
   end Adder;

   Name : constant String := Argument (1, "add_two_ints");

begin
   Node.Serve (Support, Name, Adder'Access);
   Logging.Info ("Ready to add two ints on " & Node.Expand (Name));
   Node.Spin (During => Nodes.Forever);
exception
   when E : RCL.Names.Name_Error =>
      Logging.Error ("bad service name: " & Ada.Exceptions.Exception_Message (E));
      Ada.Command_Line.Set_Exit_Status (2);
end Server;
