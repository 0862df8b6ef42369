--  The DDS side of a service client, for the clients of RCL.Clients and of
--  RCL.Services.Typed: the request writer and the reply reader (opened
--  and announced in the graph), a waitset on the reader, the requests'
--  header GUID, and the waits for the service. A private child of RCL.
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with ROSIDL;
with RCL.DDS;
with RCL.Graph;
with RCL.Nodes;
with RCL.QoS;

private package RCL.Client_Endpoints is

   type Endpoints is limited record
      Name     : Ada.Strings.Unbounded.Unbounded_String;
      --  The fully qualified service name.
      Requests : RCL.DDS.Writer;
      Replies  : RCL.DDS.Reader;
      Waiting  : RCL.DDS.Waitset;
      --  Replies attached (key 1).
      Handle   : ROSIDL.UInt64 := 0;
      --  The request writer's instance handle (the requests' header GUID).
      Node     : RCL.Graph.Node_Id := RCL.Graph.No_Node;
      --  Where the endpoints are announced (ros_discovery_info).
      Is_Open  : Boolean := False;
   end record;

   procedure Open
     (This          : in out Endpoints;
      Node          : RCL.Nodes.Node'Class;
      Name          : String;
      Request_Type  : String;
      Response_Type : String;
      QoS           : RCL.QoS.Profile)
     with Pre => not This.Is_Open;
   --  The endpoints of a client of service Name (expanded like a topic
   --  name, RCL.Names.Name_Error for a bad one) with the DDS types given,
   --  a new "clientid" in their USER_DATA, announced in the graph as
   --  endpoints of Node.

   procedure Close (This : in out Endpoints);
   --  Withdraws them from the graph (nothing when not open); the DDS
   --  entities go with the object. Never raises (for the client's
   --  Finalize).

   function Service_Name (This : Endpoints) return String;

   function Service_Available (This : Endpoints) return Boolean
     with Pre => This.Is_Open;
   --  A server's request reader and reply writer (same serviceid) matched.

   function Available_Before
     (This : Endpoints; Deadline : Ada.Real_Time.Time) return Boolean
     with Pre => This.Is_Open;
   --  Waits (10 ms steps) until the service is available, Deadline or
   --  shutdown; whether it is.

   procedure Await_Service
     (This : Endpoints; Deadline : Ada.Real_Time.Time; Timeout : Duration)
     with Pre => This.Is_Open;
   --  RCL_Timeout "service S not available after T s" (Timeout, from which
   --  Deadline was computed) unless Available_Before (Deadline).

   function Deadline_Of (Timeout : Duration) return Ada.Real_Time.Time;
   --  Clock + Timeout; Time_Last for a Timeout >= 1.0E6 (Forever).

   function Seconds_Image (Timeout : Duration) return String;
   --  " 1.500000000 s", or "ever" for Forever ("after ever").

end RCL.Client_Endpoints;
