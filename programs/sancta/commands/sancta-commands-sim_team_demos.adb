with Ada.Command_Line;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Vectors;
with Ada.Directories;
with Ada.Environment_Variables;
with Ada.Exceptions;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with GNAT.OS_Lib;
with RCL.Contexts;
with RCL.Nodes;
with RCL.Security;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Sancta.Standard_Components.Robot_Messages;
with Sancta.Geometry;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Values;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Rendering;
with Sancta.Simulation.Worlds;
with Sancta.Team.Agents;
with Sancta.Team.Missions;
with Sancta.Team.Plans;
with Sancta.Team.Security;

with Sancta.Team;
use Sancta.Team;  --  the team library's units by their short names (Agents, Plans, ...)

package body Sancta.Commands.Sim_Team_Demos is

   use Ada.Text_IO;
   use Sancta.Geometry;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;
   use type GNAT.OS_Lib.Process_Id;

   package Configurations renames Sancta.Runtime.Configurations;
   package Rendering renames Sancta.Simulation.Rendering;

   Max_Robots : constant := 50;
   --  Robot agents of one demo (each a process; the observer follows each
   --  robot's ground truth on a node of its own).

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function F1 (X : Long_Float) return String renames Team_Demos.F1;

   function Img (X : Real) return String is (Runtime.Values.Real_Image (Long_Float (X)));

   --  The configuration's view of the team ------------------------------------------------

   type Team_View is record
      Robots   : Missions.Robot_Vectors.Vector;
      --  The robot agents in the file's order, with their mission starts.
      Non_Robots : Missions.Robot_Vectors.Vector;
      --  The other agents (operator, ...): Id only.
      Mission  : Missions.Mission;
      World    : Unbounded_String;
      Team     : Unbounded_String := To_Unbounded_String ("team");
      Lease    : Duration := 1.0;
   end record;

   function Option
     (I : Configurations.Instance; Name : String; Default : String) return String is
     (if I.Options.Contains (Name) then I.Options.Element (Name) else Default);

   function Read_Team (Config : Sim_Demo_Config) return Team_View is
      File   : constant String := To_String (Config.Config_File);
      C      : Configurations.Configuration;
      Result : Team_View;
      Mission_File : Unbounded_String;
      Problems     : Unbounded_String;
   begin
      Configurations.Load (File, C, Config.Overrides);
      if Configurations.Error_Count (C) > 0 then
         for D of C.Diagnostics loop
            if Configurations."=" (D.Level, Configurations.Error) then
               Append (Problems, ASCII.LF & "  " & Configurations.Image (D));
            end if;
         end loop;
         raise Constraint_Error with File & ": the configuration has errors:"
           & To_String (Problems);
      end if;
      for A of C.Agents loop
         declare
            Is_Robot : Boolean := False;
         begin
            for I of A.Instances loop
               if I.Enabled and then To_String (I.Component) = "team_member" then
                  Is_Robot := True;
                  Result.Team := To_Unbounded_String (Option (I, "team", "team"));
                  Result.Lease := Duration'Value (Option (I, "lease", "1.0"));
               elsif I.Enabled and then To_String (I.Component) = "team_operator" then
                  Mission_File := To_Unbounded_String (Option (I, "mission", ""));
               elsif I.Enabled and then To_String (I.Component) = "path_costs"
                 and then Result.World = Null_Unbounded_String
               then
                  Result.World := To_Unbounded_String (Option (I, "world", ""));
               end if;
            end loop;
            if Is_Robot then
               Result.Robots.Append (Missions.Robot_Start'(Id => A.Id, others => <>));
            else
               Result.Non_Robots.Append (Missions.Robot_Start'(Id => A.Id, others => <>));
            end if;
         end;
      end loop;
      if Mission_File = Null_Unbounded_String then
         raise Constraint_Error with File & ": no agent has a team_operator component "
           & "(the operator publishing the mission)";
      elsif Natural (Result.Robots.Length) < 2 then
         raise Constraint_Error with File & ": the demo needs at least two robot agents "
           & "(agents with a team_member component)";
      elsif Natural (Result.Robots.Length) > Max_Robots then
         raise Constraint_Error with File & ": at most" & Max_Robots'Image & " robot agents";
      end if;
      Result.Mission := Missions.Read (To_String (Mission_File));
      for R of Result.Robots loop
         declare
            Found : Boolean := False;
         begin
            for S of Result.Mission.Robots loop
               if S.Id = R.Id then
                  R.Start := S.Start;
                  Found := True;
               end if;
            end loop;
            if not Found then
               raise Constraint_Error with To_String (Mission_File) & ": no <robot id="""
                 & To_String (R.Id) & """> start for robot agent " & To_String (R.Id)
                 & " of " & File;
            end if;
         end;
      end loop;
      if Result.World = Null_Unbounded_String then
         Result.World := Result.Mission.World;
      end if;
      if Sancta.Simulation.Map_Files.World_File (To_String (Result.World)) = "" then
         raise Constraint_Error with File & ": world '" & To_String (Result.World)
           & "' is neither a file nor a bundled world";
      end if;
      return Result;
   end Read_Team;

   --  Child processes ---------------------------------------------------------------------

   type Child is record
      Name   : Unbounded_String;
      Pid    : GNAT.OS_Lib.Process_Id := GNAT.OS_Lib.Invalid_Pid;
      Exited : Boolean := False;
   end record;

   package Child_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Child);
   --  By agent id ("sim" for the simulator).

   function Program (Config : Sim_Demo_Config; Name : String) return String is
      use GNAT.OS_Lib;
      Self : constant String := Ada.Command_Line.Command_Name;
   begin
      if Config.Bin_Dir /= Null_Unbounded_String then
         return To_String (Config.Bin_Dir) & "/" & Name;
      elsif Ada.Strings.Fixed.Index (Self, "/") > 0 then
         return Ada.Directories.Containing_Directory (Self) & "/" & Name;
      end if;
      declare
         Found : GNAT.OS_Lib.String_Access := Locate_Exec_On_Path (Name);
      begin
         if Found = null then
            raise Constraint_Error with "program " & Name & " not found on PATH";
         end if;
         return Result : constant String := Found.all do
            Free (Found);
         end return;
      end;
   end Program;

   package Text_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   function Spawn (Exe : String; Args : Text_Vectors.Vector; Log : String)
     return GNAT.OS_Lib.Process_Id
   is
      use GNAT.OS_Lib;
      List : Argument_List (1 .. Natural (Args.Length));
      Pid  : Process_Id;
   begin
      if not Is_Executable_File (Exe) then
         raise Constraint_Error with "program " & Exe & " not found (build it first)";
      end if;
      for K in List'Range loop
         List (K) := new String'(Args (K));
      end loop;
      Pid := Non_Blocking_Spawn (Exe, List, Output_File => Log, Err_To_Out => True);
      for A of List loop
         Free (A);
      end loop;
      if Pid = Invalid_Pid then
         raise Constraint_Error with "cannot start " & Exe & " (log " & Log & ")";
      end if;
      return Pid;
   end Spawn;

   procedure Reap (Children : in out Child_Maps.Map) is
      --  Notes the children that have exited (without blocking).
      Pid     : GNAT.OS_Lib.Process_Id;
      Success : Boolean;
   begin
      loop
         GNAT.OS_Lib.Non_Blocking_Wait_Process (Pid, Success);
         exit when Pid = GNAT.OS_Lib.Invalid_Pid;
         for C of Children loop
            if C.Pid = Pid then
               C.Exited := True;
            end if;
         end loop;
      end loop;
   end Reap;

   procedure Stop_All (Children : in out Child_Maps.Map) is
      Give_Up : constant Ada.Real_Time.Time :=
        Ada.Real_Time.Clock + Ada.Real_Time.Seconds (5);
   begin
      Reap (Children);
      for C of Children loop
         if not C.Exited then
            GNAT.OS_Lib.Kill (C.Pid, Hard_Kill => False);
         end if;
      end loop;
      while Ada.Real_Time.Clock < Give_Up
        and then (for some C of Children => not C.Exited)
      loop
         delay 0.05;
         Reap (Children);
      end loop;
      for C of Children loop
         if not C.Exited then
            GNAT.OS_Lib.Kill (C.Pid, Hard_Kill => True);
         end if;
      end loop;
      delay 0.1;
      Reap (Children);
   end Stop_All;

   --  The "did TASK" lines of a robot's log ----------------------------------------------

   package Count_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Natural);

   procedure Count_Log_Completions (Log : String; Counts : in out Count_Maps.Map) is
      F      : File_Type;
      Marker : constant String := "/team_member";
      Did    : constant String := "] did ";
   begin
      if not Ada.Directories.Exists (Log) then
         return;
      end if;
      Open (F, In_File, Log);
      while not End_Of_File (F) loop
         declare
            Line : constant String := Get_Line (F);
            M    : constant Natural := Ada.Strings.Fixed.Index (Line, Marker);
            D    : constant Natural := Ada.Strings.Fixed.Index (Line, Did);
         begin
            if M > 0 and then D > M and then D + Did'Length <= Line'Last then
               declare
                  Task_Id : constant String := Line (D + Did'Length .. Line'Last);
               begin
                  if Counts.Contains (Task_Id) then
                     Counts.Replace (Task_Id, Counts.Element (Task_Id) + 1);
                  else
                     Counts.Insert (Task_Id, 1);
                  end if;
               end;
            end if;
         end;
      end loop;
      Close (F);
   end Count_Log_Completions;

   --  Run -------------------------------------------------------------------------------------

   procedure Run (Config : Sim_Demo_Config; Result : out Team_Demos.Demo_Result) is
      View     : constant Team_View := Read_Team (Config);
      M        : Missions.Mission renames View.Mission;
      N        : constant Positive := Natural (View.Robots.Length);
      Dir      : constant String := To_String (Config.Run.Out_Dir);
      Log_Dir  : constant String := (if Dir = "" then "out/demo" else Dir);
      World_F  : constant String :=
        Sancta.Simulation.Map_Files.World_File (To_String (View.World));
      World    : constant Sancta.Simulation.Worlds.World :=
        Sancta.Simulation.Map_Files.Load_World (World_F);
      Children : Child_Maps.Map;
      Non_Robot_Ids : Unbounded_String;
      --  " + operator": the agents that are no robot, for the first line.

      function Robot_Id (R : Positive) return String is (To_String (View.Robots (R).Id));

      procedure Start_Agent (Id : String) is
         Args : Text_Vectors.Vector;
      begin
         Args.Append ("run");
         Args.Append (To_String (Config.Config_File));
         Args.Append ("--agent");
         Args.Append (Id);
         if Config.Sim_Time then
            Args.Append ("--sim-time");
         end if;
         for C in Config.Overrides.Iterate loop
            Args.Append ("--set");
            Args.Append (Runtime.Components.String_Maps.Key (C) & "="
                         & Runtime.Components.String_Maps.Element (C));
         end loop;
         if Config.Secure then
            Security.Set_Child_Enclave (Security.Enclave (To_String (View.Team), Id));
         end if;
         Children.Insert
           (Id, (To_Unbounded_String (Id),
                 Spawn (Program (Config, "sancta"), Args, Log_Dir & "/" & Id & ".log"),
                 False));
      end Start_Agent;

      procedure Secure_Team is
         --  The keystore (Log_Dir/keystore) and this process's settings.
         Writers         : Security.Id_List (1 .. Natural (View.Non_Robots.Length));
         Robot_Ids       : Security.Id_List (1 .. N + 2);
      begin
         for I in Writers'Range loop
            Writers (I) := View.Non_Robots (I).Id;
         end loop;
         for I in 1 .. N loop
            Robot_Ids (I) := View.Robots (I).Id;
         end loop;
         Robot_Ids (N + 1) := To_Unbounded_String ("demo_monitor");
         Robot_Ids (N + 2) := To_Unbounded_String ("view");  --  sancta-view (--view)
         Security.Create_Keystore (Log_Dir & "/keystore", To_String (View.Team),
                                   Task_Writers => Writers, Other_Nodes => Robot_Ids,
                                   Readers => [1 => To_Unbounded_String ("recorder")]);
         Security.Enable (Log_Dir & "/keystore");
         RCL.Security.Set_Enclave (Security.Enclave (To_String (View.Team), "demo_monitor"));
      end Secure_Team;

      procedure Start_View is
         --  Not a child to stop at the end: the window stays open.
         Display : constant Boolean :=
           Ada.Environment_Variables.Value ("DISPLAY", "") /= ""
           or else Ada.Environment_Variables.Value ("WAYLAND_DISPLAY", "") /= "";
         Args    : Text_Vectors.Vector;
         Pid     : GNAT.OS_Lib.Process_Id with Unreferenced;
      begin
         if not Display then
            Put_Line ("demo: --view: no display (DISPLAY unset), running without the live view");
            return;
         end if;
         Args.Append ("--world");
         Args.Append (To_String (View.World));
         Args.Append ("--team");
         Args.Append (To_String (View.Team));
         if Config.Secure then
            Security.Set_Child_Enclave (Security.Enclave (To_String (View.Team), "view"));
         end if;
         Pid := Spawn (Program (Config, "sancta-view"), Args, Log_Dir & "/view.log");
         Put_Line ("demo: live view started (sancta-view, log " & Log_Dir & "/view.log)");
      end Start_View;

      procedure Start_Recorder is
         Bag  : constant String := Dir & "/mission";
         Args : Text_Vectors.Vector;
      begin
         if Ada.Directories.Exists (Bag) then
            Ada.Directories.Delete_Tree (Bag);
         end if;
         Args.Append ("bag");
         Args.Append ("record");
         Args.Append ("-a");
         Args.Append ("-o");
         Args.Append (Bag);
         Args.Append ("--discovery-period");
         Args.Append ("0.3");
         if Config.Secure then
            --  Its enclave may read every topic and inject none.
            Security.Set_Child_Enclave (Security.Enclave (To_String (View.Team), "recorder"));
         end if;
         Children.Insert
           ("recorder", (To_Unbounded_String ("rclada"),
                         Spawn (Program (Config, "rclada"), Args, Log_Dir & "/recorder.log"),
                         False));
         Put_Line ("demo: recording every topic into " & Bag & " (rclada bag record -a)");
      end Start_Recorder;

      procedure Start_Processes is
         Args : Text_Vectors.Vector;
      begin
         Ada.Directories.Create_Path (Log_Dir);
         if Config.Secure then
            Secure_Team;
         end if;
         if Config.Record_Bag and then Dir /= "" then
            Start_Recorder;
         end if;
         if Config.Secure then
            Security.Set_Child_Enclave (Security.Simulator_Enclave);
         end if;
         Args.Append (To_String (View.World));
         for R of View.Robots loop
            Args.Append ("--robot");
            Args.Append (To_String (R.Id) & " " & Img (R.Start.X) & " " & Img (R.Start.Y) & " "
                         & Img (R.Start.Yaw));
         end loop;
         Args.Append ("--rate");
         Args.Append (Runtime.Values.Real_Image (Config.Rate));
         Args.Append ("--cmd-timeout");
         Args.Append ("0.5");
         Args.Append ("--quiet");
         Children.Insert
           ("sim", (To_Unbounded_String ("sancta-sim"),
                    Spawn (Program (Config, "sancta-sim"), Args, Log_Dir & "/sim.log"),
                    False));
         --  The robots first, the operator (which publishes the mission) last.
         for R of View.Robots loop
            Start_Agent (To_String (R.Id));
         end loop;
         for R of View.Non_Robots loop
            Start_Agent (To_String (R.Id));
         end loop;
         if Config.View then
            Start_View;
         end if;
         if Config.Secure then
            Security.Set_Child_Enclave ("");
         end if;
      end Start_Processes;
   begin
      Result := (others => <>);
      Result.Tasks_Total := Natural (M.Tasks.Length);
      if Config.Run.Kill and then Config.Run.Kill_Robot /= Null_Unbounded_String
        and then (for all R of View.Robots => R.Id /= Config.Run.Kill_Robot)
      then
         raise Constraint_Error with "--kill " & To_String (Config.Run.Kill_Robot)
           & ": no such robot agent in " & To_String (Config.Config_File);
      end if;
      Start_Processes;
      for R of View.Non_Robots loop
         Append (Non_Robot_Ids,
                 (if Length (Non_Robot_Ids) = 0 then " + " else ", ") & To_String (R.Id));
      end loop;
      Put_Line ("demo: " & To_String (Config.Config_File) & ": mission " & To_String (M.Name)
                & ":" & Result.Tasks_Total'Image & " tasks," & N'Image & " robot agents"
                & To_String (Non_Robot_Ids) & ", world "
                & To_String (View.World) & "; sancta-sim at " & F1 (Config.Rate)
                & "x, one process per agent (logs in " & Log_Dir & "/)");
      declare
         Node       : RCL.Nodes.Node := RCL.Nodes.Init ("sancta_demo");
         Monitor    : constant Agents.Agent_Access := Agents.Create
           ((Id => To_Unbounded_String ("demo_monitor"), Team => View.Team,
             Is_Robot => False, Lease => View.Lease, Verbose => False, others => <>));
         Sim_Clock  : Long_Float := 0.0;
         Here       : array (1 .. N) of Point;
         Has_Pose   : array (1 .. N) of Boolean := [others => False];
         Final_Pose : array (1 .. N) of Pose;
         Next_Rec   : array (1 .. N) of Long_Float := [others => 0.0];
         Next_Track : array (1 .. N) of Long_Float := [others => 0.0];
         Alive      : array (1 .. N) of Boolean := [others => True];
         Scene      : Rendering.Scene;
         Victim     : Natural := 0;
         Kill_Wall  : Ada.Real_Time.Time;
         Kill_Gen   : Natural := 0;
         Next_Print : Long_Float := 0.0;
         Start_Wall : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
         Seen       : Count_Maps.Map;
         Collisions : Natural := 0;
         Stop_Why   : Unbounded_String;

         procedure On_Truth (R : Positive; Msg : ROSIDL.Dynamic.Message) is
            Qz : constant Long_Float :=
              Long_Float (ROSIDL.Float64'(Msg ("pose")("orientation")("z").As_Float64));
            Qw : constant Long_Float :=
              Long_Float (ROSIDL.Float64'(Msg ("pose")("orientation")("w").As_Float64));
            P : constant Pose :=
              (Real (ROSIDL.Float64'(Msg ("pose")("position")("x").As_Float64)),
               Real (ROSIDL.Float64'(Msg ("pose")("position")("y").As_Float64)),
               (if Qz = 0.0 and then Qw = 0.0 then 0.0
                else Real (2.0 * Ada.Numerics.Long_Elementary_Functions.Arctan (Qz, Qw))));
            --  Yaw of a rotation about Z (sancta-sim's poses are planar).
            T : constant Long_Float :=
              Long_Float (Sancta.Standard_Components.Robot_Messages.Stamp_Of (Msg ("header")));
         begin
            if not Alive (R) then
               return;
            end if;
            Sim_Clock := Long_Float'Max (Sim_Clock, T);
            if Has_Pose (R) then
               Result.Robots (R).Distance := Result.Robots (R).Distance
                 + Long_Float (Distance (Here (R), Position (P)));
            end if;
            Here (R) := Position (P);
            Has_Pose (R) := True;
            Final_Pose (R) := P;
            if T >= Next_Rec (R) then
               Scene.Trajectories (R).Append (Here (R));
               Next_Rec (R) := T + 0.5;
            end if;
            if T >= Next_Track (R) then
               Result.Robots (R).Track.Append (Team_Demos.Track_Sample'(T, P));
               Next_Track (R) := T + 0.9 * Team_Demos.Track_Period;
            end if;
         end On_Truth;

         --  One node per robot for its ground truth: the callback knows the
         --  robot by its node's name (any number of robots).
         type Node_Access is access RCL.Nodes.Node;
         Truth_Nodes : array (1 .. N) of Node_Access;

         function Truth_Node_Name (R : Positive) return String is
           ("sancta_demo_truth_" & Robot_Id (R));

         procedure On_Any_Truth
           (Node : in out RCL.Nodes.Node'Class;
            Msg  : in out ROSIDL.Dynamic.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Info);
            Name : constant String := Node.Name;
         begin
            for R in 1 .. N loop
               if Name = Truth_Node_Name (R) then
                  On_Truth (R, Msg);
                  return;
               end if;
            end loop;
         end On_Any_Truth;

         procedure On_Event
           (Node : in out RCL.Nodes.Node'Class;
            Msg  : in out ROSIDL.Dynamic.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
            Text : constant String := Msg ("data").Get_String;
         begin
            if Text'Length >= 10 and then Text (Text'First .. Text'First + 9) = "collision "
            then
               Collisions := Collisions + 1;
               --  Said as it happens (the first ten), printable and at most
               --  100 characters: the text came over the network.
               if Collisions <= 10 then
                  declare
                     Shown : String := Text (Text'First .. Natural'Min (Text'Last,
                                                                        Text'First + 99));
                  begin
                     for C of Shown loop
                        if C not in ' ' .. '~' then
                           C := '?';
                        end if;
                     end loop;
                     Put_Line ("t=" & F1 (Sim_Clock) & " s (wall " & F1 (Long_Float
                               (Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Start_Wall)))
                               & ")  sancta-sim: " & Shown
                               & (if Collisions = 10 then "  (further ones only counted)"
                                  else ""));
                  end;
               end if;
            end if;
         end On_Event;

         function Index_Of (Id : String) return Natural is
         begin
            for R in 1 .. N loop
               if Robot_Id (R) = Id then
                  return R;
               end if;
            end loop;
            return 0;
         end Index_Of;

         function Done_Here (Task_Id : String) return Boolean is
           (Monitor.Database.Contains ("done/" & Task_Id));

         function Stamp return String is
           ("t=" & F1 (Sim_Clock) & " s (wall "
            & F1 (Long_Float (Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Start_Wall)))
            & ")  ");

         procedure Note_Completions is
         begin
            for T of M.Tasks loop
               declare
                  Id : constant String := To_String (T.Id);
               begin
                  if not Seen.Contains (Id) and then Done_Here (Id) then
                     declare
                        Who : constant String := Monitor.Database.Get_String ("done/" & Id);
                        R   : constant Natural := Index_Of (Who);
                     begin
                        Seen.Insert (Id, 1);
                        Result.Completions.Append
                          (Team_Demos.Completion'(T.Id, To_Unbounded_String (Who), Sim_Clock,
                                                  others => <>));
                        if R > 0 then
                           Result.Robots (R).Tasks := Result.Robots (R).Tasks + 1;
                        end if;
                        if Config.Run.Verbose then
                           Put_Line (Stamp & Who & " did " & Id & "  ("
                                     & Trim (Natural (Result.Completions.Length)) & "/"
                                     & Trim (Result.Tasks_Total) & ")");
                        end if;
                     end;
                  end if;
               end;
            end loop;
         end Note_Completions;

         function Choose_Victim return Positive is
            Best : Positive := 1;
            Most : Integer := -1;
            P    : constant Plans.Plan := Monitor.Adopted;
            S    : constant Plans.Snapshot := Monitor.Round;
         begin
            if Config.Run.Kill_Robot /= Null_Unbounded_String then
               if Index_Of (To_String (Config.Run.Kill_Robot)) = 0 then
                  raise Constraint_Error with "--kill " & To_String (Config.Run.Kill_Robot)
                    & ": no such robot agent in " & To_String (Config.Config_File);
               end if;
               return Index_Of (To_String (Config.Run.Kill_Robot));
            end if;
            for K in 1 .. Natural'Min (Natural (P.Tours.Length), Natural (S.Robots.Length)) loop
               declare
                  Left : Natural := 0;
               begin
                  for St of P.Tours (K) loop
                     if not Done_Here (To_String (St.Task_Id)) then
                        Left := Left + 1;
                     end if;
                  end loop;
                  if Left > Most and then Index_Of (To_String (S.Robots (K).Id)) /= 0 then
                     Most := Left;
                     Best := Index_Of (To_String (S.Robots (K).Id));
                  end if;
               end;
            end loop;
            return Best;
         end Choose_Victim;

         procedure Control (Command, Id : String) is
            --  A call of the simulator's control service (the first one
            --  waits for the service's discovery: done once at the start,
            --  with "list", so that the kill does not stall this loop).
            Support : constant ROSIDL.Typesupport.Service_Support :=
              ROSIDL.Typesupport.Get_Service_Support ("sancta_msgs", "SimControl");
            Request : constant ROSIDL.Dynamic.Message :=
              ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support (Support));
         begin
            Request ("command").Set_String (Command);
            Request ("name").Set_String (Id);
            declare
               Response : constant ROSIDL.Dynamic.Message :=
                 Node.Client_Call (Support, "/sancta_sim/control", Request, Timeout => 5.0);
            begin
               if not Response ("success").As_Bool then
                  Put_Line (Stamp & "sancta-sim: " & Command & " " & Id & ": "
                            & Response ("message").Get_String);
               end if;
            end;
         exception
            when E : others =>
               Put_Line (Stamp & "sancta-sim " & Command & " " & Id & " failed ("
                         & Ada.Exceptions.Exception_Message (E) & ")"
                         & (if Command = "kill" then "; the robot stops when its commands stop"
                            else ""));
         end Control;

         procedure Kill (R : Positive) is
            Id : constant String := Robot_Id (R);
         begin
            Victim := R;
            Kill_Gen := Monitor.Round.Generation;
            Result.Plan_Before := Monitor.Adopted;
            Result.Round_Before := Monitor.Round;
            Result.Orphans := Team_Demos.Unfinished
              (Result.Round_Before, Result.Plan_Before, Id, Done_Here'Access);
            GNAT.OS_Lib.Kill (Children (Id).Pid, Hard_Kill => True);
            Kill_Wall := Ada.Real_Time.Clock;
            Alive (R) := False;
            Result.Killed := To_Unbounded_String (Id);
            Result.Kill_Time := Sim_Clock;
            Result.Robots (R).Alive := False;
            Put_Line (Stamp & "** robot " & Id & ": its agent's process killed (SIGKILL), "
                      & Trim (Natural (Result.Orphans.Length)) & " of its tasks unfinished");
            Control ("kill", Id);
         end Kill;

         procedure Check_Replanned is
            S : constant Plans.Snapshot := Monitor.Round;
            P : constant Plans.Plan := Monitor.Adopted;
         begin
            if S.Generation > Kill_Gen and then P.Generation = S.Generation
              and then (for all R of S.Robots => To_String (R.Id) /= Robot_Id (Victim))
            then
               Result.Replanned := True;
               Result.Replan_Wall := Long_Float
                 (Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Kill_Wall));
               Result.Replan_Sim := Sim_Clock - Result.Kill_Time;
               Result.Plan_After := P;
               Result.Round_After := S;
               Put_Line (Stamp & "survivors re-planned " & Trim (Natural (S.Tasks.Length))
                         & " tasks among " & Trim (Natural (S.Robots.Length)) & " robots in "
                         & F1 (Result.Replan_Wall) & " s (wall, lease included)");
            end if;
         end Check_Replanned;

         procedure Print_Progress is
         begin
            Put (Stamp & "progress " & Trim (Natural (Result.Completions.Length)) & "/"
                 & Trim (Result.Tasks_Total) & " tasks done  round" & Monitor.Round.Generation'Image
                 & "  [ done per robot:");
            for R in 1 .. N loop
               Put (" " & Robot_Id (R) & ":" & Trim (Result.Robots (R).Tasks)
                    & (if Alive (R) then "" else " (lost)"));
            end loop;
            Put_Line (" ]");
         end Print_Progress;

      begin
         for R in 1 .. N loop
            Result.Robots.Append
              (Team_Demos.Robot_Summary'(Id => View.Robots (R).Id, others => <>));
            Scene.Trajectories.Append (Rendering.Point_Vectors.Empty_Vector);
            Here (R) := Position (View.Robots (R).Start);
            Final_Pose (R) := View.Robots (R).Start;
            Truth_Nodes (R) := new RCL.Nodes.Node'(RCL.Nodes.Init (Truth_Node_Name (R)));
            Truth_Nodes (R).Subscribe
              (ROSIDL.Typesupport.Get_Message_Support ("geometry_msgs", "PoseStamped"),
               "/" & Robot_Id (R) & "/ground_truth", On_Any_Truth'Access);
         end loop;
         Node.Subscribe
           (ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String"),
            "/sancta_sim/events", On_Event'Access);
         Control ("list", "");
         loop
            Node.Spin (During => 0.05);
            for T of Truth_Nodes loop
               T.Spin (During => 0.0);
            end loop;
            Reap (Children);
            Note_Completions;
            if Result.Planned_Total = 0.0 and then Monitor.Adopted.Generation > 0
              and then Monitor.Adopted.Generation = Monitor.Round.Generation
            then
               Team_Demos.Note_First_Plan (Result, Monitor.Round, Monitor.Adopted, World);
               Result.Plan_Time := Sim_Clock;
               Put_Line (Stamp & "first plan adopted (round" & Monitor.Round.Generation'Image
                         & "): total " & F1 (Result.Planned_Total) & " m, longest tour "
                         & F1 (Result.Planned_Makespan) & " m (" & F1 (Result.Grid_Total)
                         & " m, " & F1 (Result.Grid_Makespan) & " m along A* paths)");
            end if;
            if Config.Run.Kill and then Victim = 0 and then Result.Planned_Total > 0.0
              and then Long_Float (Result.Completions.Length)
                >= Config.Run.Kill_Fraction * Long_Float (Result.Tasks_Total)
              and then Monitor.Adopted.Generation = Monitor.Round.Generation
            then
               Kill (Choose_Victim);
            end if;
            if Result.Replanned then
               Team_Demos.Follow_Replan (Result, Monitor.Adopted);
            end if;
            if Victim /= 0 and then not Result.Replanned then
               Check_Replanned;
            end if;
            if Config.Run.Verbose and then Sim_Clock >= Next_Print then
               Next_Print := Sim_Clock + 20.0;
               Print_Progress;
            end if;
            if Monitor.All_Done and then Natural (Result.Completions.Length) = Result.Tasks_Total
            then
               Stop_Why := To_Unbounded_String ("every task is done");
            elsif RCL.Contexts.Is_Shutdown then
               Stop_Why := To_Unbounded_String ("interrupted");
            elsif Sim_Clock > Config.Run.Max_Seconds then
               Stop_Why := To_Unbounded_String ("simulated time limit reached");
            elsif Ada.Real_Time.Clock - Start_Wall
              > Ada.Real_Time.To_Time_Span (Config.Max_Wall)
            then
               Stop_Why := To_Unbounded_String ("wall-clock limit reached");
            elsif Children ("sim").Exited then
               Stop_Why := To_Unbounded_String ("sancta-sim exited (see " & Log_Dir
                                                & "/sim.log)");
            elsif (for all R in 1 .. N =>
                     Children (Robot_Id (R)).Exited or else R = Victim)
            then
               Stop_Why := To_Unbounded_String ("every robot agent exited (see the logs in "
                                                & Log_Dir & "/)");
            end if;
            exit when Stop_Why /= Null_Unbounded_String;
         end loop;
         Result.Makespan := Sim_Clock;
         Put_Line (Stamp & "stopping: " & To_String (Stop_Why));
         if Config.Run.Verbose then
            Print_Progress;
         end if;
         Result.Tasks_Done := Natural (Result.Completions.Length);
         Result.All_Done := Result.Tasks_Done = Result.Tasks_Total;
         Result.Rounds := Monitor.Round.Generation;
         Result.Collisions := Collisions;
         Monitor.Stop;
         Stop_All (Children);
         --  What each robot says it did (its own log): a task done twice,
         --  or done but never recorded in the team database, shows here.
         declare
            Counts : Count_Maps.Map;
         begin
            for R in 1 .. N loop
               Count_Log_Completions (Log_Dir & "/" & Robot_Id (R) & ".log", Counts);
            end loop;
            for C in Counts.Iterate loop
               if Count_Maps.Element (C) > 1 then
                  Result.Duplicates := Result.Duplicates + 1;
                  Put_Line ("demo: task " & Count_Maps.Key (C) & " done"
                            & Count_Maps.Element (C)'Image & " times (robots' logs)");
               end if;
            end loop;
         end;
         for R in 1 .. N loop
            Result.Executed_Total := Result.Executed_Total + Result.Robots (R).Distance;
            Scene.Robots.Append (Final_Pose (R));
            if not Alive (R) then
               Scene.Lost.Append (Position (Final_Pose (R)));
            end if;
         end loop;
         for T of M.Tasks loop
            Scene.Markers.Append
              (Rendering.Marker'
                 (T.Points (1),
                  T.Id & ">" & (if Seen.Contains (To_String (T.Id))
                                then Monitor.Database.Get_String ("done/" & To_String (T.Id))
                                else "?")));
         end loop;
         Team_Demos.Resolve_Orphans (Result);
         --  A task the robot finished just before its death (its record
         --  reaching this observer after the kill) was not unfinished.
         for K in reverse 1 .. Natural (Result.Orphans.Length) loop
            if Result.Killed /= Null_Unbounded_String
              and then Result.Orphans (K).Robot = Result.Killed
            then
               Result.Orphans.Delete (K);
            end if;
         end loop;
         Team_Demos.Note_Arrivals (Result, M.Tasks);
         if Dir /= "" then
            Team_Demos.Write_Report (Result, World, Scene, Dir);
         end if;
      exception
         when others =>
            --  Its worker task would keep the program alive ("sancta demo
            --  | head": our output closed while the robots run).
            Monitor.Stop;
            raise;
      end;
   exception
      when others =>
         Stop_All (Children);
         raise;
   end Run;

end Sancta.Commands.Sim_Team_Demos;
