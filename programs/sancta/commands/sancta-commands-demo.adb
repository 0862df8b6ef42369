with Ada.Command_Line;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Sancta.Commands.Options;
with Sancta.Installation;
with Sancta.Commands.Team_Demos;
with Sancta.Team.Missions;
with Sancta.Commands.Sim_Team_Demos;

package body Sancta.Commands.Demo is

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;

   procedure Usage is
   begin
      Put_Line ("usage: sancta demo [CONFIG.xml] [--set NAME=VALUE]... [--rate X] [--wall-clock]");
      Put_Line ("          [--kill ID | --no-kill] [--kill-at FRACTION] [--max SECONDS]");
      Put_Line ("          [--max-wall SECONDS] [--out DIR] [--quiet] [--check] [--view]");
      Put_Line ("          [--secure] [--no-record]");
      Put_Line ("The team demo (make run): sancta-sim and one 'sancta run CONFIG --agent ID");
      Put_Line ("--sim-time' process per agent; a robot's process is killed mid-mission; this");
      Put_Line ("command observes over DDS, prints progress and a summary, writes the report.");
      Put_Line ("  CONFIG.xml          the team (default share/config/sim-team.xml)");
      Put_Line ("  --set NAME=VALUE    give constant $NAME of CONFIG this value in every agent");
      Put_Line ("                      (e.g. method=auctions, costs=straight)");
      Put_Line ("  --rate X            simulated seconds per wall second, at most 100 (4)");
      Put_Line ("  --wall-clock        the agents run on the wall clock, not sancta-sim's /clock");
      Put_Line ("  --kill ID           the robot whose process is killed (default: the one with");
      Put_Line ("                      the most tasks left at that moment)");
      Put_Line ("  --no-kill           kill no robot");
      Put_Line ("  --kill-at FRACTION  kill when this fraction of the tasks is done (0.25)");
      Put_Line ("  --max SECONDS       simulated time limit (default 1200)");
      Put_Line ("  --max-wall SECONDS  wall-clock time limit (default 900)");
      Put_Line ("  --out DIR           report, logs and bag there (default out/demo)");
      Put_Line ("  --quiet             no progress lines");
      Put_Line ("  --check             exit status 1 unless every task was done exactly once");
      Put_Line ("  --view              also open the live view (sancta-view) if there is a");
      Put_Line ("                      display");
      Put_Line ("  --secure            DDS-Security: a keystore in DIR/keystore, one enclave per");
      Put_Line ("                      process, only the operator may publish tasks");
      Put_Line ("  --no-record         do not record the bag DIR/mission (rclada bag record -a;");
      Put_Line ("                      under --secure in an enclave that may only read)");
   end Usage;

   function Default_Config return String is (Installation.Share_File ("config/sim-team.xml"));

   procedure Run is
      Config : Sancta.Commands.Sim_Team_Demos.Sim_Demo_Config;
      Result : Sancta.Commands.Team_Demos.Demo_Result;

      procedure Take (A : String; I : in out Positive) is
      begin
         if Team_Demos.Take_Run_Option (A, I, Config.Run) then
            null;
         elsif A = "--set" then
            Options.Parse_Set (Options.Next_Value (I), Config.Overrides);
         elsif A = "--rate" then
            Config.Rate := Options.Number_Value (I);
            if Config.Rate <= 0.0 or else Config.Rate > 100.0 then
               raise Constraint_Error with "option --rate: expected a value in ]0, 100]";
            end if;
         elsif A = "--wall-clock" then
            Config.Sim_Time := False;
         elsif A = "--max-wall" then
            Config.Max_Wall := Duration (Options.Number_Value (I));
         elsif A = "--secure" then
            Config.Secure := True;
         elsif A = "--view" then
            Config.View := True;
         elsif A = "--no-record" then
            Config.Record_Bag := False;
         elsif A'Length > 0 and then A (A'First) = '-' then
            raise Constraint_Error with "unknown option " & A;
         else
            Config.Config_File := To_Unbounded_String (A);
         end if;
      end Take;

      function Parse is new Options.Parse_Arguments (Usage, Take);
   begin
      Config.Config_File := To_Unbounded_String (Default_Config);
      if not Parse then
         return;
      end if;
      if not Ada.Directories.Exists (To_String (Config.Config_File)) then
         raise Constraint_Error with To_String (Config.Config_File) & ": no such file";
      end if;
      Sancta.Commands.Sim_Team_Demos.Run (Config, Result);
      Sancta.Commands.Team_Demos.Print_Summary (Result);
      declare
         Dir     : constant String := To_String (Config.Run.Out_Dir);
         Log_Dir : constant String := (if Dir = "" then "out/demo" else Dir);
      begin
         --  Where everything is (the report's line is printed above).
         Put_Line ("logs: " & Log_Dir & "/{sim,operator,<robot>"
                   & (if Config.Record_Bag and then Dir /= "" then ",recorder" else "")
                   & (if Config.View then ",view" else "") & "}.log"
                   & (if Config.Record_Bag and then Dir /= ""
                      then "; bag: " & Dir & "/mission (rclada bag info " & Dir
                           & "/mission; rclada bag play " & Dir & "/mission --clock)"
                      else ""));
      end;
      if Config.Run.Check then
         if Sancta.Commands.Team_Demos.Check_Passed (Result) then
            Put_Line ("check: passed (every task done exactly once"
                      & (if Result.Killed = Null_Unbounded_String then ")"
                         else "; the lost robot's unfinished tasks done by survivors)"));
         else
            Put_Line ("check: FAILED");
            Set_Exit_Status (Failure);
         end if;
      elsif not Result.All_Done then
         Set_Exit_Status (Failure);
      end if;
   exception
      when E : Sancta.Team.Missions.Format_Error =>
         Put_Line (Standard_Error, "sancta demo: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (2);
      when E : Constraint_Error | Options.Usage_Error =>
         Put_Line (Standard_Error, "sancta demo: " & Ada.Exceptions.Exception_Message (E)
                   & " (sancta demo --help)");
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Demo;
