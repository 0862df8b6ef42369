--  Typed publishers and subscriptions: messages are the generated records
--  (ROSIDL.Static.<Pkg>.Messages.<Type>.Message), checked by the compiler,
--  encoded and decoded by the generated codec straight into and out of the
--  DDS sample (no dynamic message, no intermediate buffer). Instantiate
--  once per message type with the type's Handling package:
--  Example:
--     package Strings renames ROSIDL.Static.Std_Msgs.Messages.String;
--     package Chatter is new RCL.Nodes.Typed (Strings.Handling);
--     Pub : Publishers.Publisher := Chatter.Publish (Node, "/chatter");
--     Chatter.Publish (Pub, (Data => To_Unbounded_String ("Hello")));
--     Chatter.Subscribe (Node, "/chatter", On_Message'Access);
--
--  The wire is the one of the dynamic API (same DDS type names, QoS,
--  graph announcements), so typed and dynamic nodes talk to each other
--  and to ROS 2. Steady state: see Publish and Subscribe.
with ROSIDL.Static.Message_Support;

generic
   with package Handling is new ROSIDL.Static.Message_Support (<>);
package RCL.Nodes.Typed is

   subtype Message is Handling.Message;
   Full_Name  : constant String := Handling.Full_Name;
   --  "std_msgs/msg/String"
   Is_Bounded : constant Boolean := Handling.Is_Bounded;
   --  Allocation-free in steady state (see Publish and Subscribe).

   function Publish
     (Node  : in out Nodes.Node'Class;
      Topic : String;
      QoS   : RCL.QoS.Profile := RCL.QoS.Default) return RCL.Publishers.Publisher;
   --  A publisher of this type on Topic (expanded as Node.Publish does).

   procedure Publish (Pub : RCL.Publishers.Publisher; Msg : Message);
   --  Encodes Msg (native byte order) into a DDS sample and writes it.
   --  ROS_Exception when Pub's type is not this one, after shutdown, or on
   --  a DDS error. Allocates nothing on the Ada heap (the sample's bytes
   --  are Cyclone's).

   procedure Subscribe
     (Node     : in out Nodes.Node'Class;
      Topic    : String;
      Callback : not null access procedure
        (Node : in out Nodes.Node'Class;
         Msg  : Message;
         Info : ROSIDL.Message_Info);
      QoS      : RCL.QoS.Profile := RCL.QoS.Default);
   --  Each sample is decoded into a record kept by the subscription (made
   --  at Subscribe, reused for every sample: no allocation per sample for
   --  bounded types, nor for unbounded ones once their sequences and
   --  strings have grown to the sizes received) and passed to Callback by
   --  the executor spinning the node. Malformed samples are logged with the
   --  topic and the byte offset, and skipped. Callback may be nested in the
   --  main subprogram: it must stay callable while the node exists.

end RCL.Nodes.Typed;
