with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with AUnit.Assertions;
with ROSIDL;
with ROSIDL.Dynamic;
with Sancta.Standard_Components.All_Standard;
with Sancta.Standard_Components.Robot_Messages;
with Sancta.Standard_Components.ROS2;
with Sancta.Geometry;
with Sancta.Logging;
with Sancta.Robot.Goal_Sequencers;
with Sancta.Robot.Grids;
with Sancta.Robot.Mappers;
with Sancta.Robot.Sensors;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Factory;
with Sancta.Runtime.Component_Hosts;
with Sancta.Runtime.Values;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Robot_Lists;
with Sancta.Simulation.Simulators;
with Suite_Support; use Suite_Support;

package body Sancta.Standard_Components.Navigation.Tests is

   pragma Warnings (Off, Sancta.Standard_Components.All_Standard);

   use AUnit.Assertions;
   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use type Ada.Real_Time.Time;
   use type ROSIDL.UInt32;
   use type ROSIDL.Int8;
   use type ROSIDL.Float64;
   use type ROSIDL.Dynamic.Int8_Array;
   use type Sancta.Robot.Sensors.Range_Array;
   package RC renames Sancta.Runtime.Components;
   package RM renames Sancta.Standard_Components.Robot_Messages;
   package Sims renames Sancta.Simulation.Simulators;

   function Img (X : Real) return String is (Values.Real_Image (Long_Float (X)));

   --  "test_feed": declares the sensor keys the test stores itself --

   type Feed is new RC.Component with null record;

   function Create_Feed (Ctx : RC.Context) return RC.Component_Access is
      Result : constant RC.Component_Access := new Feed;
   begin
      Result.Initialize (Ctx);
      return Result;
   end Create_Feed;

   procedure Register_Feed is
      use type RC.Port_Vectors.Vector;
   begin
      if not Factory.Is_Registered ("test_feed") then
         Factory.Register
           ((Name    => To_Unbounded_String ("test_feed"),
             Doc     => To_Unbounded_String ("test: keys stored by the test"),
             Ports   => RC.Port_Vectors.Empty_Vector
                          & RC.Out_Port ("odometry", "types.pose")
                          & RC.Out_Port ("scan", RM.Scan_Type)
                          & RC.Out_Port ("gps", RM.GPS_Type)
                          & RC.Out_Port ("tasks", "types.string"),
             others  => <>),
            Create_Feed'Access);
      end if;
   end Register_Feed;

   procedure Load_Checked (File : String; Config : out Configurations.Configuration) is
   begin
      Configurations.Load (File, Config);
      if Configurations.Error_Count (Config) > 0 then
         Assert (False, File & ": " & Configurations.Image (Config.Diagnostics.First_Element));
      end if;
   end Load_Checked;

   procedure Start_Host
     (N      : in out Component_Hosts.Component_Host;
      File   : String;
      Config : out Configurations.Configuration;
      Clock  : not null Clocks.Clock_Access) is
      --  N runs the configuration File (its agent 1, with the test feed),
      --  driven by hand (no scheduler task), console logging off.
   begin
      Register_Feed;
      Load_Checked (File, Config);
      N.Create (Config, 1, Clock);
      Logging.Set_Console (False);
      N.Start (Run_Scheduler_Task => False);
   end Start_Host;

   function Pose_At (N : in out Component_Hosts.Component_Host; Key : String) return Pose is
     (Values.Pose_Value (N.Database.Get (Key)).Data);

   function Position_Error (A, B : Pose) return Real is (Distance (Position (A), Position (B)));

   ---------------------------------------------------------------------------

   procedure Closed_Loop_Reaches_Goals (Unused : in out Fixture) is
      Config  : Configurations.Configuration;
      Clock   : aliased Clocks.Manual_Clock;
      N       : Component_Hosts.Component_Host;
      Sim     : Sims.Simulator;
      Id      : Sims.Robot_Id;
      Robot   : Sims.Robot_Config := Sims.Default_Robot;
      Start   : constant Pose := (2.0, 10.0, 0.0);
      Last_O, Last_S, Last_G : Natural := 0;
      Done    : Boolean := False;
      Raw_Max, Matched_Max, Fused_Max, Raw_Yaw_Max, Aligned_Yaw_Max : Real := 0.0;
      Steps   : Natural := 0;
   begin
      Register_Feed;
      Robot.Odometry.Linear_Scale_Error := 0.03;
      Robot.Odometry.Angular_Bias := 0.003;
      Robot.GPS := (Enabled => True, Rate => 1.0, Std_Dev => 0.3);
      Sim.Initialize
        (Simulation.Map_Files.Load_World (Simulation.Map_Files.World_File ("office")), Seed => 5);
      Sim.Add_Robot (Robot, Start, Id, "robot1");
      Load_Checked ("tests/data/config/robot-closed-loop.xml", Config);
      N.Create (Config, 1, Clock'Unchecked_Access);
      Logging.Set_Console (False);
      N.Start (Run_Scheduler_Task => False);
      while not Done and then Sim.Clock < 200.0 loop
         Sim.Step (0.05);
         Steps := Steps + 1;
         if Sim.Odometry_Count (Id) /= Last_O then
            Last_O := Sim.Odometry_Count (Id);
            N.Database.Put ("odometric_pose", Values.Pose_Value'
                              (Data => Relative (Start, Sim.Latest_Odometry (Id).Pose)));
         end if;
         if Sim.GPS_Count (Id) /= Last_G then
            Last_G := Sim.GPS_Count (Id);
            N.Database.Put ("gps", ROS2.Message_Value'
                              (Message => RM.Fix_Message (Sim.Latest_GPS (Id))));
         end if;
         if Sim.Scan_Count (Id) /= Last_S then
            Last_S := Sim.Scan_Count (Id);
            N.Database.Put ("scan", ROS2.Message_Value'
                              (Message => RM.Scan_Message (Sim.Latest_Scan (Id), "base_link")));
            --  Errors against the ground truth, once every key has a value.
            if N.Database.Contains ("matched_world") and then N.Database.Contains ("fused_pose")
              and then N.Database.Contains ("aligned_pose")
            then
               declare
                  Truth : constant Pose := Sim.Ground_Truth (Id).Pose;
               begin
                  Raw_Max := Real'Max (Raw_Max, Position_Error (Pose_At (N, "pose"), Truth));
                  Matched_Max := Real'Max
                    (Matched_Max, Position_Error (Pose_At (N, "matched_world"), Truth));
                  Fused_Max := Real'Max
                    (Fused_Max, Position_Error (Pose_At (N, "fused_pose"), Truth));
                  Raw_Yaw_Max := Real'Max
                    (Raw_Yaw_Max, abs Normalize_Angle (Pose_At (N, "pose").Yaw - Truth.Yaw));
                  Aligned_Yaw_Max := Real'Max
                    (Aligned_Yaw_Max,
                     abs Normalize_Angle (Pose_At (N, "aligned_pose").Yaw - Truth.Yaw));
               end;
            end if;
         end if;
         if N.Database.Contains ("cmd_vel") then
            Sim.Set_Command
              (Id, RM.To_Twist (ROS2.Message_Value (N.Database.Get ("cmd_vel")).Message));
         end if;
         Clock.Advance (Ada.Real_Time.Milliseconds (50));
         while N.Scheduler.Next_Due <= Clock.Now loop
            N.Scheduler.Step;
         end loop;
         Done := N.Database.Contains ("done")
           and then Values.Boolean_Value (N.Database.Get ("done")).Data;
      end loop;
      declare
         Truth   : constant Pose := Sim.Ground_Truth (Id).Pose;
         Summary : constant String :=
           " (t=" & Img (Sim.Clock) & ", truth " & Img (Truth.X) & "," & Img (Truth.Y)
           & "; max position errors: odometry " & Img (Raw_Max) & ", scan matching "
           & Img (Matched_Max) & ", GPS fusion " & Img (Fused_Max) & "; max yaw errors: "
           & "odometry " & Img (Raw_Yaw_Max) & ", aligner " & Img (Aligned_Yaw_Max) & ")";
         Map     : constant ROSIDL.Dynamic.Message :=
           ROS2.Message_Value (N.Database.Get ("map")).Message;
         Status  : constant String := Values.String_Value (N.Database.Get ("status")).Image;
      begin
         N.Stop;
         Logging.Set_Console (True);
         Assert (Done, "goals not done within 200 s" & Summary);
         Assert (Sim.Collision_Count (Id) = 0, "collisions" & Summary);
         Assert (Values.Integer_Value (N.Database.Get ("completed")).Data = 2, "completed");
         Assert (Values.Real_Value (N.Database.Get ("progress")).Data = 1.0, "progress");
         Assert (Contains (Status, "done 2 / 2"), "status " & Status);
         Assert (Position_Error (Pose_At (N, "pose"), (7.0, 4.0, 0.0)) <= 0.3,
                 "the estimated pose is at the last goal" & Summary);
         Assert (Distance (Position (Truth), (7.0, 4.0)) < 1.5, "near the last goal" & Summary);
         Assert (Raw_Max > 0.3, "the odometry drifts" & Summary);
         Assert (Matched_Max < 0.6 * Raw_Max, "scan matching beats odometry" & Summary);
         Assert (Fused_Max < 1.0, "GPS fusion stays within 1 m" & Summary);
         Assert (Aligned_Yaw_Max < Raw_Yaw_Max, "the aligner corrects the heading" & Summary);
         Assert (ROSIDL.UInt32'(Map ("info")("width").As_UInt32) = 300, "map width");
         Assert (Values.Real_Value (N.Database.Get ("known")).Data > 0.05,
                 "the map knows some cells");
      end;
   end Closed_Loop_Reaches_Goals;

   procedure Executor_Takes_Task_Lists (Unused : in out Fixture) is
      Config : Configurations.Configuration;
      Clock  : aliased Clocks.Manual_Clock;
      N      : Component_Hosts.Component_Host;
   begin
      Start_Host (N, "tests/data/config/robot-closed-loop.xml", Config, Clock'Unchecked_Access);
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (0.0, 0.0, 0.0)));
      Assert (Pose_At (N, "pose") = (2.0, 10.0, 0.0), "transformer: start pose");
      Assert (Position (Pose_At (N, "goal")) = (8.0, 10.0), "first goal");
      Assert (Values.Integer_Value (N.Database.Get ("completed")).Data = 0, "none completed");
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (6.0, 0.1, 0.0)));
      Assert (Position (Pose_At (N, "goal")) = (7.0, 4.0), "second goal once at the first");
      Assert (Values.Real_Value (N.Database.Get ("progress")).Data = 0.5, "progress 1/2");
      --  A bad list is ignored; a good one replaces the list.
      N.Database.Put ("tasks", Values.To_Value ("1,2; 3"));
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (6.0, 0.1, 0.0)));
      Assert (Position (Pose_At (N, "goal")) = (7.0, 4.0), "bad task list ignored");
      N.Database.Put ("tasks", Values.To_Value ("3.0,10.0; 2.0,10.5"));
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (1.0, 0.0, 0.0)));
      Assert (Position (Pose_At (N, "goal")) = (2.0, 10.5), "new list: first goal reached");
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (0.0, 0.4, 0.0)));
      Assert (Values.Boolean_Value (N.Database.Get ("done")).Data, "new list done");
      Assert (Values.String_Value (N.Database.Get ("status")).Image = "done 2 / 2",
              "status " & Values.String_Value (N.Database.Get ("status")).Image);
      --  The transformer with a rotated frame.
      N.Stop;
      Logging.Set_Console (True);
   end Executor_Takes_Task_Lists;

   procedure Path_Costs_Callback (Unused : in out Fixture) is
      Config : Configurations.Configuration;
      Clock  : aliased Clocks.Manual_Clock;
      N      : Component_Hosts.Component_Host;
      Raised : Boolean := False;
   begin
      Start_Host (N, "tests/data/config/robot-closed-loop.xml", Config, Clock'Unchecked_Access);
      declare
         Straight : constant Real := Cost_Of ("Loop", (2.0, 10.0), (8.0, 10.0));
         Office   : constant Real := Cost_Of ("Loop", (2.0, 10.0), (7.0, 4.0));
         Wall     : constant Real := Cost_Of ("Loop", (2.0, 10.0), (6.0, 4.0));
      begin
         Assert (abs (Straight - 6.0) < 0.2, "along the corridor: " & Img (Straight));
         Assert (Office > Distance ((2.0, 10.0), (7.0, 4.0)) + 0.5,
                 "through the door, longer than straight: " & Img (Office));
         Assert (Wall = Real'Last, "inside a wall: unreachable");
      end;
      --  The component's outputs: a goal behind a door gives a waypoint
      --  on the way (not the goal itself) and its cost.
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (0.0, 0.0, 0.0)));
      N.Database.Put ("tasks", Values.To_Value ("7.0,4.0"));
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (0.0, 0.0, 0.0)));
      Assert (Position (Pose_At (N, "waypoint")) /= (7.0, 4.0), "a waypoint before the goal");
      Assert (Values.Real_Value (N.Database.Get ("goal_cost")).Data > 7.0, "cost output");
      N.Stop;
      Logging.Set_Console (True);
      begin
         declare
            C : constant Real := Cost_Of ("Loop", (2.0, 10.0), (8.0, 10.0));
         begin
            Assert (C < 0.0, "unreachable");
         end;
      exception
         when Program_Error =>
            Raised := True;
      end;
      Assert (Raised, "no planner once the component stopped");
   end Path_Costs_Callback;

   procedure Scan_Matching_Without_Laser (Unused : in out Fixture) is
      Config : Configurations.Configuration;
      Clock  : aliased Clocks.Manual_Clock;
      N      : Component_Hosts.Component_Host;
   begin
      Start_Host (N, "tests/data/config/scan-matching-fixed.xml", Config, Clock'Unchecked_Access);
      N.Database.Put ("odometric_pose", Values.Pose_Value'(Data => (2.0, 0.0, 0.5)));
      declare
         P : constant Pose := Pose_At (N, "corrected_pose");
      begin
         N.Stop;
         Logging.Set_Console (True);
         --  (1, -2, pi/2) (+) (2, 0, 0.5) = (1, 0, pi/2 + 0.5).
         Assert (abs (P.X - 1.0) < 1.0E-9 and then abs (P.Y - 0.0) < 1.0E-9
                 and then abs (P.Yaw - (Pi / 2.0 + 0.5)) < 1.0E-9,
                 "fixed correction: " & Img (P.X) & "," & Img (P.Y) & "," & Img (P.Yaw));
      end;
   end Scan_Matching_Without_Laser;

   procedure Bad_Goal_Option (Unused : in out Fixture) is
      Config : Configurations.Configuration;
   begin
      Configurations.Load ("tests/data/config/bad-robot-goals.xml", Config);
      Assert (Configurations.Error_Count (Config) = 1, "one error");
      declare
         Text : constant String := Configurations.Image (Config.Diagnostics.First_Element);
      begin
         Assert (Contains (Text, "bad-robot-goals.xml:4:32:")
                   and then Contains (Text, "goal 2")
                   and then Contains (Text, """x,y"""),
                 "positioned goal error: " & Text);
      end;
   end Bad_Goal_Option;

   procedure Message_Conversions (Unused : in out Fixture) is
      Scan : Sancta.Robot.Sensors.Laser_Scan (4);
      Goals : constant Sancta.Robot.Goal_Sequencers.Point_Array := RM.Parse_Goals (" 1,2 ;3.5, -4");
   begin
      Scan.Stamp := 12.25;
      Scan.Angle_Min := -1.5;
      Scan.Angle_Increment := 1.0;
      Scan.Angle_Max := 1.5;
      Scan.Range_Min := 0.1;
      Scan.Range_Max := 8.0;
      Scan.Ranges := [1.0, 2.5, 8.0, 0.5];
      declare
         Back : constant Sancta.Robot.Sensors.Laser_Scan :=
           RM.To_Scan (RM.Scan_Message (Scan, "laser"));
      begin
         Assert (Back.Beams = 4 and then Back.Ranges = Scan.Ranges, "ranges");
         Assert (Back.Stamp = 12.25 and then Back.Angle_Min = -1.5 and then Back.Range_Max = 8.0,
                 "scan fields");
      end;
      declare
         T : constant Sancta.Robot.Sensors.Twist :=
           RM.To_Twist (RM.Twist_Message ((0.25, -0.5)));
      begin
         Assert (T.Linear_X = 0.25 and then T.Angular_Z = -0.5, "twist");
      end;
      declare
         F : constant Sancta.Robot.Sensors.GPS_Fix :=
           RM.To_Fix (RM.Fix_Message ((Stamp => 3.0, Position => (1.5, -2.0), Std_Dev => 0.5)));
      begin
         Assert (F.Position = (1.5, -2.0) and then abs (F.Std_Dev - 0.5) < 1.0E-12
                 and then F.Stamp = 3.0, "fix");
      end;
      declare
         Frame : constant Sancta.Robot.Grids.Frame := ((1.0, 2.0), 0.5, 3, 2);
         Cells : constant Sancta.Robot.Mappers.Cell_Value_Array := [-1, 0, 100, 50, -1, 7];
         Msg   : constant ROSIDL.Dynamic.Message := RM.Grid_Message (Frame, Cells, 4.5, "map");
      begin
         Assert (ROSIDL.UInt32'(Msg ("info")("width").As_UInt32) = 3
                 and then ROSIDL.UInt32'(Msg ("info")("height").As_UInt32) = 2, "grid size");
         Assert (Msg ("data").Get_Int8_Array = [-1, 0, 100, 50, -1, 7], "grid data");
         Assert (ROSIDL.Float64'(Msg ("info")("origin")("position")("y").As_Float64) = 2.0,
                 "grid origin");
      end;
      Assert (Goals'Length = 2 and then Goals (1) = (1.0, 2.0) and then Goals (2) = (3.5, -4.0),
              "goals parsed");
      Assert (RM.Goals_Image (Goals) = "1.0,2.0;3.5,-4.0", RM.Goals_Image (Goals));
      Assert (RM.Parse_Goals ("  ")'Length = 0, "no goal");
      Assert (RM.Goals_Problem ("1,2;") /= "", "empty goal accepted");
      Assert (RM.Goals_Problem ("a,1") /= "", "letters accepted");
      Assert (RM.Goals_Problem ("1 2") /= "", "no comma accepted");
      Assert (RM.Goals_Problem ("1,2;3,1e400") /= "", "overflow accepted");
      Assert (Contains (RM.Goals_Problem ("1,2; x,3"), "goal 2"),
              RM.Goals_Problem ("1,2; x,3"));
   end Message_Conversions;

   procedure Robot_List_Lines (Unused : in out Fixture) is
      use Sancta.Simulation.Robot_Lists;
      L : Robot_List;

      function Error_Of (Line : String) return String is
         M : Robot_List := L;
      begin
         Parse_Line (Line, "robots.txt", 7, M);
         return "";
      exception
         when E : List_Error =>
            return Ada.Exceptions.Exception_Message (E);
      end Error_Of;
   begin
      Parse_Line ("robot1 1 2.5 -0.5 beams=180 fov=180 gps=on gps_std=0.2 odom_bias=0.01"
                  & " odom_angular_scale=0.02", "robots.txt", 1, L);
      Parse_Line ("   # a comment", "robots.txt", 2, L);
      Parse_Line ("", "robots.txt", 3, L);
      Assert (Natural (L.Length) = 1, "one robot");
      Assert (L (1).Start = (1.0, 2.5, -0.5), "start pose");
      Assert (L (1).Config.Laser.Beams = 180 and then abs (L (1).Config.Laser.Field_Of_View - Pi)
              < 1.0E-12, "laser keys");
      Assert (L (1).Config.GPS.Enabled and then L (1).Config.GPS.Std_Dev = 0.2, "gps keys");
      Assert (L (1).Config.Odometry.Angular_Bias = 0.01
              and then L (1).Config.Odometry.Angular_Scale_Error = 0.02, "odometry keys");
      Assert (Find (L, "robot1") = 1 and then Find (L, "robot2") = 0, "Find");
      Assert (Error_Of ("robot1 0 0 0") = "robots.txt:7:1: robot ""robot1"" is listed twice",
              Error_Of ("robot1 0 0 0"));
      Assert (Error_Of ("r2 0 0") = "robots.txt:7:7: expected the start yaw, found the end of"
              & " the line", Error_Of ("r2 0 0"));
      Assert (Ada.Strings.Fixed.Index (Error_Of ("r2 0 0 0 beams=0"), "robots.txt:7:16:") = 1,
              Error_Of ("r2 0 0 0 beams=0"));
      Assert (Contains (Error_Of ("r2 0 0 0 wheels=3"), "unknown key ""wheels"""),
              Error_Of ("r2 0 0 0 wheels=3"));
      Assert (Contains (Error_Of ("r2 0 0 0 radius=-1"), "invalid robot"),
              Error_Of ("r2 0 0 0 radius=-1"));
      Assert (Contains (Error_Of ("r-2 0 0 0"), "expected a robot name"),
              Error_Of ("r-2 0 0 0"));
      begin
         Load ("no/such/robots.txt", L);
         Assert (False, "missing file accepted");
      exception
         when E : List_Error =>
            Assert (Ada.Exceptions.Exception_Message (E)
                      = "no/such/robots.txt: cannot open the robot list",
                    Ada.Exceptions.Exception_Message (E));
      end;
   end Robot_List_Lines;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;

      procedure Add (Name : String; Test : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("robot components: " & Name, Test));
      end Add;
   begin
      Add ("message conversions and goal lists", Message_Conversions'Access);
      Add ("sancta-sim robot lists", Robot_List_Lines'Access);
      Add ("a bad goal list is a positioned configuration error", Bad_Goal_Option'Access);
      Add ("executor and transformer wiring, task lists", Executor_Takes_Task_Lists'Access);
      Add ("path_costs: cost callback and waypoints", Path_Costs_Callback'Access);
      Add ("scan_matching with no laser: the fixed correction",
           Scan_Matching_Without_Laser'Access);
      Add ("closed loop with a simulator: goals, localisation, map",
           Closed_Loop_Reaches_Goals'Access);
      return Result;
   end Suite;

end Sancta.Standard_Components.Navigation.Tests;
