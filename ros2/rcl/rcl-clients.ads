--  Clients: calls of a service, with the conventions of rmw_cyclonedds_cpp
--  (see RCL.Services): requests on "rq/<name>Request" from a writer whose
--  USER_DATA is "clientid=<id>;", replies on "rr/<name>Reply" read by a
--  reader with the same USER_DATA; the request header carries the request
--  writer's instance handle and a process-wide sequence number, and only
--  replies with this client's handle are kept.
--  Example:
--     C : Clients.Client;
--     C.Init (Node, Get_Service_Support ("example_interfaces", "AddTwoInts"),
--             "add_two_ints");
--     C.Wait_For_Service (Timeout => 5.0);            --  RCL_Timeout if not
--     Sum := C.Call (Request, Timeout => 1.0) ("sum").As_Int64;
--     C.Call_Async (Request, On_Sum'Access);          --  returns at once
--
--  Several tasks may call one client at once: each gets its own response
--  (pairing by sequence number, RCL.Pending_Calls). Call waits for the
--  service to be available before sending (a request sent to nobody would
--  be lost), all within its Timeout. Asynchronous callbacks run in a task
--  of the client that lives while asynchronous calls are pending, NOT in
--  the node's executor: replies are read by the client itself because
--  synchronous Call must work from any task without the node spinning, and
--  one reply reader serves both kinds of call. So an asynchronous callback
--  may run at the same time as the node's subscription and timer
--  callbacks: state shared with them needs a protected object. (Moving
--  them to the executor would need the reply reader registered with the
--  node and Call to wait on the executor: not done.)
with Ada.Finalization;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.QoS;

private with RCL.Client_Endpoints;
private with RCL.Pending_Calls.Asynchronous;

package RCL.Clients is

   Forever : constant Duration := RCL.Nodes.Forever;

   type Response_Callback is access procedure (Response : ROSIDL.Dynamic.Message);
   --  What Call_Async runs with the response.

   type Client is new Ada.Finalization.Limited_Controlled with private;

   procedure Init
     (This    : in out Client;
      Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Services_Default)
     with Pre => not Is_Open (This);
   --  Name is expanded like a topic name (relative to the node's namespace).

   function Is_Open (This : Client) return Boolean;

   function Service_Name (This : Client) return String;
   --  The fully qualified service name.

   function Service_Available (This : Client) return Boolean
     with Pre => Is_Open (This);
   --  A server's request reader and reply writer (same serviceid) matched.

   function Wait_For_Service (This : Client; Timeout : Duration := Forever) return Boolean
     with Pre => Is_Open (This);
   procedure Wait_For_Service (This : Client; Timeout : Duration := Forever)
     with Pre => Is_Open (This);
   --  The procedure raises RCL_Timeout when the service is not available
   --  within Timeout.

   function Call
     (This    : in out Client;
      Request : ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever) return ROSIDL.Dynamic.Message
     with Pre => Is_Open (This);
   --  RCL_Timeout (naming the service) when no response came within
   --  Timeout; ROS_Exception when Request is not of the service's request
   --  type, when the context shuts down (Ctrl-C) during the wait, or when
   --  called from a response callback of this client (Call_Async).

   procedure Call_Async
     (This     : in out Client;
      Request  : ROSIDL.Dynamic.Message;
      Callback : not null Response_Callback;
      Timeout  : Duration := 60.0)
     with Pre => Is_Open (This);
   --  Sends Request at once (without waiting for the service) and returns;
   --  Callback runs with the response in the client's task (or in a
   --  synchronous Call or a future's wait of the same client that reads
   --  the reply); an exception in it is logged. A response not come within
   --  Timeout is forgotten (a warning is logged), as are the calls still
   --  pending when the context shuts down or the client is finalized.
   --  Malformed replies are logged and skipped. Callback must not make a
   --  synchronous Call of this client (ROS_Exception: it would wait for
   --  itself).

   function Pending_Async (This : Client) return Natural;
   --  Asynchronous calls still waiting for their response.

   function Pending_Calls (This : Client) return Natural;
   --  Every call still waiting for its response: synchronous calls,
   --  futures and asynchronous calls.

   --  Futures: an asynchronous call whose response the caller waits for
   --  while spinning its node (rclcpp's async_send_request with
   --  spin_until_future_complete). The response is read while somebody
   --  waits: Spin_Until_Complete, Wait, or a synchronous Call of the same
   --  client.
   --  Example:
   --     F : Clients.Future;
   --     C.Call_Future (Request, F);
   --     if Clients.Spin_Until_Complete (Node, F, Timeout => 2.0) = Clients.Success then
   --        Sum := Clients.Response (F) ("sum").As_Int64;
   --     end if;

   type Future is limited private;
   --  Must not outlive its client; finalizing a future forgets its call.

   type Future_Return_Code is (Success, Interrupted, Timed_Out);
   --  As rclcpp's FutureReturnCode: the response came; the context shut
   --  down (Ctrl-C); the Timeout passed.

   procedure Call_Future
     (This    : in out Client;
      Request : ROSIDL.Dynamic.Message;
      Into    : in out Future)
     with Pre => Is_Open (This) and then not Is_Pending (Into);
   --  Sends Request at once (without waiting for the service) and returns;
   --  Into then stands for the response. ROS_Exception when Request is not
   --  of the service's request type.

   function Is_Pending (F : Future) return Boolean;
   --  A call was made with F (ready or not).

   function Is_Ready (F : Future) return Boolean;
   --  The response has come (it stays available).

   function Response (F : Future) return ROSIDL.Dynamic.Message
     with Pre => Is_Ready (F);

   function Wait (F : in out Future; Timeout : Duration := Forever) return Future_Return_Code
     with Pre => Is_Pending (F);
   --  Reads replies until the response comes, without spinning any node.
   --  ROS_Exception from a response callback of F's client (as Call).

   function Spin_Until_Complete
     (Node    : in out RCL.Nodes.Node'Class;
      F       : in out Future;
      Timeout : Duration := Forever) return Future_Return_Code
     with Pre => Is_Pending (F);
   --  Runs Node's callbacks (Node.Spin) while waiting for F's response.
   --  ROS_Exception from a response callback of F's client (as Call).

   --  One client per (node, service name) made on first use:

   function Call
     (Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      Request : ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever) return ROSIDL.Dynamic.Message;
   --  What Node.Client_Call does.

   procedure Wait_For_Service
     (Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      Timeout : Duration := Forever);
   --  RCL_Timeout when the service is not available within Timeout.

   overriding procedure Finalize (This : in out Client);

private

   type Client_Ref is access all Client;

   procedure Read_Replies (This : Client_Ref);
   --  The pump's reading (RCL.Pending_Calls.Asynchronous).
   function Service_Name (This : Client_Ref) return String;

   package Async_Calls is new RCL.Pending_Calls.Asynchronous
     (ROSIDL.Dynamic.Message, Response_Callback, Client_Ref, Read_Replies, Service_Name);

   type Future_Call is new Ada.Finalization.Limited_Controlled with record
      Owner    : Client_Ref;
      Sequence : ROSIDL.Int64 := 0;
      Into     : RCL.Pending_Calls.Slot_Access;
   end record;

   overriding procedure Finalize (This : in out Future_Call);

   type Future is limited record
      Call : Future_Call;
   end record;
   --  (Not tagged itself: Call_Future is a primitive of Client.)

   type Client is new Ada.Finalization.Limited_Controlled with record
      Ends    : RCL.Client_Endpoints.Endpoints;
      Support : ROSIDL.Typesupport.Service_Support;
      Calls   : RCL.Pending_Calls.Table;
      --  Synchronous calls and futures; who reads replies.
      Asyncs  : Async_Calls.Calls;
   end record;

end RCL.Clients;
