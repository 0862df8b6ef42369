--  The slides' Client with generated types: asks "add_two_ints" (or the
--  name given) for A + B and prints the sum.
--     typed_client A B [TIMEOUT [SERVICE_NAME]]
with Example_Support; use Example_Support;
with RCL.Logging;
with RCL.Nodes;
with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;

procedure Typed_Client is

   use RCL;

   package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
   package Adding is new RCL.Services.Typed (Add.Handling);

   Node    : constant Nodes.Node := Nodes.Init ("add_two_ints_client");
   Request : constant Add.Request.Message :=
     (A => ROSIDL.Int64'Value (Argument (1, "2")),
      B => ROSIDL.Int64'Value (Argument (2, "3")));
   Answer  : constant Add.Response.Message :=
     Adding.Call (Node, Argument (4, "add_two_ints"), Request,
                  Timeout => Duration'Value (Argument (3, "10.0")));
begin
   Logging.Info ("Got answer:" & Answer.Sum'Image);
end Typed_Client;
