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
      Put_Line ("  sancta-sim + one 'sancta run CONFIG --agent ID' process per agent;");
      Put_Line ("  default CONFIG: share/config/sim-team.xml; --set method=auctions");
      Put_Line ("  --view: also open the live view (sancta-view) when a display is set");
      Put_Line ("  the run is recorded into the bag OUT/mission (rclada bag record -a) unless");
      Put_Line ("  --no-record is given (under --secure in an enclave that may only read)");
      Put_Line ("  --secure: DDS-Security, a keystore in OUT/keystore, one enclave per process,");
      Put_Line ("  only the operator may publish tasks");
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
      when E : Constraint_Error | Options.Usage_Error | Sancta.Team.Missions.Format_Error =>
         Put_Line (Standard_Error, "sancta demo: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Demo;
