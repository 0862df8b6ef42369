with Ada.Command_Line;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Sancta.Commands.Managed_Agents;
with Sancta.Commands.Options;
with Sancta.Standard_Components.All_Standard;
with Sancta.Logging;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Component_Hosts;
with Sancta.Standard_Components.ROS_Clocks;
with RCL.Clocks;
with Sancta.Runtime.Shutdown;

package body Sancta.Commands.Run is

   pragma Warnings (Off, Sancta.Standard_Components.All_Standard);
   --  Withed for its registrations only.

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   package Configurations renames Sancta.Runtime.Configurations;
   package Shutdown renames Sancta.Runtime.Shutdown;

   Usage_Text : constant String :=
     "usage: sancta run FILE (--agent ID | --all) [--set NAME=VALUE]... [--for SECONDS]"
     & ASCII.LF
     & "          [--debug] [--level SECTION=LEVEL]... [--log FILE] [--stats]" & ASCII.LF
     & "          [--sim-time] [--managed] [--ros-args -p use_sim_time:=true]";

   Help_Text : constant String :=
     Usage_Text & ASCII.LF
     & "Runs agents of a configuration (share/config/README.md) until Ctrl-C, a watchdog"
     & ASCII.LF & "abort or the time limit; checks it first as sancta check does." & ASCII.LF
     & "  FILE                   the configuration (.xml)" & ASCII.LF
     & "  --agent ID             run agent ID (repeatable)" & ASCII.LF
     & "  --all                  run every agent, each with its own database" & ASCII.LF
     & "  --set NAME=VALUE       give constant $NAME of FILE this value" & ASCII.LF
     & "  --for SECONDS          stop after SECONDS (default: until Ctrl-C)" & ASCII.LF
     & "  --debug                log at level debug (default info)" & ASCII.LF
     & "  --level SECTION=LEVEL  level of one log section, the name in brackets"
     & ASCII.LF
     & "                         (e.g. Ari/logger#4): debug, info, warning, error"
     & ASCII.LF
     & "  --log FILE             also append the log to FILE" & ASCII.LF
     & "  --stats                print each agent's statistics when it stops" & ASCII.LF
     & "  --sim-time             run on ROS time following /clock (e.g. sancta-sim)"
     & ASCII.LF
     & "                         instead of the wall clock" & ASCII.LF
     & "  --managed              each agent a lifecycle node /sancta_ID, created by"
     & ASCII.LF
     & "                         configure and started by activate (rclada lifecycle set)"
     & ASCII.LF
     & "  --ros-args ... [--]    ROS 2 arguments (-p use_sim_time:=true is --sim-time)";

   Clock : aliased Sancta.Runtime.Clocks.Real_Clock;

   Sim_Clock : aliased Sancta.Standard_Components.ROS_Clocks.ROS_Clock;
   --  With --sim-time (or use_sim_time:=true): the agents run on ROS time
   --  following /clock (a simulator's time), not on the wall clock.

   type Host_Access is access Sancta.Runtime.Component_Hosts.Component_Host;
   type Host_Array is array (Positive range <>) of Host_Access;

   procedure Run is
      File      : Unbounded_String;
      Agents    : Sancta.Runtime.Local_Databases.Key_Vectors.Vector;
      All_Of    : Boolean := False;
      Limit     : Duration := 0.0;
      Overrides : Sancta.Runtime.Components.String_Maps.Map;
      Config    : Configurations.Configuration;
      Stats     : Boolean := False;
      Sim_Time  : Boolean := RCL.Clocks.Sim_Time_Requested;
      Managed   : Boolean := False;
      I         : Positive := 2;

      procedure Set_Level (Text : String) is
         --  SECTION=LEVEL
         Equal : Natural := 0;
      begin
         for J in Text'Range loop
            if Text (J) = '=' then
               Equal := J;
            end if;
         end loop;
         if Equal <= Text'First then
            raise Options.Usage_Error with "--level expects SECTION=LEVEL, found '" & Text & "'";
         end if;
         Sancta.Logging.Set_Level
           (Text (Text'First .. Equal - 1),
            Sancta.Logging.Level'Value (Text (Equal + 1 .. Text'Last)));
      exception
         when Constraint_Error =>
            raise Options.Usage_Error with "--level: unknown level '"
              & Text (Equal + 1 .. Text'Last) & "' (debug, info, warning, error)";
      end Set_Level;

   begin
      while I <= Argument_Count loop
         declare
            A   : constant String := Argument (I);
            Has : constant Boolean := I < Argument_Count;
         begin
            if A in "--agent" | "--set" | "--for" | "--level" | "--log" and then not Has then
               raise Options.Usage_Error with "option " & A & " needs a value";
            elsif A = "--agent" and then Has then
               Agents.Append (Argument (I + 1));
               I := I + 1;
            elsif A = "--all" then
               All_Of := True;
            elsif A = "--set" and then Has then
               Options.Parse_Set (Argument (I + 1), Overrides);
               I := I + 1;
            elsif A = "--for" and then Has then
               begin
                  Limit := Duration'Value (Argument (I + 1));
                  if Limit < 0.0 then
                     raise Constraint_Error;  --  Not "forever": a mistake.
                  end if;
               exception
                  when Constraint_Error =>
                     raise Options.Usage_Error with "--for expects seconds (>= 0), found '"
                       & Argument (I + 1) & "'";
               end;
               I := I + 1;
            elsif A = "--debug" then
               Sancta.Logging.Set_Default_Level (Sancta.Logging.Debug);
            elsif A = "--stats" then
               Stats := True;
            elsif A = "--sim-time" then
               Sim_Time := True;
            elsif A = "--managed" then
               Managed := True;
            elsif A = "--ros-args" then
               --  ROS arguments (use_sim_time read by RCL.Clocks) up to "--".
               while I < Argument_Count and then Argument (I + 1) /= "--" loop
                  I := I + 1;
               end loop;
               I := I + 1;
            elsif A = "--level" and then Has then
               Set_Level (Argument (I + 1));
               I := I + 1;
            elsif A = "--log" and then Has then
               begin
                  Sancta.Logging.Open_File (Argument (I + 1));
               exception
                  when E : Ada.IO_Exceptions.Name_Error | Ada.IO_Exceptions.Use_Error =>
                     raise Options.Usage_Error with "--log: cannot create the file: "
                       & Ada.Exceptions.Exception_Message (E);
               end;
               I := I + 1;
            elsif A in "-h" | "--help" then
               Put_Line (Help_Text);
               return;
            elsif A'Length > 0 and then A (A'First) /= '-' and then Length (File) = 0 then
               File := To_Unbounded_String (A);
            else
               raise Options.Usage_Error with "unexpected argument '" & A & "'";
            end if;
         end;
         I := I + 1;
      end loop;
      if Length (File) = 0 then
         raise Options.Usage_Error with "missing configuration FILE";
      elsif All_Of = not Agents.Is_Empty then
         raise Options.Usage_Error with "give either --agent ID or --all";
      end if;

      Options.Load_Reporting (To_String (File), Config, Overrides);
      if Configurations.Error_Count (Config) > 0 then
         Put_Line (Standard_Error, "sancta run: configuration has errors; nothing started");
         Set_Exit_Status (Failure);
         return;
      end if;
      if All_Of then
         for A of Config.Agents loop
            Agents.Append (To_String (A.Id));
         end loop;
      end if;
      for Id of Agents loop
         if Configurations.Find_Agent (Config, Id) = 0 then
            Put_Line (Standard_Error, "sancta run: no agent '" & Id & "' in " & To_String (File)
                      & " (agents: " & Configurations.Agent_Ids (Config) & ")");
            Set_Exit_Status (Failure);
            return;
         end if;
      end loop;

      declare
         Hosts    : Host_Array (1 .. Natural (Agents.Length));
         Created  : Natural := 0;
         Attached : Boolean;
         Done     : Boolean;
         Time_Of  : Sancta.Runtime.Clocks.Clock_Access := Clock'Access;
      begin
         if Sim_Time then
            Sim_Clock.Follow_Clock_Topic ("sancta_clock");
            Time_Of := Sim_Clock'Access;
            Sancta.Logging.Log ("run", Sancta.Logging.Info, "on simulated time (/clock)");
         end if;
         Shutdown.Catch_Interrupt (Attached);
         if not Attached then
            Sancta.Logging.Log ("run", Sancta.Logging.Warning,
                                "Ctrl-C cannot be caught (reserved by the Ada runtime)");
         end if;
         if Managed then
            Managed_Agents.Run (Config, Agents, Time_Of, Limit);
            Sancta.Logging.Log ("run", Sancta.Logging.Info,
                                "stopping: " & (if Shutdown.Requested then Shutdown.Reason
                                                else "time limit reached"));
            Sim_Clock.Stop;
            if Shutdown.Failed then
               Set_Exit_Status (Failure);
            end if;
            return;
         end if;
         begin
            for Index in Hosts'Range loop
               Hosts (Index) := new Sancta.Runtime.Component_Hosts.Component_Host;
               Created := Index;
               Hosts (Index).Create
                 (Config, Configurations.Find_Agent (Config, Agents (Index)),
                  Time_Of);
            end loop;
            for N of Hosts loop
               N.Start;
            end loop;
         exception
            when E : Configuration_Error =>
               Put_Line (Standard_Error, Ada.Exceptions.Exception_Message (E));
               Shutdown.Request ("start-up failed", Failure => True);
         end;
         if not Shutdown.Requested then
            Shutdown.Wait ((if Limit > 0.0 then Limit else 1.0E9), Done);
         end if;
         Sancta.Logging.Log ("run", Sancta.Logging.Info,
                             "stopping: " & (if Shutdown.Requested then Shutdown.Reason
                                             else "time limit reached"));
         for Index in reverse 1 .. Created loop
            Hosts (Index).Stop;
            if Stats then
               Put_Line ("statistics of agent " & Hosts (Index).Id & ":");
               Put (Hosts (Index).Statistics);
            end if;
         end loop;
         Sim_Clock.Stop;
         if Shutdown.Failed then
            Set_Exit_Status (Failure);
         end if;
      exception
         when others =>
            Sim_Clock.Stop;  --  Its task would keep the program alive.
            raise;
      end;
   exception
      when E : Options.Usage_Error =>
         Put_Line (Standard_Error, "sancta run: " & Ada.Exceptions.Exception_Message (E));
         Put_Line (Standard_Error, Usage_Text);
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Run;
