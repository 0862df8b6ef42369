--  The slides' Listener with a generated message type: the callback
--  receives the record std_msgs/msg/String.
with Ada.Strings.Unbounded;
with RCL.Logging;
with RCL.Nodes.Typed;
with ROSIDL.Static.Std_Msgs.Messages.String;

use RCL;

procedure Typed_Listener is
   package Strings renames ROSIDL.Static.Std_Msgs.Messages.String;
   package Chatter is new RCL.Nodes.Typed (Strings.Handling);

   procedure Callback (Node : in out Nodes.Node'Class;
                       Msg  :        Strings.Message;
                       Info :        ROSIDL.Message_Info) is
      pragma Unreferenced (Node, Info);
   begin
      Logging.Info ("Got chatter: '" & Ada.Strings.Unbounded.To_String (Msg.Data) & "'");
   end Callback;

   Node : Nodes.Node := Nodes.Init ("listener");

begin
   Chatter.Subscribe (Node, "/chatter", Callback'Access);
   Node.Spin (During => Nodes.Forever);
end Typed_Listener;
