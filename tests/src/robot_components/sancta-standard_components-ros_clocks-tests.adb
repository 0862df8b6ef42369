with Ada.Real_Time;
with AUnit.Assertions;
with ROSIDL;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with Sancta.Runtime.Components;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Schedulers;
with Suite_Support; use Suite_Support;

package body Sancta.Standard_Components.ROS_Clocks.Tests is

   use AUnit.Assertions;
   use Ada.Real_Time;

   --  Counts its calls; period 100 ms.
   type Counter is new Runtime.Components.Component with record
      Calls : Natural := 0;
   end record;

   overriding procedure Run (This : in out Counter; Next : in out Runtime.Clocks.Time);

   overriding procedure Run (This : in out Counter; Next : in out Runtime.Clocks.Time) is
   begin
      This.Calls := This.Calls + 1;
      Next := Next + Milliseconds (100);
   end Run;

   type Counter_Access is access all Counter;

   procedure Follows_Clock_Topic (Unused : in out Fixture) is
      Support : constant ROSIDL.Typesupport.Message_Support :=
        ROSIDL.Typesupport.Get_Message_Support ("rosgraph_msgs", "Clock");
      Node    : RCL.Nodes.Node := RCL.Nodes.Init ("ros_clock_test_publisher");
      Pub     : RCL.Publishers.Publisher := Node.Publish (Support, "/clock", RCL.QoS.Clock);
      Sim     : aliased ROS_Clock;
      DB      : aliased Runtime.Local_Databases.Database;
      S       : Runtime.Schedulers.Scheduler;
      C       : constant Counter_Access := new Counter;
      Base    : constant Runtime.Clocks.Time := Runtime.Clocks.Epoch + Seconds (100);

      procedure Publish_Until (Millis : Natural) is
         --  Publishes /clock = 100 s + Millis until Sim.Now shows it.
         Msg  : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
         Want : constant Runtime.Clocks.Time := Base + Milliseconds (Millis);
      begin
         Msg ("clock") ("sec").As_Int32 := ROSIDL.Int32 (100 + Millis / 1000);
         Msg ("clock") ("nanosec").As_UInt32 := ROSIDL.UInt32 ((Millis mod 1000) * 1_000_000);
         for I in 1 .. 200 loop
            exit when Sim.Now = Want;
            Pub.Publish (Msg);
            delay 0.02;
         end loop;
         Assert (Sim.Now = Want, "ROS clock at" & Millis'Image & " ms after 100 s");
      end Publish_Until;

   begin
      Sim.Follow_Clock_Topic ("ros_clock_test_follower");
      C.Initialize
        ((Agent_Id => Ada.Strings.Unbounded.To_Unbounded_String ("Test"),
          Instance_Name => Ada.Strings.Unbounded.To_Unbounded_String ("counter"),
          Database => DB'Unchecked_Access, Clock => Sim'Unchecked_Access, others => <>));
      S.Initialize (Sim'Unchecked_Access, "sim");
      S.Add (Runtime.Components.Component_Access (C), Base);
      Publish_Until (0);
      S.Run_Due;
      Assert (C.Calls = 1, "first call at 100 s, calls:" & C.Calls'Image);
      Publish_Until (350);
      S.Run_Due;
      Assert (C.Calls = 4, "100.1, 100.2, 100.3 caught up, calls:" & C.Calls'Image);
      --  No /clock: 0.3 s of wall time pass, the ROS clock does not move,
      --  nothing more is due (on the wall clock, 3 more calls would be).
      delay 0.3;
      S.Run_Due;
      Assert (C.Calls = 4, "time stands still without /clock, calls:" & C.Calls'Image);
      --  Wait_Until gives up after Max_Wait of wall time when /clock stops.
      Sim.Wait_Until (Base + Seconds (10));
      Assert (Sim.Now = Base + Milliseconds (350), "Wait_Until returned, time unchanged");
      --  Step waits for the next due time (100.4 s) on /clock.
      Publish_Until (420);
      S.Step;
      Assert (C.Calls = 5, "Step at 100.42 s, calls:" & C.Calls'Image);
      Sim.Stop;
   exception
      when others =>
         Sim.Stop;
         raise;
   end Follows_Clock_Topic;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("ros clock: scheduler follows /clock",
                                      Follows_Clock_Topic'Access));
      return Result;
   end Suite;

end Sancta.Standard_Components.ROS_Clocks.Tests;
