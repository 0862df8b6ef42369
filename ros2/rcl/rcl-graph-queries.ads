--  Graph queries: the nodes, topics and services of the ROS 2 network as
--  this process's participant has discovered them, with endpoint details
--  (node, GID, QoS). This is the graph query API, and the one place that
--  reads DDS discovery and demangles names; RCL.Graph, the parent,
--  publishes this process's own presence, and its Topics and counts are
--  summaries computed from here.
--
--  Nodes come from the "ros_discovery_info" topic of every participant
--  (rmw_dds_common/ParticipantEntitiesInfo, Humble 24-byte or Jazzy 16-byte
--  gids both read); topics and services, with their types and QoS, from
--  the DDS built-in topics DCPSPublication and DCPSSubscription, demangled
--  ("rt/chatter" -> "/chatter"; "rq/addRequest" and "rr/addReply" ->
--  service "/add"; "std_msgs::msg::dds_::String_" -> "std_msgs/msg/String").
--  Endpoints are attributed to nodes through the gids of the discovery
--  info. Each query reads the current state, so peers that appear or
--  disappear are seen by the next query; a newly started process needs a
--  moment of discovery first (Wait_For_Settled_Discovery).
--  Example:
--     RCL.Graph.Queries.Wait_For_Settled_Discovery;
--     for T of RCL.Graph.Queries.Topic_Names_And_Types loop
--        Put_Line (To_String (T.Name) & " [" & To_String (T.Types) & "]");
--     end loop;
with Ada.Strings.Unbounded;
with RCL.DDS;
with RCL.QoS;

package RCL.Graph.Queries is

   use Ada.Strings.Unbounded;

   Unknown_Node_Name      : constant String := "_NODE_NAME_UNKNOWN_";
   Unknown_Node_Namespace : constant String := "_NODE_NAMESPACE_UNKNOWN_";

   type Graph_Node is record
      Name, Namespace : Unbounded_String;
   end record;

   function Fully_Qualified (Node : Graph_Node) return String;
   --  "/ns/name".

   type Node_Array is array (Positive range <>) of Graph_Node;

   type Endpoint_Kind is (Publisher, Subscription);

   type Endpoint is record
      Kind       : Endpoint_Kind;
      Topic_Name : Unbounded_String;  --  ROS name ("/chatter", "/add")
      Type_Name  : Unbounded_String;  --  ROS type ("std_msgs/msg/String")
      DDS_Topic  : Unbounded_String;
      DDS_Type   : Unbounded_String;
      Node       : Graph_Node;           --  Unknown_* when not announced
      GID        : RCL.DDS.GUID;
      QoS        : RCL.QoS.Profile;
      User_Data  : Unbounded_String;
   end record;

   type Endpoint_Array is array (Positive range <>) of Endpoint;

   type Name_And_Types is record
      Name  : Unbounded_String;
      Types : Unbounded_String;  --  Sorted, ", " between several types.
   end record;

   type Name_And_Types_Array is array (Positive range <>) of Name_And_Types;

   procedure Wait_For_Discovery (Time : Duration);
   --  Starts reading ros_discovery_info (if not yet) and waits Time.

   procedure Wait_For_Settled_Discovery
     (Least : Duration := 1.0; Quiet : Duration := 0.5; Limit : Duration := 5.0)
     with Pre => Least <= Limit;
   --  Waits until discovery has settled, what the ros2 daemon achieves by
   --  running all the time: at least Least, then until the participants
   --  and endpoints discovered have not changed for Quiet and every ROS 2
   --  participant (USER_DATA "enclave=...") has announced its nodes on
   --  ros_discovery_info; at most Limit. A Fast DDS node's announcement
   --  often arrives only with its next heartbeat, about 3 s after discovery.
   --  Example:
   --     Wait_For_Settled_Discovery;  --  then Node_Names is complete

   function Node_Names return Node_Array;
   --  Sorted by fully qualified name; this process's own nodes included
   --  when it publishes ros_discovery_info.

   function Topic_Endpoints return Endpoint_Array;
   --  The publishers and subscriptions of ROS topics ("rt/").

   function Topic_Names_And_Types return Name_And_Types_Array;
   function Service_Names_And_Types return Name_And_Types_Array;
   --  Sorted by name. A service is listed when its request reader or
   --  reply writer is seen (a server), as ros2 service list does.

   function Publishers_Info (Topic : String) return Endpoint_Array;
   function Subscriptions_Info (Topic : String) return Endpoint_Array;
   function Count_Publishers (Topic : String) return Natural;
   function Count_Subscribers (Topic : String) return Natural;
   --  Topic is a fully qualified ROS name ("/chatter").

   function Node_Endpoints (Node : Graph_Node) return Endpoint_Array;
   --  Every endpoint of Node, topics and services (request/reply) alike.

   --  Name mangling (pure) ----------------------------------------------

   type Name_Kind is (Topic, Request, Reply, Other);

   procedure Demangle_Topic (DDS_Topic : String; Kind : out Name_Kind;
                             ROS_Name : out Unbounded_String);
   --  "rt/a/b" -> Topic "/a/b"; "rq/addRequest" -> Request "/add";
   --  "rr/addReply" -> Reply "/add"; anything else -> Other (DDS_Topic).

   function Demangle_Type (DDS_Type : String) return String;
   --  "pkg::msg::dds_::Name_" -> "pkg/msg/Name"; service parts
   --  "pkg::srv::dds_::Name_Request_" / "_Response_" -> "pkg/srv/Name";
   --  anything else is returned unchanged.

   function Mangle_Type (ROS_Type : String) return String;
   --  "pkg/msg/Name" -> "pkg::msg::dds_::Name_" (no check).

   --  ros_discovery_info (pure) --------------------------------------------

   type Announced_Node is record
      Id      : Graph_Node;
      Readers : Unbounded_String;  --  Concatenated 16-byte GUID images, ","
      Writers : Unbounded_String;
   end record;

   type Announced_Node_Array is array (Positive range <>) of Announced_Node;

   type Participant_Info (Count : Natural) is record
      Participant : RCL.DDS.GUID;
      Nodes       : Announced_Node_Array (1 .. Count);
   end record;

   function Decode_Participant_Info (Data : RCL.DDS.Byte_Array) return Participant_Info;
   --  A ParticipantEntitiesInfo sample (CDR with encapsulation header,
   --  either byte order, 24- or 16-byte gids). ROS_Exception naming the
   --  byte offset when malformed.

end RCL.Graph.Queries;
