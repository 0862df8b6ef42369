--  The typed (generated message) publish/subscribe peer of the
--  interoperability tests (tests/interop/test_pubsub_typed.py), as
--  pubsub_peer but with ROSIDL.Static records and RCL.Nodes.Typed:
--
--     typed_peer pub  MSG TOPIC COUNT
--        publishes COUNT messages (10 Hz) filled with the values below;
--     typed_peer echo MSG TOPIC OUT_TOPIC COUNT
--        republishes each message received on TOPIC to OUT_TOPIC, COUNT
--        times, then exits; COUNT 0: until stopped (SIGTERM), for a test
--        that feeds it until its echoes come back (Echo_Peers).
--
--  MSG: LaserScan (sensor_msgs), Odometry, OccupancyGrid (nav_msgs); the
--  Python test expects the same values.
with Ada.Command_Line;
with Ada.Strings.Unbounded;
with Echo_Peers; use Echo_Peers;
with RCL.Nodes.Typed;
with RCL.Publishers;
with ROSIDL.Static.Message_Support;
with ROSIDL.Static.Nav_Msgs.Messages.OccupancyGrid;
with ROSIDL.Static.Nav_Msgs.Messages.Odometry;
with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
with ROSIDL.Static.Sequences;
with ROSIDL.Static.Std_Msgs.Messages.Header;

procedure Typed_Peer is

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use type ROSIDL.Float32;
   use type ROSIDL.Float64;
   use type ROSIDL.Int8;

   package Scans renames ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
   package Odometries renames ROSIDL.Static.Nav_Msgs.Messages.Odometry;
   package Grids renames ROSIDL.Static.Nav_Msgs.Messages.OccupancyGrid;

   Mode     : constant String := Argument (1);
   Msg_Name : constant String := Argument (2);
   Topic    : constant String := Argument (3);
   Count    : constant Natural := Natural'Value (Argument (if Mode = "echo" then 5 else 4));

   Header : constant ROSIDL.Static.Std_Msgs.Messages.Header.Message :=
     (Stamp => (Sec => 1_700_000_123, Nanosec => 456_789),
      Frame_Id => To_Unbounded_String ("base_laser"));

   function Scan return Scans.Message is
   begin
      return M : Scans.Message do
         M.Header := Header;
         M.Angle_Min := -1.5;
         M.Angle_Max := 1.5;
         M.Angle_Increment := 0.25;
         M.Time_Increment := 0.001;
         M.Scan_Time := 0.1;
         M.Range_Min := 0.125;
         M.Range_Max := 30.0;
         M.Ranges := ROSIDL.Static.Sequences.Float32_Sequences.To_Sequence
           ([for I in 0 .. 12 => ROSIDL.Float32 (I + 1) * 0.5]);
         M.Intensities := ROSIDL.Static.Sequences.Float32_Sequences.To_Sequence
           ([100.0, 200.0, 300.0]);
      end return;
   end Scan;

   function Odometry return Odometries.Message is
   begin
      return M : Odometries.Message do
         M.Header := Header;
         M.Child_Frame_Id := To_Unbounded_String ("base_link");
         M.Pose.Pose.Position := (1.0, 2.0, 3.0);
         M.Pose.Pose.Orientation.W := 1.0;
         M.Pose.Covariance := [for I in 0 .. 35 => ROSIDL.Float64 (I + 1) / 4.0];
         M.Twist.Twist.Linear.X := 0.25;
         M.Twist.Twist.Angular.Z := -0.5;
         M.Twist.Covariance := [for I in 0 .. 35 => (if I mod 7 = 0 then 0.01 else 0.0)];
      end return;
   end Odometry;

   function Grid return Grids.Message is
      Width  : constant := 100;
      Height : constant := 50;
   begin
      return M : Grids.Message do
         M.Header := Header;
         M.Info.Map_Load_Time := (Sec => 3, Nanosec => 4);
         M.Info.Resolution := 0.05;
         M.Info.Width := Width;
         M.Info.Height := Height;
         M.Info.Origin.Position := (-25.0, -25.0, 0.0);
         M.Info.Origin.Orientation.W := 1.0;
         M.Data.Set_Length (Width * Height);
         for I in 0 .. Width * Height - 1 loop
            M.Data (I) := ROSIDL.Int8 (I mod 101) - (if I mod 3 = 0 then 1 else 0);
         end loop;
      end return;
   end Grid;

   Node : RCL.Nodes.Node := RCL.Nodes.Init ("typed_peer");

   generic
      with package Handling is new ROSIDL.Static.Message_Support (<>);
      with function Value return Handling.Message;
   procedure Run;

   procedure Run is
      package Topics is new RCL.Nodes.Typed (Handling);
   begin
      if Mode = "pub" then
         declare
            Pub : constant RCL.Publishers.Publisher := Topics.Publish (Node, Topic);
            Msg : constant Topics.Message := Value;
         begin
            for Unused in 1 .. Count loop
               Topics.Publish (Pub, Msg);
               Node.Spin (During => 0.1);
            end loop;
         end;
      elsif Mode = "echo" then
         declare
            Pub : constant RCL.Publishers.Publisher := Topics.Publish (Node, Argument (4));

            procedure Echo
              (Node : in out RCL.Nodes.Node'Class;
               Msg  : Topics.Message;
               Info : ROSIDL.Message_Info)
            is
               pragma Unreferenced (Node, Info);
            begin
               Topics.Publish (Pub, Msg);
               Echoed := Echoed + 1;
            end Echo;
         begin
            Topics.Subscribe (Node, Topic, Echo'Access);
            Spin_Until_Echoed (Node, Count);
         end;
      else
         raise Program_Error with "typed_peer: mode pub or echo expected, found " & Mode;
      end if;
   end Run;

   procedure Run_Scan is new Run (Scans.Handling, Scan);
   procedure Run_Odometry is new Run (Odometries.Handling, Odometry);
   procedure Run_Grid is new Run (Grids.Handling, Grid);

begin
   if Msg_Name = "LaserScan" then
      Run_Scan;
   elsif Msg_Name = "Odometry" then
      Run_Odometry;
   elsif Msg_Name = "OccupancyGrid" then
      Run_Grid;
   else
      raise Program_Error with "typed_peer: no values for " & Msg_Name;
   end if;
end Typed_Peer;
