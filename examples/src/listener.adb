--  The RCLAda slides' Listener, with trivial changes only: "until" is an
--  Ada reserved word (Spin's parameter is During), the unfinished string
--  concatenation of the slide is closed with "'", the with/use clauses the
--  slides omit are written out.
with RCL.Logging;
with RCL.Nodes;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

use RCL;
use RCL.Nodes;

procedure Listener is

   procedure Callback (Node : in out Nodes.Node'Class;
                       Msg  : in out ROSIDL.Dynamic.Message;
                       Info :        ROSIDL.Message_Info) is
      pragma Unreferenced (Node, Info);
   begin
      Logging.Info ("Got chatter: '" & Msg ("data").Get_String & "'");
   end Callback;

   Node : Nodes.Node := Nodes.Init ("listener");

begin
   Node.Subscribe
     (ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String"),
      "/chatter",
      Callback'Access);
   Node.Spin (During => Forever);
end Listener;
