--  Graph presence: the process's nodes and their endpoints, published on
--  "ros_discovery_info" (rmw_dds_common/msg/ParticipantEntitiesInfo,
--  reliable, transient local, keep last 1) as rmw_cyclonedds does, so that
--  ROS 2 tools (ros2 node list, ros2 node info) see our nodes. The message
--  is republished whole on every node or endpoint creation / destruction.
--
--  Gids are 24 bytes (the 16-byte DDS GUID then zeros) as in Humble, or 16
--  bytes as in Jazzy: Set_Layout, or ROS_DISTRO (jazzy, kilted, rolling
--  select 16; anything else 24), before the first node is created.
with Ada.Strings.Unbounded;
with ROSIDL.Type_Hashes;

package RCL.Graph is

   type GID_Layout is (Humble_24, Jazzy_16);

   procedure Set_Layout (Layout : GID_Layout);
   function Layout return GID_Layout;

   Topic_Name : constant String := "ros_discovery_info";
   Type_Name  : constant String := "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_";

   --  Basic topic queries. They are computed by RCL.Graph.Queries (the one
   --  place that reads DDS discovery and demangles names); use that child
   --  for nodes, services, endpoint details and QoS. ----------------------

   type Topic_Info is record
      Name        : Ada.Strings.Unbounded.Unbounded_String;
      --  ROS name ("/chatter").
      Type_Name   : Ada.Strings.Unbounded.Unbounded_String;
      --  ROS type ("std_msgs/msg/String").
      Publishers  : Natural := 0;
      Subscribers : Natural := 0;
   end record;

   type Topic_Info_Array is array (Positive range <>) of Topic_Info;

   function Topics return Topic_Info_Array;
   --  The ROS topics ("rt/..." DDS topics) of every ROS 2 participant on
   --  the domain, this process included, sorted by name then type, with
   --  their publisher and subscription counts (from
   --  RCL.Graph.Queries.Topic_Endpoints).

   function Count_Publishers (Topic : String) return Natural;
   function Count_Subscribers (Topic : String) return Natural;
   --  Topic: fully qualified ROS name. The same as
   --  RCL.Graph.Queries.Count_Publishers / Count_Subscribers.

   function ROS_Type_Name (DDS_Type_Name : String) return String;
   --  RCL.Graph.Queries.Demangle_Type: "std_msgs::msg::dds_::String_" ->
   --  "std_msgs/msg/String"; other names unchanged.

   --  Endpoint USER_DATA -------------------------------------------------

   Zero_Type_Hash : constant String := ROSIDL.Type_Hashes.Zero;
   --  The hash of a type unknown to this program (a raw-CDR endpoint whose
   --  interface is not on the search path): Jazzy then matches by name.

   function Endpoint_User_Data
     (Layout : GID_Layout; DDS_Type_Name : String; Extra : String := "") return String;
   --  The USER_DATA of an endpoint of the given type: Extra ("clientid=...;"
   --  or "") then, in the Jazzy layout, "typehash=RIHS01_<hex>;", the
   --  type's REP 2011 hash (ROSIDL.Type_Hashes), as rmw_cyclonedds writes it.

   function Endpoint_User_Data (DDS_Type_Name : String; Extra : String := "") return String is
     (Endpoint_User_Data (Layout, DDS_Type_Name, Extra));
   --  The same in the current layout.

   function Type_Hash (User_Data : String) return String;
   --  The "typehash=" value of an endpoint's USER_DATA; Zero_Type_Hash
   --  when absent (Humble peers), as Jazzy does.

   type Node_Id is new Natural;
   No_Node : constant Node_Id := 0;
   --  A node as the graph announcements know it (RCL.Nodes.Graph_Id); the
   --  announcements themselves are made by the library's own units
   --  (RCL.Graph_Announcements, private).

end RCL.Graph;
