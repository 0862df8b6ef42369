--  Services: a node answers requests of one service type, with the
--  conventions of rmw_cyclonedds_cpp (docs/ros2-wire.md): service "/add"
--  reads requests on DDS topic "rq/addRequest" and writes replies on
--  "rr/addReply"; both endpoints carry USER_DATA "serviceid=<id>;"; every
--  request and reply starts with the 16-byte header (requester's writer
--  handle, sequence number) that the reply echoes. A reply is written only
--  once the reply writer has matched the requester's reply reader (found by
--  the "clientid" of its request writer), waiting up to 100 ms for it, so
--  that no reply is lost to a client discovered late.
--  Example:
--     procedure Adder (Node : in out Nodes.Node'Class;
--                      Req  : ROSIDL.Dynamic.Message;
--                      Resp : in out ROSIDL.Dynamic.Message) is
--     begin
--        Resp ("sum").As_Int64 := Req ("a").As_Int64 + Req ("b").As_Int64;
--     end Adder;
--     ...
--     Node.Serve (Get_Service_Support ("example_interfaces", "AddTwoInts"),
--                 "add_two_ints", Adder'Access);
--     Node.Spin;
--
--  Callbacks run in the task spinning the node. An exception in a callback
--  is logged with the service name and no reply is sent (the client times
--  out), as rclcpp does; a malformed request is logged and dropped.
with Ada.Streams;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.DDS;
with RCL.Nodes;
with RCL.QoS;

private with Ada.Containers.Ordered_Sets;
private with Ada.Strings.Unbounded;
private with RCL.Node_Entities;

package RCL.Services is

   type Callback is access procedure
     (Node     : in out RCL.Nodes.Node'Class;
      Request  : ROSIDL.Dynamic.Message;
      Response : in out ROSIDL.Dynamic.Message);

   procedure Serve
     (Node     : in out RCL.Nodes.Node'Class;
      Support  : ROSIDL.Typesupport.Service_Support;
      Name     : String;
      Callback : not null access procedure
        (Node     : in out RCL.Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message);
      QoS      : RCL.QoS.Profile := RCL.QoS.Services_Default);
   --  Callback may be nested in the main subprogram: it must stay callable
   --  as long as the node exists. RCL.Names.Name_Error for a bad Name.

   --  Servers that answer later (action results): ----------------------

   type Request_Id is private;
   --  Says which request a response answers.

   type Server is abstract new RCL.Nodes.Handler with private;
   --  A service server whose On_Request may answer at once or keep the
   --  Request_Id and Respond later, from any task (RCL.Actions).

   overriding procedure Deliver
     (This : in out Server;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info);
   --  Decodes the request and calls On_Request; the executors call it (it
   --  overrides RCL.Nodes.Handler's: Ada keeps it visible so that types
   --  derived from Server outside this package inherit it).

   procedure On_Request
     (This    : in out Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : ROSIDL.Dynamic.Message;
      Id      : Request_Id) is abstract;

   procedure Respond
     (This     : in out Server'Class;
      Id       : Request_Id;
      Response : ROSIDL.Dynamic.Message);
   --  Writes Response for request Id (once the requester's reply reader
   --  is matched, see above).

   function Support (This : Server'Class) return ROSIDL.Typesupport.Service_Support;
   function Name (This : Server'Class) return String;

   type Server_Access is access all Server'Class;

   procedure Open
     (Node    : in out RCL.Nodes.Node'Class;
      Handler : not null Server_Access;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Services_Default);
   --  Offers service Name answered by Handler, which the node then owns.

   Reply_Match_Wait : constant Duration := 0.1;
   --  How long a reply waits for the requester's reply reader.

   function Request_Topic (Service_Name : String) return String;
   --  "/add" -> "rq/addRequest" (Service_Name fully qualified).

   function Reply_Topic (Service_Name : String) return String;
   --  "/add" -> "rr/addReply".

private

   type Request_Id is record
      Header    : ROSIDL.CDR.Request_Header;
      Requester : RCL.DDS.GUID := RCL.DDS.Null_GUID;
   end record;

   function "<" (L, R : RCL.DDS.GUID) return Boolean;

   package GUID_Sets is new Ada.Containers.Ordered_Sets (RCL.DDS.GUID, "<", ROSIDL."=");

   protected type GUID_Set is
      --  Deliver may run in several executor tasks at once.
      function Contains (G : RCL.DDS.GUID) return Boolean;
      procedure Include (G : RCL.DDS.GUID);
   private
      Set : GUID_Sets.Set;
   end GUID_Set;

   --  Servers that decode their own requests (RCL.Services.Typed:
   --  generated codecs straight out of and into the DDS samples, no
   --  dynamic message).

   procedure Open_Raw
     (Node          : in out RCL.Nodes.Node'Class;
      Request_Type  : String;
      Response_Type : String;
      Name          : String;
      On_Request    : not null access procedure
        (Server : in out Services.Server'Class;
         Node   : in out RCL.Nodes.Node'Class;
         Data   : RCL.DDS.Byte_Array;
         Info   : ROSIDL.Message_Info);
      QoS           : RCL.QoS.Profile := RCL.QoS.Services_Default);
   --  Offers service Name with the DDS types given
   --  ("example_interfaces::srv::dds_::AddTwoInts_Request_"); On_Request
   --  gets every request's bytes (header included) and answers with
   --  Respond_Filled. On_Request must stay callable as long as the node
   --  exists. Support (the server) is not set: the type may be unknown to
   --  the dynamic layer.

   procedure Respond_Filled
     (This      : in out Server'Class;
      Requester : RCL.DDS.GUID;
      Size      : Ada.Streams.Stream_Element_Count;
      Fill      : not null access procedure
        (Buffer : out RCL.DDS.Byte_Array; Last : out Ada.Streams.Stream_Element_Offset));
   --  Writes the reply that Fill encodes (header included, as
   --  RCL.DDS.Write_Filled) to the request of writer Requester, once its
   --  client's reply reader is matched (see above).

   type Server is abstract new RCL.Nodes.Handler with record
      Support  : ROSIDL.Typesupport.Service_Support;
      Name     : Ada.Strings.Unbounded.Unbounded_String;
      Replies  : RCL.DDS.Writer;
      Requests : RCL.Node_Entities.Subscription_Access;
      --  The node's subscription holding the request reader.
      Ready    : GUID_Set;
      --  Request writers whose client's reply reader is known to be
      --  matched: their replies are written without checking again (a
      --  reply to a client gone meanwhile is harmless).
   end record;

end RCL.Services;
