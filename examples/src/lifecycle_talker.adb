--  A managed (lifecycle) node, as ROS 2's lifecycle_talker demo: publishes
--  "Lifecycle HelloWorld #N" on /lifecycle_chatter every 0.2 s, but only
--  while active. Drive it with "rclada lifecycle set /lc_talker configure"
--  (then activate, deactivate, cleanup, shutdown) or "ros2 lifecycle".
--  Configuring fails while the parameter fail_configure is true.
--     lifecycle_talker [--ros-args ...]
with Example_Support; use Example_Support;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Arguments;
with RCL.Lifecycle;
with RCL.Logging;
with RCL.Nodes;
with RCL.Parameters;
with RCL.Timers;

procedure Lifecycle_Talker is

   use RCL;
   use RCL.Lifecycle;

   Support : constant ROSIDL.Typesupport.Message_Support :=
     ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");

   function Report (What : String; Node : in out Nodes.Node'Class; Previous : State_Id)
     return Callback_Return is
   begin
      Logging.Info (What & " (from " & Label (Previous) & ")", Node.Logger_Name);
      return Success;
   end Report;

   function On_Configure (Node : in out Nodes.Node'Class; Previous : State_Id)
     return Callback_Return is
     (if Parameters.Get (Node, "fail_configure").Bool then Failure
      else Report ("on_configure", Node, Previous));
   function On_Activate (Node : in out Nodes.Node'Class; Previous : State_Id)
     return Callback_Return is (Report ("on_activate", Node, Previous));
   function On_Deactivate (Node : in out Nodes.Node'Class; Previous : State_Id)
     return Callback_Return is (Report ("on_deactivate", Node, Previous));
   function On_Cleanup (Node : in out Nodes.Node'Class; Previous : State_Id)
     return Callback_Return is (Report ("on_cleanup", Node, Previous));
   function On_Shutdown (Node : in out Nodes.Node'Class; Previous : State_Id)
     return Callback_Return is (Report ("on_shutdown", Node, Previous));

begin
   RCL.Arguments.Load;
   declare
      Node    : Nodes.Node := Nodes.Init ("lc_talker");
      Managed : Managed_Node;
   begin
      Parameters.Declare_Parameter (Node, "fail_configure", Parameters.To_Value (False));
      Managed.Init (Node,
                    On_Configure  => On_Configure'Access,
                    On_Activate   => On_Activate'Access,
                    On_Deactivate => On_Deactivate'Access,
                    On_Cleanup    => On_Cleanup'Access,
                    On_Shutdown   => On_Shutdown'Access);
      declare
         Pub   : Lifecycle_Publisher := Managed.Publish (Support, "lifecycle_chatter");
         Msg   : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
         --  One message, refilled by every tick (as talker's).
         Count : Natural := 0;

         procedure Tick
           (Node    : in out Nodes.Node'Class;
            Timer   : in out Timers.Timer;
            Elapsed : Duration)
         is
            pragma Unreferenced (Node, Timer, Elapsed);
            Img : constant String := Natural'Image (Count + 1);
         begin
            Count := Count + 1;
            Msg ("data").Set_String ("Lifecycle HelloWorld #" & Img (Img'First + 1 .. Img'Last));
            Pub.Publish (Msg);
         end Tick;
      begin
         Node.Timer_Add (0.2, Tick'Access);
         Node.Spin;
      end;
   end;
exception
   when E : RCL.Arguments.Argument_Error | RCL.Parameters.Parameter_Error =>
      Fail (E);
end Lifecycle_Talker;
