with AUnit.Assertions; use AUnit.Assertions;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with Suite_Support; use Suite_Support;

package body RCL.Clocks.Tests is

   procedure Real_Clocks (Unused : in out Fixture) is
      S1 : constant Nanoseconds := Now (Steady);
      W  : constant Nanoseconds := Now (System);
      S2 : constant Nanoseconds := Now (Steady);
   begin
      Assert (S2 >= S1, "steady clock is monotonic");
      Assert (W > 1_600_000_000 * 1_000_000_000, "system time since the epoch");
      Assert (To_Duration (1_500_000_000) = 1.5, "To_Duration");
      Assert (To_Duration (-1) < 0.0, "negative spans");
      Assert (not Sim_Time_Requested, "no --ros-args in the test driver");
   end Real_Clocks;

   procedure Sim_Time (Unused : in out Fixture) is
      Support : constant ROSIDL.Typesupport.Message_Support :=
        ROSIDL.Typesupport.Get_Message_Support ("rosgraph_msgs", "Clock");
      Node    : RCL.Nodes.Node := RCL.Nodes.Init ("sim_time_test");
      Pub     : RCL.Publishers.Publisher := Node.Publish (Support, "/clock", RCL.QoS.Clock);
      Msg     : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
      Target  : constant Nanoseconds := 42 * 1_000_000_000 + 500;
   begin
      Enable_Sim_Time (Node);
      Assert (Sim_Time_Enabled, "enabled");
      Msg ("clock") ("sec").As_Int32 := 42;
      Msg ("clock") ("nanosec").As_UInt32 := 500;
      for I in 1 .. 100 loop
         exit when Now (ROS) = Target;
         Pub.Publish (Msg);
         Node.Spin (During => 0.05);
      end loop;
      Assert (Now (ROS) = Target, "ROS time follows /clock:" & Now (ROS)'Image);
      Assert (Now (System) > Target * 10, "system time unaffected");
   end Sim_Time;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("clocks: steady and system", Real_Clocks'Access));
      Result.Add_Test (Caller.Create ("clocks: ROS time from /clock", Sim_Time'Access));
      return Result;
   end Suite;

end RCL.Clocks.Tests;
