--  The RCLAda slides' Talker, with trivial changes only: "until" is an Ada reserved word
--  (Spin's parameter is During), the slides' "Counter" typo is Count, a use type clause for
--  Calendar's "+" and a warning pragma, and the with/use clauses the slides omit are written
--  out.
with Ada.Calendar;
with RCL.Nodes;
with RCL.Publishers;
with RCL.Utils;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

use Ada;
use RCL;
use RCL.Nodes;
use type Ada.Calendar.Time;

pragma Warnings (Off, "*could be declared constant*");
--  Msg is filled through references: the compiler sees no assignment.

procedure Talker is
   Support : constant ROSIDL.Typesupport.Message_Support :=
               ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");

   Node    : Nodes.Node           := Nodes.Init (Utils.Command_Name);
   Pub     : Publishers.Publisher := Node.Publish (Support, "/chatter");

   task Publisher;
   task body Publisher is
      Count  : Positive               := 1;
      Period : constant Duration      := 1.0;
      Next   : Calendar.Time          := Calendar.Clock;
      Msg    : ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
   begin
      loop
         Msg ("data").Set_String ("Hello World:" & Count'Img);
         delay until Next;
         Pub.Publish (Msg);
         Count := Count + 1;
         Next := Next + Period; -- Next := @ + Period; -- in Ada 202x
      end loop;
   end Publisher;
   --  After Ctrl-C, Spin returns and Publish raises (the context is shut
   --  down), which ends the task and then the program.

begin
   Node.Spin (During => Forever);
end Talker;
