--  The "sancta" command: one program, a subcommand per job.
--     sancta plan FILE ...     task allocation (see sancta plan --help)
--     sancta check FILE        validate a configuration and show its wiring
--     sancta run FILE ...      run agents of a configuration
--     sancta team [MISSION]    the team mission demo over DDS
--     sancta team-agent ...    one team node per process
--     sancta demo [CONFIG]     the team demo, an agent process per robot
--  Each subcommand lives in a package Sancta.Commands.<Name> of its own.
--  Those that look up ROS 2 types first put SANCTA's interfaces on the
--  ROS 2 library's search path (Sancta.Team.Interface_Paths.Ensure).
pragma Unreserve_All_Interrupts;
--  Lets "sancta run" catch Ctrl-C (SIGINT) and stop its components cleanly.
with Ada.Command_Line;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Text_IO;
with Sancta.Commands.Check;
with Sancta.Commands.Demo;
with Sancta.Commands.Run;
with Sancta.Commands.Plan;
with Sancta.Commands.Team;
with Sancta.Commands.Team_Agent;
with Sancta.Team.Interface_Paths;

procedure Sancta_CLI is
   use Ada.Command_Line;
   use Ada.Text_IO;

   procedure Usage (To : File_Type := Standard_Output) is
      --  To: standard error when the usage answers a mistake.
   begin
      Put_Line (To, "usage: sancta COMMAND [ARGS...]");
      Put_Line (To, "commands:");
      --  One line per subcommand, in the order below.
      Put_Line (To, "  help             this text");
      Put_Line (To, "  check FILE       validate a configuration, print and draw its wiring");
      Put_Line (To, "  run FILE         run agents: --agent ID | --all [--set NAME=VALUE]"
                & " [--for S]");
      Put_Line (To, "  plan FILE ...    task allocation (sancta plan --help)");
      Put_Line (To, "  team [MISSION]   team mission demo over DDS (sancta team --help)");
      Put_Line (To, "  team-agent ...   one team node per process (sancta team-agent --help)");
      Put_Line (To, "  demo [CONFIG]    team demo: sancta-sim + an agent process per robot");
   end Usage;

   Command : constant String := (if Argument_Count = 0 then "" else Argument (1));
begin
   if Command = "" or else Command = "help" or else Command = "--help"
     or else Command = "-h"
   then
      if Command = "" then
         Usage (Standard_Error);
         Set_Exit_Status (2);  --  As for any other usage error.
      else
         Usage;
      end if;
   elsif Command = "check" then
      Sancta.Team.Interface_Paths.Ensure;
      Sancta.Commands.Check.Run;
   elsif Command = "run" then
      Sancta.Team.Interface_Paths.Ensure;
      Sancta.Commands.Run.Run;
   elsif Command = "plan" then
      Sancta.Commands.Plan.Run;
   elsif Command = "team" then
      Sancta.Commands.Team.Run;
   elsif Command = "team-agent" then
      Sancta.Commands.Team_Agent.Run;
   elsif Command = "demo" then
      Sancta.Team.Interface_Paths.Ensure;
      Sancta.Commands.Demo.Run;
   else
      Put_Line (Standard_Error, "sancta: unknown command '" & Command & "'");
      Usage (Standard_Error);
      Set_Exit_Status (Failure);
   end if;
exception
   when E : Ada.IO_Exceptions.Device_Error =>
      --  Our output was closed ("sancta plan --help | head"): done; other
      --  device errors are reported.
      if Ada.Exceptions.Exception_Message (E) /= "Broken pipe" then
         Put_Line (Standard_Error, "sancta: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
      end if;
   when E : others =>
      --  Last resort: a bug, reported in one line instead of a traceback.
      Put_Line (Standard_Error, "sancta: internal error: " & Ada.Exceptions.Exception_Name (E)
                & ": " & Ada.Exceptions.Exception_Message (E));
      Set_Exit_Status (70);
end Sancta_CLI;
