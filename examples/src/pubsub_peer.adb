--  Typed publish/subscribe peer of the interoperability tests
--  (tests/interop/test_pubsub_typed.py):
--
--     pubsub_peer pub  PKG MSG TOPIC COUNT [best_effort]
--        publishes COUNT messages (10 Hz) filled with the values below;
--     pubsub_peer echo PKG MSG TOPIC OUT_TOPIC COUNT [best_effort]
--        republishes each message received on TOPIC to OUT_TOPIC, COUNT
--        times, then exits; COUNT 0: until stopped (SIGTERM), for a test
--        that feeds it until its echoes come back (Echo_Peers);
--
--  Known types filled: std_msgs/String, geometry_msgs/Twist,
--  sensor_msgs/LaserScan, nav_msgs/Odometry (the Python test expects the
--  same values).
with Ada.Command_Line;
with Echo_Peers; use Echo_Peers;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;

procedure Pubsub_Peer is

   use Ada.Command_Line;
   use ROSIDL.Dynamic;
   use type ROSIDL.Float32;
   use type ROSIDL.Float64;

   Mode     : constant String := Argument (1);
   Pkg      : constant String := Argument (2);
   Msg_Name : constant String := Argument (3);
   Topic    : constant String := Argument (4);
   Count    : constant Natural :=
     Natural'Value (Argument (if Mode = "echo" then 6 else 5));
   Best     : constant Boolean :=
     Argument_Count >= (if Mode = "echo" then 7 else 6)
     and then Argument (Argument_Count) = "best_effort";
   Profile  : constant RCL.QoS.Profile :=
     (if Best then RCL.QoS.Sensor_Data else RCL.QoS.Default);
   Support  : constant ROSIDL.Typesupport.Message_Support :=
     ROSIDL.Typesupport.Get_Message_Support (Pkg, Msg_Name);

   procedure Fill_Header (Msg : Message) is
   begin
      Msg ("header") ("stamp") ("sec").As_Int32 := 1_700_000_123;
      Msg ("header") ("stamp") ("nanosec").As_UInt32 := 456_789;
      Msg ("header") ("frame_id").Set_String ("base_laser");
   end Fill_Header;

   procedure Fill (Msg : Message; N : Positive) is
   begin
      if Msg_Name = "String" then
         Msg ("data").Set_String ("Hello World:" & N'Image);
      elsif Msg_Name = "Twist" then
         Msg ("linear") ("x").As_Float64 := 0.5;
         Msg ("linear") ("y").As_Float64 := -1.25;
         Msg ("linear") ("z").As_Float64 := 0.0;
         Msg ("angular") ("x").As_Float64 := 0.0;
         Msg ("angular") ("y").As_Float64 := 0.0;
         Msg ("angular") ("z").As_Float64 := 0.75 * ROSIDL.Float64 (N);
      elsif Msg_Name = "LaserScan" then
         Fill_Header (Msg);
         Msg ("angle_min").As_Float32 := -1.5;
         Msg ("angle_max").As_Float32 := 1.5;
         Msg ("angle_increment").As_Float32 := 0.25;
         Msg ("time_increment").As_Float32 := 0.001;
         Msg ("scan_time").As_Float32 := 0.1;
         Msg ("range_min").As_Float32 := 0.125;
         Msg ("range_max").As_Float32 := 30.0;
         Msg ("ranges").Set_Float32_Array
           ([for I in 1 .. 13 => ROSIDL.Float32 (I) * 0.5]);
         Msg ("intensities").Set_Float32_Array ([100.0, 200.0, 300.0]);
      elsif Msg_Name = "Odometry" then
         Fill_Header (Msg);
         Msg ("child_frame_id").Set_String ("base_link");
         Msg ("pose") ("pose") ("position") ("x").As_Float64 := 1.0;
         Msg ("pose") ("pose") ("position") ("y").As_Float64 := 2.0;
         Msg ("pose") ("pose") ("position") ("z").As_Float64 := 3.0;
         Msg ("pose") ("pose") ("orientation") ("w").As_Float64 := 1.0;
         Msg ("pose") ("covariance").Set_Float64_Array
           ([for I in 1 .. 36 => ROSIDL.Float64 (I) / 4.0]);
         Msg ("twist") ("twist") ("linear") ("x").As_Float64 := 0.25;
         Msg ("twist") ("twist") ("angular") ("z").As_Float64 := -0.5;
         Msg ("twist") ("covariance").Set_Float64_Array
           ([for I in 1 .. 36 => (if I mod 7 = 1 then 0.01 else 0.0)]);
      else
         raise Program_Error with "pubsub_peer: no values for " & Msg_Name;
      end if;
   end Fill;

   Node : RCL.Nodes.Node := RCL.Nodes.Init ("pubsub_peer");

begin
   if Mode = "pub" then
      declare
         Pub : RCL.Publishers.Publisher := Node.Publish (Support, Topic, Profile);
         Msg : constant Message := Init (Support);
      begin
         for N in 1 .. Count loop
            Fill (Msg, N);
            Pub.Publish (Msg);
            Node.Spin (During => 0.1);
         end loop;
      end;
   elsif Mode = "echo" then
      declare
         Out_Topic : constant String := Argument (5);
         Pub       : RCL.Publishers.Publisher := Node.Publish (Support, Out_Topic, Profile);

         procedure Echo
           (Node : in out RCL.Nodes.Node'Class;
            Msg  : in out Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            Pub.Publish (Msg);
            Echoed := Echoed + 1;
         end Echo;
      begin
         Node.Subscribe (Support, Topic, Echo'Access, Profile);
         Spin_Until_Echoed (Node, Count);
      end;
   else
      raise Program_Error with "pubsub_peer: mode pub or echo expected, found " & Mode;
   end if;
end Pubsub_Peer;
