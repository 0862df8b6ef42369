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
--     C : Adding.Client;
--     C.Init (Node, "add_two_ints");
--     C.Call ((A => 2, B => 3), Sum_Response, Timeout => 1.0);
--     Sum := Adding.Call (Node, "add_two_ints", (A => 2, B => 3)).Sum;  --  one-off
--
--  On the wire these are the services and clients of RCL.Services and
--  RCL.Clients (rmw_cyclonedds conventions: request header, pairing by
--  "clientid"/"serviceid", a reply only once the client's reply reader is
--  matched), so typed and dynamic peers talk to each other and to ROS 2.
--  The generated codec writes a request or reply (header included)
--  straight into the DDS sample and reads it straight out of the taken
--  sample: no dynamic message, no intermediate buffer, and the type need
--  not be on the interface search path. Steady state with bounded types
--  (no unbounded string or sequence in request and response): a Client's
--  Call procedure and the server's answering allocate nothing on the Ada
--  heap (tests/src/alloc/typed_alloc_check).
with Ada.Finalization;
with ROSIDL.Static.Service_Support;
with RCL.Clients;

private with RCL.Client_Endpoints;
private with RCL.Pending_Calls.Asynchronous;
private with ROSIDL.Mutexes;

generic
   with package Handling is new ROSIDL.Static.Service_Support (<>);
package RCL.Services.Typed is

   subtype Request is Handling.Request_Message;
   subtype Response is Handling.Response_Message;

   Forever : constant Duration := RCL.Clients.Forever;

   -------------
   -- Clients --
   -------------

   type Client is new Ada.Finalization.Limited_Controlled with private;
   --  A client of one service. Calls from several tasks are served one
   --  after the other.

   procedure Init
     (This : in out Client;
      Node : RCL.Nodes.Node'Class;
      Name : String;
      QoS  : RCL.QoS.Profile := RCL.QoS.Services_Default)
     with Pre => not Is_Open (This);
   --  Name is expanded like a topic name (relative to the node's
   --  namespace); RCL.Names.Name_Error for a bad one.

   function Is_Open (This : Client) return Boolean;

   function Service_Name (This : Client) return String
     with Pre => Is_Open (This);
   --  The fully qualified service name.

   function Service_Available (This : Client) return Boolean
     with Pre => Is_Open (This);
   --  A server's request reader and reply writer (same serviceid) matched.

   procedure Wait_For_Service (This : Client; Timeout : Duration := Forever)
     with Pre => Is_Open (This);
   --  RCL_Timeout when the service is not available within Timeout.

   procedure Call
     (This    : in out Client;
      Req     : Request;
      Resp    : in out Response;
      Timeout : Duration := Forever)
     with Pre => Is_Open (This);
   --  Waits for the service (the first time, and after a timeout), sends
   --  Req and decodes the response into Resp, reusing its storage; all
   --  within Timeout, else RCL_Timeout naming the service. ROS_Exception
   --  when the context shuts down (Ctrl-C) meanwhile. Malformed replies
   --  are logged and skipped; replies to other clients or to earlier calls
   --  that timed out are dropped.

   function Call
     (This    : in out Client;
      Req     : Request;
      Timeout : Duration := Forever) return Response
     with Pre => Is_Open (This);
   --  The same, returning a fresh response.

   type Response_Callback is access procedure (Resp : Response);
   --  What Call_Async runs with the response.

   procedure Call_Async
     (This     : in out Client;
      Req      : Request;
      Callback : not null Response_Callback;
      Timeout  : Duration := 60.0)
     with Pre => Is_Open (This);
   --  Sends Req at once (without waiting for the service: call
   --  Wait_For_Service first, a request sent before a server matched is
   --  lost) and returns. Callback runs with the decoded response, as for
   --  RCL.Clients.Call_Async, in a task of the client that lives while
   --  asynchronous calls are pending (or in a synchronous Call of the same
   --  client that reads the reply), NOT in the node's executor: state
   --  shared with the node's callbacks needs a protected object. A
   --  response not come within Timeout is forgotten (a warning is logged);
   --  malformed replies are logged and skipped; an exception in Callback
   --  is logged. The calls still pending when the context shuts down or
   --  the client is finalized are dropped (a warning is logged). Callback
   --  must not make a synchronous Call of this client (ROS_Exception: it
   --  would wait for itself). The same machinery as RCL.Clients's
   --  (RCL.Pending_Calls.Asynchronous). Allocates (the table of pending
   --  calls, the pumping task): not for the allocation-free path. The
   --  pumping task depends on the scope of this instance: leaving that
   --  scope waits until calls still pending there are answered or time
   --  out (declare the client in an inner scope to drop them at once).
   --  Example:
   --     package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
   --     package Adding is new RCL.Services.Typed (Add.Handling);
   --     Last_Sum : ROSIDL.Int64 := 0 with Atomic;  --  read by other tasks
   --
   --     procedure On_Sum (Resp : Add.Response.Message) is
   --     begin
   --        Last_Sum := Resp.Sum;
   --     end On_Sum;
   --     C : Adding.Client;
   --     C.Init (Node, "add_two_ints");
   --     C.Wait_For_Service (Timeout => 5.0);
   --     C.Call_Async ((A => 2, B => 3), On_Sum'Access, Timeout => 1.0);

   function Pending_Async (This : Client) return Natural
     with Pre => Is_Open (This);
   --  Asynchronous calls still waiting for their response.

   overriding procedure Finalize (This : in out Client);

   function Call
     (Node    : RCL.Nodes.Node'Class;
      Name    : String;
      Req     : Request;
      Timeout : Duration := Forever) return Response;
   --  As Node.Client_Call: the call of a Client made on first use for
   --  (Node, Name) and kept by this instance (convenient, not
   --  allocation-free: the lookup builds the key).

   ------------
   -- Server --
   ------------

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
      --  Offers service Name, answered by Callback while the node spins.
      --  Resp starts as a default response for every request. An
      --  exception in Callback is logged with the service name and no
      --  reply is sent (the client times out), as Node.Serve does; a
      --  malformed request is logged and dropped. The instance must live
      --  as long as the node.
   end Server;

private

   subtype Call_Lock is ROSIDL.Mutexes.Mutex;
   --  One call at a time per client; also held while the pumping task
   --  reads replies (so each reply is read by one task).

   type Client_Ref is access all Client;

   procedure Read_Replies (This : Client_Ref);
   --  The pump's reading (RCL.Pending_Calls.Asynchronous), with the lock.
   function Service_Name (This : Client_Ref) return String;

   package Async_Calls is new RCL.Pending_Calls.Asynchronous
     (Response, Response_Callback, Client_Ref, Read_Replies, Service_Name);

   type Client is new Ada.Finalization.Limited_Controlled with record
      Ends      : RCL.Client_Endpoints.Endpoints;
      Available : Boolean := False;
      --  The service was available at the last call (not checked again
      --  until a call times out).
      Lock      : Call_Lock;
      Asyncs    : Async_Calls.Calls;
   end record;

end RCL.Services.Typed;
