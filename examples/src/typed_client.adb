--  The slides' Client with generated types: asks "add_two_ints" (or the
--  name given) for A + B and prints the sum.
--     typed_client A B [TIMEOUT [SERVICE_NAME]]
with Ada.Command_Line;
with RCL.Logging;
with RCL.Nodes;
with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;

procedure Typed_Client is

   use RCL;
   package CL renames Ada.Command_Line;

   package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
   package Adding is new RCL.Services.Typed (Add.Handling);

   function Arg (N : Positive; Default : String) return String is
     (if CL.Argument_Count >= N then CL.Argument (N) else Default);

   Node    : constant Nodes.Node := Nodes.Init ("add_two_ints_client");
   Request : constant Add.Request.Message :=
     (A => ROSIDL.Int64'Value (Arg (1, "2")), B => ROSIDL.Int64'Value (Arg (2, "3")));
   Answer  : constant Add.Response.Message :=
     Adding.Call (Node, Arg (4, "add_two_ints"), Request,
                  Timeout => Duration'Value (Arg (3, "10.0")));
begin
   Logging.Info ("Got answer:" & Answer.Sum'Image);
end Typed_Client;
