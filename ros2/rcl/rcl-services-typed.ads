--  Typed services and clients: requests and responses are the generated
--  records of a service (ROSIDL.Static.<Pkg>.Services.<Srv>.Request /
--  .Response). Instantiate with the service's Handling package:
--  Example:
--     package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
--     package Adding is new RCL.Services.Typed (Add.Handling);
--
--     procedure Adder (Node : in out Nodes.Node'Class;
--                      Req  : Add.Request.Message;
--                      Resp : in out Add.Response.Message) is
--     begin
--        Resp.Sum := Req.A + Req.B;
--     end Adder;
--     package Adder_Server is new Adding.Server (Adder);
--     Adder_Server.Serve (Node, "add_two_ints");
--
--     Sum := Adding.Call (Node, "add_two_ints", (A => 2, B => 3), Timeout => 1.0).Sum;
--
--  On the wire these are the services and clients of RCL.Services and
--  RCL.Clients (rmw_cyclonedds conventions, pairing, timeouts, errors),
--  which run the dynamic path: a typed request or response is converted
--  through its CDR encoding (the service type must be on the interface
--  search path, as the bundled ones are). Not allocation-free.
with ROSIDL.Static.Service_Support;
with RCL.Clients;

generic
   with package Handling is new ROSIDL.Static.Service_Support (<>);
package RCL.Services.Typed is

   subtype Request is Handling.Request_Message;
   subtype Response is Handling.Response_Message;

   function Call
     (Node    : RCL.Nodes.Node'Class;
      Name    : String;
      Req     : Request;
      Timeout : Duration := RCL.Clients.Forever) return Response;
   --  As Node.Client_Call: waits for the service, then for the response;
   --  RCL_Timeout when Timeout passes.

   generic
      with procedure Callback
        (Node : in out RCL.Nodes.Node'Class;
         Req  : Request;
         Resp : in out Response);
   package Server is
      procedure Serve
        (Node : in out RCL.Nodes.Node'Class;
         Name : String;
         QoS  : RCL.QoS.Profile := RCL.QoS.Services_Default);
      --  Offers service Name, answered by Callback while the node spins
      --  (an exception in Callback: logged, no reply, as Node.Serve). The
      --  instance must live as long as the node.
   end Server;

end RCL.Services.Typed;
