--  What the other RCL units reach inside a publisher: its creation by a
--  node, its DDS writer (the typed Publish writes to it, the QoS event
--  watches poll it) and its message type. The full view of
--  RCL.Publishers.Publisher extends Publisher_Core. A private child of RCL.
with Ada.Finalization;
with Ada.Strings.Unbounded;
with ROSIDL.Typesupport;
with RCL.DDS;
with RCL.Graph;
with RCL.QoS;
limited with RCL.Publishers;

private package RCL.Publisher_Writers is

   type Publisher_Core is abstract new Ada.Finalization.Limited_Controlled with record
      W       : aliased RCL.DDS.Writer;
      Topic   : Ada.Strings.Unbounded.Unbounded_String;
      Node    : RCL.Graph.Node_Id := RCL.Graph.No_Node;
      Typed   : Boolean := False;
      --  Support is the publisher's message type (Set_Support).
      Support : ROSIDL.Typesupport.Message_Support;
   end record;

   procedure Create
     (This      : in out RCL.Publishers.Publisher'Class;
      Topic     : String;
      Type_Name : String;
      Profile   : RCL.QoS.Profile;
      Node      : RCL.Graph.Node_Id);
   --  Opens This's writer on the DDS topic of Topic (a fully qualified ROS
   --  name; RCL.Names.DDS_Topic_Name), announced in the graph as an
   --  endpoint of Node; its QoS events are watched.

   function Writer
     (This : RCL.Publishers.Publisher'Class) return not null access constant RCL.DDS.Writer;

   procedure Set_Support
     (This    : in out RCL.Publishers.Publisher'Class;
      Support : ROSIDL.Typesupport.Message_Support);
   --  The message type of a typed publisher (a cheaper check in Publish).

end RCL.Publisher_Writers;
