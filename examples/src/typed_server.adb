--  The slides' Server with generated types: offers
--  example_interfaces/srv/AddTwoInts as "add_two_ints" (or the name given)
--  and answers until Ctrl-C.
--     typed_server [SERVICE_NAME]
with Example_Support; use Example_Support;
with RCL.Logging;
with RCL.Nodes;
with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;

procedure Typed_Server is

   use RCL;
   use type ROSIDL.Int64;

   package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
   package Adding is new RCL.Services.Typed (Add.Handling);

   procedure Adder
     (Node : in out Nodes.Node'Class;
      Req  : Add.Request.Message;
      Resp : in out Add.Response.Message)
   is
      pragma Unreferenced (Node);
   begin
      if (Req.B > 0 and then Req.A > ROSIDL.Int64'Last - Req.B)
        or else (Req.B < 0 and then Req.A < ROSIDL.Int64'First - Req.B)
      then
         raise Constraint_Error with "a + b overflows int64: no answer";
      end if;
      Resp.Sum := Req.A + Req.B;
      Logging.Info ("Incoming request a:" & Req.A'Image & " b:" & Req.B'Image);
   end Adder;

   package Adder_Server is new Adding.Server (Adder);

   Node : Nodes.Node := Nodes.Init ("add_two_ints_server");
   Name : constant String := Argument (1, "add_two_ints");

begin
   Adder_Server.Serve (Node, Name);
   Logging.Info ("Ready to add two ints on " & Node.Expand (Name));
   Node.Spin (During => Nodes.Forever);
end Typed_Server;
