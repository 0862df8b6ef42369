--  QoS events of a publisher or a subscription (RCL.Events), printed one
--  per line: "event KIND total=N change=N policy=NAME alive=N not_alive=N
--  current=N". The publisher publishes std_msgs/String every PERIOD s.
--     qos_events_demo pub|sub TOPIC [best_effort|reliable] [DEADLINE] [PERIOD] [LEASE]
--                     [by_reception|by_source]
--  DEADLINE, LEASE: seconds, 0 for none (LEASE: manual-by-topic liveliness);
--  by_source: destination order by source timestamp (older samples lost).
with Ada.Text_IO;
with Example_Support; use Example_Support;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Arguments;
with RCL.Events;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with RCL.Timers;

procedure QoS_Events_Demo is

   use RCL;

   Support : constant ROSIDL.Typesupport.Message_Support :=
     ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");

   procedure On_Event (Node : in out Nodes.Node'Class; E : Events.Event) is
      pragma Unreferenced (Node);
      function Img (N : Integer) return String is
        (if N < 0 then N'Image else N'Image (2 .. N'Image'Last));
   begin
      Ada.Text_IO.Put_Line
        ("event " & E.Kind'Image & " total=" & Img (E.Total) & " change=" & Img (E.Change)
         & " policy=" & Events.Policy_Name (E.Policy) & " alive=" & Img (E.Alive)
         & " not_alive=" & Img (E.Not_Alive) & " current=" & Img (E.Current));
      Ada.Text_IO.Flush;
   end On_Event;

   procedure On_Data
     (Node : in out Nodes.Node'Class;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info) is null;

begin
   RCL.Arguments.Load;
   declare
      Role     : constant String := Argument (1, "sub");
      Topic    : constant String := Argument (2, "qos_events");
      Deadline : constant Duration := Duration'Value (Argument (4, "0"));
      Period   : constant Duration := Duration'Value (Argument (5, "1.0"));
      Lease    : constant Duration := Duration'Value (Argument (6, "0"));
      Profile  : constant RCL.QoS.Profile :=
        (RCL.QoS.Default with delta
           Reliability => (if Argument (3, "reliable") = "best_effort" then RCL.QoS.Best_Effort
                           else RCL.QoS.Reliable),
           Deadline    => Deadline,
           Liveliness  => (if Lease > 0.0 then RCL.QoS.Manual_By_Topic else RCL.QoS.Automatic),
           Lease       => (if Lease > 0.0 then Lease else RCL.QoS.Infinite),
           Destination_Order =>
             (if Argument (7, "by_reception") = "by_source" then RCL.QoS.By_Source_Timestamp
              else RCL.QoS.By_Reception_Timestamp));
      Node     : Nodes.Node := Nodes.Init ("qos_events_" & Role);
   begin
      if Role = "pub" then
         declare
            Pub : Publishers.Publisher := Node.Publish (Support, Topic, Profile);

            procedure Tick
              (Node    : in out Nodes.Node'Class;
               Timer   : in out Timers.Timer;
               Elapsed : Duration)
            is
               pragma Unreferenced (Node, Timer, Elapsed);
               Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
            begin
               Msg ("data").Set_String ("x");
               Pub.Publish (Msg);
            end Tick;
         begin
            Events.Watch (Node, Pub, On_Event'Access);
            Node.Timer_Add (Period, Tick'Access);
            Node.Spin (During => 1.0);
            declare
               Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
            begin
               Msg ("data").Set_String ("first");
               Pub.Publish (Msg);  --  Deadlines count from the first sample.
            end;
            Node.Spin;
         end;
      else
         Node.Subscribe (Support, Topic, On_Data'Access, Profile);
         Events.Watch (Node, Topic, On_Event'Access);
         Node.Spin;
      end if;
   end;
exception
   when E : RCL.Arguments.Argument_Error | Constraint_Error =>
      Fail (E);
end QoS_Events_Demo;
