with Ada.Directories;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with AUnit.Assertions;
with Sancta.Standard_Components.All_Standard;
with Sancta.Geometry;
with Sancta.Logging;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Component_Hosts;
with Sancta.Runtime.Shutdown;
with Sancta.Runtime.Tasks;
with Sancta.Runtime.Values;
with Suite_Support; use Suite_Support;

package body Sancta.Standard_Components.Tests is

   pragma Warnings (Off, Sancta.Standard_Components.All_Standard);

   use AUnit.Assertions;
   use Ada.Strings.Unbounded;
   use Sancta.Runtime;
   use type Ada.Real_Time.Time;
   use type Sancta.Geometry.Real;
   package RC renames Sancta.Runtime.Components;

   function File_Text (Name : String) return String is
      F      : Ada.Text_IO.File_Type;
      Result : Unbounded_String;
   begin
      Ada.Text_IO.Open (F, Ada.Text_IO.In_File, Name);
      while not Ada.Text_IO.End_Of_File (F) loop
         Append (Result, Ada.Text_IO.Get_Line (F) & "|");
      end loop;
      Ada.Text_IO.Close (F);
      return To_String (Result);
   end File_Text;

   procedure Load_Checked
     (File : String; Config : out Configurations.Configuration;
      Overrides : RC.String_Maps.Map := RC.String_Maps.Empty_Map) is
   begin
      Configurations.Load (File, Config, Overrides);
      if Configurations.Error_Count (Config) > 0 then
         Assert (False, File & ": " & Configurations.Image (Config.Diagnostics.First_Element));
      end if;
   end Load_Checked;

   procedure Run_Until (N : in out Component_Hosts.Component_Host; Seconds : Duration) is
   begin
      while N.Scheduler.Next_Due <= Clocks.Epoch + Ada.Real_Time.To_Time_Span (Seconds) loop
         N.Scheduler.Step;
      end loop;
   end Run_Until;

   function Real_At (N : in out Component_Hosts.Component_Host; Key : String) return Long_Float is
     (Values.Real_Value (N.Database.Get (Key)).Data);

   procedure Plumbing_And_Logs (Unused : in out Fixture) is
      Config : Configurations.Configuration;
      Clock  : aliased Clocks.Manual_Clock;
      N      : Component_Hosts.Component_Host;
      Prefix : constant String := "out/test/plumbing";
   begin
      Ada.Directories.Create_Path ("out/test");
      Load_Checked ("tests/data/config/good-plumbing.xml", Config);
      N.Create (Config, 1, Clock'Unchecked_Access);
      Logging.Set_Console (False);
      N.Start (Run_Scheduler_Task => False);
      Run_Until (N, 1.25);
      Assert (Real_At (N, "copied") = 1.5, "copy");
      Assert (Real_At (N, "merged") = -2.0, "merge: the last stored input");
      Assert (Real_At (N, "switched") = 1.5, "switch: input a selected");
      Assert (Values.Boolean_Value (N.Database.Get ("in_a_stale")).Data,
              "watchdog alarm after 1.25 s without in_a");
      N.Database.Put ("in_a", Values.Real_Value'(Data => 3.0));
      Assert (not Values.Boolean_Value (N.Database.Get ("in_a_stale")).Data, "alarm cleared");
      Assert (Real_At (N, "switched") = 3.0, "switch forwards a");
      N.Database.Put ("choice", Values.To_Value ("b"));
      Assert (Real_At (N, "switched") = -2.0, "switch to b forwards b's current value");
      N.Database.Put ("in_a", Values.Real_Value'(Data => 4.0));
      Assert (Real_At (N, "switched") = -2.0, "a no longer forwarded");
      N.Stop;
      Logging.Set_Console (True);
      Assert (File_Text (Prefix & "-events.csv") =
                "time,key,value|0.0,copied,1.5|0.0,merged,1.5|0.0,merged,-2.0|"
                & "1.25,copied,3.0|1.25,merged,3.0|1.25,copied,4.0|1.25,merged,4.0|",
              "events: " & File_Text (Prefix & "-events.csv"));
      Assert (File_Text (Prefix & "-periodic.jsonl") =
                "{""time"": 0.0, ""copied"": 1.5, ""switched"": 1.5}|"
                & "{""time"": 0.5, ""copied"": 1.5, ""switched"": 1.5}|"
                & "{""time"": 1.0, ""copied"": 1.5, ""switched"": 1.5}|",
              "periodic: " & File_Text (Prefix & "-periodic.jsonl"));
      Assert (File_Text (Prefix & "-alarm.csv") =
                "time,key,value|1.25,in_a_stale,true|1.25,in_a_stale,false|",
              "alarm: " & File_Text (Prefix & "-alarm.csv"));
   end Plumbing_And_Logs;

   procedure Watchdog_Abort (Unused : in out Fixture) is
      Config    : Configurations.Configuration;
      Overrides : RC.String_Maps.Map;
   begin
      for Feed in Boolean loop
         Overrides.Include ("feed", (if Feed then "0.1" else "0"));
         --  A heartbeat every 0.1 s, or once only.
         Load_Checked ("tests/data/config/good-watchdog-abort.xml", Config, Overrides);
         declare
            Clock : aliased Clocks.Manual_Clock;
            N     : Component_Hosts.Component_Host;
         begin
            Shutdown.Reset;
            N.Create (Config, 1, Clock'Unchecked_Access);
            Logging.Set_Console (False);
            N.Start (Run_Scheduler_Task => False);
            Run_Until (N, 2.0);
            N.Stop;
            Logging.Set_Console (True);
            Assert (Shutdown.Requested = not Feed,
                    "abort requested only without heartbeat (feed=" & Feed'Image & ")");
            if not Feed then
               Assert (Shutdown.Failed, "abort is a failure");
               Assert (Ada.Strings.Fixed.Index (Shutdown.Reason, "watchdog Ari/watchdog#2") = 1,
                       Shutdown.Reason);
            end if;
            Shutdown.Reset;
         end;
      end loop;
   end Watchdog_Abort;

   procedure Transform (Unused : in out Fixture) is
      Config : Configurations.Configuration;
      Clock  : aliased Clocks.Manual_Clock;
      N      : Component_Hosts.Component_Host;
   begin
      Load_Checked ("tests/data/config/good-transform.xml", Config);
      N.Create (Config, 1, Clock'Unchecked_Access);
      Logging.Set_Console (False);
      N.Start (Run_Scheduler_Task => False);
      N.Scheduler.Step;
      declare
         Goal : constant Values.Pose_Value := Values.Pose_Value (N.Database.Get ("goal"));
      begin
         N.Stop;
         Logging.Set_Console (True);
         Assert (abs (Goal.Data.X - 1.0) < 1.0E-9 and then abs (Goal.Data.Y - 3.0) < 1.0E-9
                 and then abs (Goal.Data.Yaw - 1.5707963267948966) < 1.0E-9, Goal.Image);
      end;
   end Transform;

   --  A failed Start is retried after retry_after (on_error="retry").
   procedure Start_Retry (Unused : in out Fixture) is
      Config    : Configurations.Configuration;
      Clock     : aliased Clocks.Manual_Clock;
      N         : Component_Hosts.Component_Host;
      Overrides : RC.String_Maps.Map;
      Dir       : constant String := "out/test/start-retry";
      Logger    : RC.Component_Access;
   begin
      if Ada.Directories.Exists (Dir) then
         Ada.Directories.Delete_Tree (Dir);
      end if;
      Overrides.Include ("dir", Dir);
      Load_Checked ("tests/data/config/good-start-retry.xml", Config, Overrides);
      N.Create (Config, 1, Clock'Unchecked_Access);
      Logger := N.Find ("logger#2");
      Logging.Set_Console (False);
      --  A folder where the log file should be: the logger cannot create it
      --  (it makes missing folders, so a missing one would not do).
      Ada.Directories.Create_Path (Dir & "/x.csv");
      N.Start (Run_Scheduler_Task => False);
      Run_Until (N, 0.25);
      Assert (not Logger.Started and then Logger.Failures = 1, "first Start failed");
      Ada.Directories.Delete_Directory (Dir & "/x.csv");
      Run_Until (N, 0.75);
      N.Stop;
      Logging.Set_Console (True);
      Assert (Logger.Started and then Logger.Failures = 1, "Start retried at 0.5 s");
      --  Logged times count from the logger's (successful) start at 0.5 s;
      --  it was queued before the value's call due at 0.5 s.
      Assert (File_Text (Dir & "/x.csv") = "time,key,value|0.0,x,1.5|0.25,x,1.5|",
              File_Text (Dir & "/x.csv"));
   end Start_Retry;

   --  An asynchronous component whose task dies of an exception.
   type Async is new RC.Component with null record;

   overriding procedure Start (This : in out Async);

   task type Worker is
      entry Go;
   end Worker;

   type Worker_Access is access Worker;

   task body Worker is
   begin
      accept Go;
      raise Program_Error with "worker gave up";
   end Worker;

   W : Worker_Access;

   overriding procedure Start (This : in out Async) is
   begin
      W := new Worker;
      Tasks.Watch (W'Identity, This.Name);
      W.Go;
   end Start;

   procedure Task_Death (Unused : in out Fixture) is
      Clock  : aliased Clocks.Manual_Clock;
      A      : Async;
      Before : constant Natural := Tasks.Abnormal_Ends;
   begin
      A.Initialize ((Instance_Name => To_Unbounded_String ("async#1"),
                     Clock => Clock'Unchecked_Access, others => <>));
      A.Start;
      for I in 1 .. 500 loop
         exit when W'Terminated;
         delay 0.01;
      end loop;
      Assert (W'Terminated, "the worker ended");
      Logging.Set_Console (False);
      Tasks.Report_Ended;
      Logging.Set_Console (True);
      Assert (Tasks.Abnormal_Ends = Before + 1, "abnormal end counted");
      Assert (Ada.Strings.Fixed.Index
                (Logging.Last_Message,
                 "task of async#1 died of an unhandled exception: PROGRAM_ERROR: worker gave up")
              = 1, Logging.Last_Message);
   end Task_Death;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("components: copy, merge, switch, logger, watchdog alarm",
                                      Plumbing_And_Logs'Access));
      Result.Add_Test (Caller.Create ("components: watchdog abort", Watchdog_Abort'Access));
      Result.Add_Test (Caller.Create ("components: transform", Transform'Access));
      Result.Add_Test (Caller.Create ("components: a failed Start is retried",
                                      Start_Retry'Access));
      Result.Add_Test (Caller.Create ("components: asynchronous task death reported",
                                      Task_Death'Access));
      return Result;
   end Suite;

end Sancta.Standard_Components.Tests;
