--  The slides' Talker with a generated message type: the record
--  std_msgs/msg/String (ROSIDL.Static.Std_Msgs.Messages.String) instead of
--  a dynamic message, so a misspelt field is a compile-time error.
with Ada.Calendar;
with Ada.Strings.Unbounded;
with RCL.Nodes.Typed;
with RCL.Publishers;
with RCL.Utils;
with ROSIDL.Static.Std_Msgs.Messages.String;

use Ada;
use RCL;
use type Ada.Calendar.Time;

procedure Typed_Talker is
   package Strings renames ROSIDL.Static.Std_Msgs.Messages.String;
   package Chatter is new RCL.Nodes.Typed (Strings.Handling);

   Node : Nodes.Node           := Nodes.Init (Utils.Command_Name);
   Pub  : constant Publishers.Publisher := Chatter.Publish (Node, "/chatter");

   task Publisher;
   task body Publisher is
      Count  : Positive          := 1;
      Period : constant Duration := 1.0;
      Next   : Calendar.Time     := Calendar.Clock;
      Msg    : Strings.Message;
   begin
      loop
         Msg.Data := Ada.Strings.Unbounded.To_Unbounded_String ("Hello World:" & Count'Image);
         delay until Next;
         Chatter.Publish (Pub, Msg);
         Count := Count + 1;
         Next := Next + Period;
      end loop;
   end Publisher;
   --  After Ctrl-C, Spin returns and Publish raises (the context is shut
   --  down), which ends the task and then the program.

begin
   Node.Spin (During => Nodes.Forever);
end Typed_Talker;
