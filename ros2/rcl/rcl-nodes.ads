--  Nodes: named participants of the ROS 2 graph, owning subscriptions and
--  timers and making publishers. All nodes of a process share the
--  context's DDS participant (RCL.Contexts).
--  Example:
--     Node : Nodes.Node := Nodes.Init ("listener", Namespace => "/robot1");
--     Node.Subscribe
--       (ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String"),
--        "chatter", Callback'Access);
--     Node.Spin (During => Forever);  --  until Ctrl-C or Contexts.Shutdown
--
--  (RCLAda's slides write Spin (Until => Forever); "until" being an Ada
--  reserved word, the parameter is named During.)
with Ada.Finalization;
with ROSIDL;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Allocators;
with RCL.DDS;
with RCL.Publishers;
with RCL.QoS;
with RCL.Timers;
with System;

private with Ada.Strings.Unbounded;
private with RCL.Node_Entities;

package RCL.Nodes is

   Forever : constant Duration := Duration'Last;

   type Node is new Ada.Finalization.Limited_Controlled with private;

   type Node_Options is record
      Start_Parameter_Services : Boolean := True;
      --  The node serves its parameters (RCL.Parameters.Serve), as every
      --  rclcpp node does unless told otherwise.
      Use_Global_Arguments     : Boolean := True;
      --  The command line's remapping rules (--ros-args -r) apply to it.
      Pool                     : RCL.Allocators.Pool_Access :=
        RCL.Allocators.Global_Allocator;
      --  Where decoding for this node's subscriptions allocates (see
      --  RCL.Allocators); the standard heap by default.
   end record;

   Default_Options : constant Node_Options := (others => <>);

   function Init
     (Name      : String;
      Namespace : String := "/";
      Options   : Node_Options := Default_Options) return Node;
   --  Validates Name (RCL.Names.Name_Error naming the offending character)
   --  and normalizes Namespace ("ns" and "/ns/" become "/ns"). The first
   --  node reads the command line (RCL.Arguments: Argument_Error for a bad
   --  --ros-args), creates the context (RCL.Contexts) and starts /rosout
   --  and ros_discovery_info; with --ros-args -p use_sim_time:=true it also
   --  subscribes to /clock (RCL.Clocks). "-r __node:=" and "-r __ns:="
   --  rename the node; its parameter services start unless Options say.

   function Name (This : Node) return String;
   function Namespace (This : Node) return String;
   function Fully_Qualified_Name (This : Node) return String;

   function Logger_Name (This : Node) return String;
   --  As in ROS 2: the namespace without its leading '/', dots for '/',
   --  then the name ("robot1.listener").

   function Expand (This : Node; Topic : String) return String;
   --  The fully qualified topic name (relative, "~", substitutions), after
   --  the command line's remapping rules (--ros-args -r from:=to).

   function Expand_Service (This : Node; Service : String) return String;
   --  The same for a service name (rules for services apply).

   function Pool (This : Node) return RCL.Allocators.Pool_Access;
   --  Options.Pool of Init.

   function Original_Name (This : Node) return String;
   --  The name the program gave, before "-r __node:=" renamed it.

   --  Publish / subscribe --------------------------------------------------

   function Publish
     (This    : in out Node;
      Support : ROSIDL.Typesupport.Message_Support;
      Topic   : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Default) return RCL.Publishers.Publisher;
   --  Topic is expanded (relative, "~", substitutions) and validated.

   procedure Subscribe
     (This     : in out Node;
      Support  : ROSIDL.Typesupport.Message_Support;
      Topic    : String;
      Callback : not null access procedure
        (Node : in out Nodes.Node'Class;
         Msg  : in out ROSIDL.Dynamic.Message;
         Info : ROSIDL.Message_Info);
      QoS      : RCL.QoS.Profile := RCL.QoS.Default);
   --  Each sample is decoded into a message of Support's type and passed to
   --  Callback by the executor spinning the node. Bytes that do not decode
   --  are reported (ROSIDL.Decode_Error with the byte offset, logged with
   --  the topic) and skipped. Callback may be nested in the main subprogram
   --  (as in the RCLAda slides): it must stay callable while the node exists.

   --  Raw (serialized) publish / subscribe ---------------------------------

   type Raw_Callback is access procedure
     (Node : in out Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info);
   --  Data: CDR with its encapsulation header, valid during the call only.

   function Publish_Raw
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      QoS       : RCL.QoS.Profile := RCL.QoS.Default) return RCL.Publishers.Publisher;
   --  Type_Name is the DDS type name ("std_msgs::msg::dds_::String_").

   procedure Subscribe_Raw
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      Callback  : not null access procedure
        (Node : in out Nodes.Node'Class;
         Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info);
      QoS       : RCL.QoS.Profile := RCL.QoS.Default);
   --  Callback may be nested in the main subprogram (as in the RCLAda
   --  slides): it must stay callable as long as the node exists.

   function Take_Raw
     (This  : in out Node;
      Topic : String;
      Info  : out ROSIDL.Message_Info) return RCL.DDS.Byte_Array;
   --  The next sample of this node's first subscription on Topic (expanded),
   --  taken without running its callback (as rclcpp's Subscription::take),
   --  for a program that polls in its own loop instead of spinning the
   --  node; an empty array when none is waiting. ROS_Exception when the node
   --  has no subscription on Topic.
   --  Example:
   --     Info : ROSIDL.Message_Info;
   --     Node.Subscribe_Raw ("geometry_msgs::msg::dds_::Twist_", "cmd_vel", Ignore'Access);
   --     ...
   --     Next : constant RCL.DDS.Byte_Array := Node.Take_Raw ("cmd_vel", Info);

   --  Subscriptions with a handler object ----------------------------------

   type Handler is abstract tagged limited null record;
   --  What a subscription runs for each sample, as an object with its own
   --  state rather than a callback (the typed subscriptions, a bag
   --  recorder's topics, the services' request readers are handlers).

   procedure Deliver
     (This : in out Handler;
      Node : in out Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is abstract;
   --  Data: CDR with its encapsulation header, valid during the call only.
   --  Run by the executor spinning the node, as a callback.

   type Handler_Access is access all Handler'Class;

   procedure Subscribe_Handler
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile := RCL.QoS.Default);
   --  As Subscribe_Raw, Handle.Deliver receiving the samples. The node owns
   --  Handle once this returns (freed with the node); not when it raises.
   --  Example:
   --     type Sink is new Nodes.Handler with null record;
   --     overriding procedure Deliver
   --       (This : in out Sink; Node : in out Nodes.Node'Class;
   --        Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info) is null;
   --     Node.Subscribe_Handler ("std_msgs::msg::dds_::String_", "chatter", new Sink);

   --  Liveliness of publishers ---------------------------------------------

   procedure Track_Liveliness (This : in out Node; Topic : String);
   --  From now on, records the liveliness changes of the publishers that
   --  this node's first subscription on Topic (expanded) matches: a
   --  publisher whose QoS has a Lease (Liveliness Automatic) and that stops
   --  asserting itself -- its process died, its host is cut off -- is
   --  reported lost once the lease has passed, and alive again when heard
   --  again. The publishers matched already are reported alive first.
   --  ROS_Exception when the node has no subscription on Topic.

   procedure Take_Liveliness_Change
     (This      : in out Node;
      Topic     : String;
      Publisher : out ROSIDL.GID;
      Alive     : out Boolean;
      Found     : out Boolean);
   --  The oldest change recorded for Topic, if any (Found): the publisher's
   --  GID (as in ROSIDL.Message_Info; all zero when DDS no longer knew it)
   --  and whether it became alive or was lost. Safe while another task
   --  spins the node.

   --  Services and clients (RCL.Services, RCL.Clients) --------------------

   procedure Serve
     (This     : in out Node;
      Support  : ROSIDL.Typesupport.Service_Support;
      Name     : String;
      Callback : not null access procedure
        (Node     : in out Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message);
      QoS      : RCL.QoS.Profile := RCL.QoS.Services_Default);
   --  Offers service Name (expanded like a topic): requests are answered
   --  by Callback while the node spins. See RCL.Services.

   function Client_Call
     (This    : Node;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      Request : ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever) return ROSIDL.Dynamic.Message;
   --  Calls service Name and waits for its response, waiting first for the
   --  service to be available; RCL_Timeout when Timeout passes. Safe from
   --  several tasks at once. See RCL.Clients.

   --  Timers ---------------------------------------------------------------

   function Timer_Add
     (This     : in out Node;
      Period   : Duration;
      Callback : not null access procedure
        (Node    : in out RCL.Nodes.Node'Class;
         Timer   : in out RCL.Timers.Timer;
         Elapsed : Duration);
      Clock    : RCL.Timers.Timer_Clock := RCL.Timers.Node_Clock) return RCL.Timers.Timer
     with Pre => Period > 0.0;
   --  Callback: as for Subscribe_Raw. On the node's clock (ROS time: /clock
   --  under use_sim_time, steady otherwise) unless Clock is Steady_Clock;
   --  see RCL.Timers.

   procedure Timer_Add
     (This     : in out Node;
      Period   : Duration;
      Callback : not null access procedure
        (Node    : in out RCL.Nodes.Node'Class;
         Timer   : in out RCL.Timers.Timer;
         Elapsed : Duration);
      Clock    : RCL.Timers.Timer_Clock := RCL.Timers.Node_Clock)
     with Pre => Period > 0.0;

   --  Callback groups ------------------------------------------------------

   type Callback_Group_Kind is (Mutually_Exclusive, Reentrant);
   --  As in rclcpp: the callbacks of a mutually exclusive group never run
   --  at the same time; those of a reentrant group may (one subscription's
   --  callback even in parallel with itself). Only the concurrent executor
   --  (RCL.Executors.Concurrent) runs callbacks in parallel at all: the
   --  sequential ones run everything one at a time anyway.
   --  Example:
   --     Sensors : constant Callback_Group := Node.Create_Callback_Group (Reentrant);
   --     Node.Set_Callback_Group (Sensors);
   --     Node.Subscribe (Scan_Support, "scan", On_Scan'Access);  --  in Sensors
   --     Node.Set_Callback_Group (Node.Default_Callback_Group);

   type Callback_Group is private;

   function Default_Callback_Group (This : Node) return Callback_Group;
   --  The group of every subscription, service and timer not made after a
   --  Set_Callback_Group: mutually exclusive, as rclcpp's default group.

   function Create_Callback_Group
     (This : in out Node;
      Kind : Callback_Group_Kind) return Callback_Group;
   --  A new group of This node (groups of different nodes never exclude
   --  each other).

   procedure Set_Callback_Group (This : in out Node; Group : Callback_Group)
     with Pre => Belongs_To (Group, This);
   --  Subscriptions, services, clients' replies and timers made on This
   --  from now on belong to Group.

   function Current_Callback_Group (This : Node) return Callback_Group;

   function Belongs_To (Group : Callback_Group; This : Node) return Boolean;
   --  Group was made by This node (or is its default group).

   function Kind (Group : Callback_Group) return Callback_Group_Kind;
   function Id (Group : Callback_Group) return Natural;
   --  0 for the default group, then 1, 2, ... in the order of creation.

   --  Spinning -------------------------------------------------------------

   procedure Spin
     (This   : in out Node;
      During : Duration := Forever;
      Once   : Boolean := False);
   --  Runs this node's callbacks in the calling task (a sequential
   --  executor, made by the first Spin and reused): for During, or until one
   --  batch of work has run (Once), or until shutdown (Ctrl-C, SIGTERM,
   --  Contexts.Shutdown). Spin a node from one task at a time; to run
   --  several nodes, or callbacks in parallel, use RCL.Executors.

   overriding procedure Finalize (This : in out Node);

private

   use Ada.Strings.Unbounded;

   procedure Subscribe_Closure
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      Deliver   : not null access procedure
        (State : System.Address;
         Node  : in out Nodes.Node'Class;
         Data  : RCL.DDS.Byte_Array;
         Info  : ROSIDL.Message_Info);
      State     : System.Address;
      Release   : not null access procedure (State : System.Address);
      QoS       : RCL.QoS.Profile := RCL.QoS.Default);
   --  For RCL.Nodes.Typed: as Subscribe_Raw, Deliver receiving
   --  State with every sample; Release (State) when the subscription ends
   --  (the node's finalization, or a failed Subscribe_Closure). Deliver,
   --  Release and State must stay valid as long as the node exists.

   type Callback_Group is new RCL.Node_Entities.Group_Data;

   protected type Cache_Lock is
      procedure Try (Got : out Boolean);
      --  Got: the kept decoded message was free and is now taken.
      procedure Release;
   private
      Taken : Boolean := False;
   end Cache_Lock;
   --  Guards the one decoded message a subscription keeps and reuses (no
   --  allocation per sample); a concurrent delivery that finds it taken
   --  decodes into a fresh one (RCL.Nodes and RCL.Nodes.Typed).

   procedure Deliver_Decoded
     (Lock     : in out Cache_Lock;
      Use_Kept : not null access procedure;
      Use_Own  : not null access procedure);
   --  A delivery: Use_Kept (decode into the kept message and run the
   --  callback) with the kept message taken, given back afterwards, also
   --  when Use_Kept raises; Use_Own (into a fresh message) when it is taken.

   type Spinner;
   type Spinner_Access is access Spinner;
   --  The sequential executor of Node.Spin, made by the first Spin and
   --  reused (completed in the body).

   type Node is new RCL.Node_Entities.Node_Core with record
      --  Node_Core: the subscriptions, timers, graph identity and current
      --  callback group that the other RCL units reach (RCL.Node_Entities).
      Spin_Exec : Spinner_Access;
      Name      : Unbounded_String;
      Namespace : Unbounded_String;
      Original  : Unbounded_String;
      Remapped  : Boolean := True;
      --  Options.Use_Global_Arguments.
      Pool      : RCL.Allocators.Pool_Access;
      Serial    : RCL.Node_Entities.Node_Serial := 0;
      --  Tells the nodes of a process apart (Belongs_To).
      Groups    : Natural := 0;
      --  Callback groups made so far.
   end record;

end RCL.Nodes;
