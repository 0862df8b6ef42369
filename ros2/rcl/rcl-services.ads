--  Services: a node answers requests of one service type, with the
--  conventions of rmw_cyclonedds_cpp (docs/ros2-wire.md): service "/add"
--  reads requests on DDS topic "rq/addRequest" and writes replies on
--  "rr/addReply"; both endpoints carry USER_DATA "serviceid=<id>;"; every
--  request and reply starts with the 16-byte header (requester's writer
--  handle, sequence number) that the reply echoes. A reply is written only
--  once the reply writer has matched the requester's reply reader (found by
--  the "clientid" of its request writer), waiting up to 100 ms for it, so
--  that no reply is lost to a client discovered late.
--
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
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.QoS;

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

   Reply_Match_Wait : constant Duration := 0.1;
   --  How long a reply waits for the requester's reply reader.

   function Request_Topic (Service_Name : String) return String;
   --  "/add" -> "rq/addRequest" (Service_Name fully qualified).

   function Reply_Topic (Service_Name : String) return String;
   --  "/add" -> "rr/addReply".

end RCL.Services;
