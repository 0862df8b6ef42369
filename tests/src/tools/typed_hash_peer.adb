--  Test peer of tests/interop/test_typed_type_hash.py: endpoints of a
--  generated user type, sancta_test_msgs/msg/Everything, which the test
--  keeps off the interface search path. First a raw (untyped) publisher of
--  its DDS type on TOPIC_untyped, made before any typed endpoint: it
--  announces what the search path alone gives (in Jazzy layout, the zero
--  hash when the type is not on it). Then a typed publisher and a typed
--  subscription on TOPIC, which register the generated hash. Prints
--  "type_hash HASH" (the generated constant) and "ready", then spins.
--     typed_hash_peer TOPIC SECONDS
with Ada.Command_Line;
with Ada.Text_IO;
with RCL.Nodes.Typed;
with RCL.Publishers;
with ROSIDL.Static.Sancta_Test_Msgs.Messages.Everything;

procedure Typed_Hash_Peer is
   package Everything renames ROSIDL.Static.Sancta_Test_Msgs.Messages.Everything;
   package Typed is new RCL.Nodes.Typed (Everything.Handling);
   use Ada.Command_Line;
begin
   if Argument_Count /= 2 then
      Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, "usage: typed_hash_peer TOPIC SECONDS");
      Set_Exit_Status (2);
      return;
   end if;
   declare
      Topic   : constant String := Argument (1);
      Seconds : constant Duration := Duration'Value (Argument (2));

      procedure On_Message
        (Node : in out RCL.Nodes.Node'Class;
         Msg  : Everything.Message;
         Info : ROSIDL.Message_Info) is null;

      Node    : RCL.Nodes.Node := RCL.Nodes.Init ("typed_hash_peer");
      Untyped : constant RCL.Publishers.Publisher :=
        Node.Publish_Raw (Everything.DDS_Type_Name, Topic & "_untyped");
      Pub     : constant RCL.Publishers.Publisher := Typed.Publish (Node, Topic);
      pragma Unreferenced (Untyped, Pub);
   begin
      Typed.Subscribe (Node, Topic, On_Message'Access);
      Ada.Text_IO.Put_Line ("type_hash " & Everything.Type_Hash);
      Ada.Text_IO.Put_Line ("ready");
      Ada.Text_IO.Flush;
      Node.Spin (During => Seconds);
   end;
end Typed_Hash_Peer;
