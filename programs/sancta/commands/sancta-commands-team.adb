with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Sancta.Team.Agents;
with Sancta.Commands.Options;
with Sancta.Installation;
with Sancta.Simulation;
with Sancta.Commands.Team_Demos;
with Sancta.Team.Missions;

package body Sancta.Commands.Team is

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;

   procedure Usage is
   begin
      Put_Line ("usage: sancta team [MISSION.xml] [--method annealer|auctions] [--rate X]");
      Put_Line ("          [--kill ID | --no-kill] [--kill-at FRACTION] [--lease SECONDS]");
      Put_Line ("          [--max SECONDS] [--world FILE] [--out DIR] [--quiet] [--check]");
      Put_Line ("          [--cut-for SECONDS [--cut-at FRACTION]]");
      Put_Line ("A team mission in one process: the simulator driven in-process, each robot a");
      Put_Line ("team agent with its own DDS node; legs costed on straight lines; a robot is");
      Put_Line ("lost mid-mission; progress, a summary and the report as sancta demo.");
      Put_Line ("  MISSION.xml         the mission (default share/missions/office-team.xml)");
      Put_Line ("  --method M          annealer (default) or auctions");
      Put_Line ("  --rate X            simulated seconds per wall second (default 25)");
      Put_Line ("  --kill ID           the robot lost (default: the one with the most tasks left)");
      Put_Line ("  --no-kill           lose no robot");
      Put_Line ("  --kill-at FRACTION  lose it when this fraction of the tasks is done (0.3)");
      Put_Line ("  --lease SECONDS     presence lease: a silent member is lost after it (0.5,");
      Put_Line ("                      at least 0.1)");
      Put_Line ("  --max SECONDS       simulated time limit (default 1200)");
      Put_Line ("  --world FILE        another world than the mission's");
      Put_Line ("  --out DIR           the report there (default out/demo)");
      Put_Line ("  --quiet             no progress lines");
      Put_Line ("  --check             exit status 1 unless every task was done exactly once");
      Put_Line ("  --cut-for S         when FRACTION (--cut-at, default 0.5) of the tasks is");
      Put_Line ("                      done, cut one robot off the team for S wall-clock");
      Put_Line ("                      seconds, then measure the replicas' convergence");
   end Usage;

   function Default_Mission return String is (Installation.Share_File ("missions/office-team.xml"));

   procedure Run is
      Config : Sancta.Commands.Team_Demos.Demo_Config;
      Result : Sancta.Commands.Team_Demos.Demo_Result;

      procedure Take (A : String; I : in out Positive) is
      begin
         if Team_Demos.Take_Run_Option (A, I, Config.Run) then
            null;
         elsif A = "--method" then
            Config.How := Sancta.Team.Agents.Parse_Method (Options.Next_Value (I));
         elsif A = "--rate" then
            Config.Rate := Options.Number_Value (I);
            if Config.Rate <= 0.0 then
               raise Constraint_Error with "option --rate must be positive";
            end if;
         elsif A = "--lease" then
            Config.Lease := Duration (Options.Number_Value (I));
            if Config.Lease < 0.1 then
               raise Constraint_Error with "option --lease must be at least 0.1 s";
            end if;
         elsif A = "--cut-for" then
            Config.Cut_For := Duration (Options.Number_Value (I));
            if Config.Cut_For not in 0.0 .. 3600.0 then
               raise Constraint_Error with "option --cut-for: expected 0 .. 3600 seconds";
            end if;
         elsif A = "--cut-at" then
            Config.Cut_Fraction := Options.Number_Value (I);
            if Config.Cut_Fraction not in 0.0 .. 1.0 then
               raise Constraint_Error with "option --cut-at: expected a fraction in [0, 1]";
            end if;
         elsif A = "--world" then
            Config.World_File := To_Unbounded_String (Options.Next_Value (I));
         elsif A'Length > 0 and then A (A'First) = '-' then
            raise Constraint_Error with "unknown option " & A;
         else
            Config.Mission_File := To_Unbounded_String (A);
         end if;
      end Take;

      function Parse is new Options.Parse_Arguments (Usage, Take);
   begin
      Config.Mission_File := To_Unbounded_String (Default_Mission);
      if not Parse then
         return;
      end if;
      Sancta.Commands.Team_Demos.Run (Config, Result);
      Sancta.Commands.Team_Demos.Print_Summary (Result);
      if Config.Run.Check then
         if Sancta.Commands.Team_Demos.Check_Passed (Result) then
            Put_Line ("check: passed (every task done exactly once)");
         else
            Put_Line ("check: FAILED");
            Set_Exit_Status (Failure);
         end if;
      end if;
   exception
      when E : Sancta.Team.Missions.Format_Error | Sancta.Simulation.Format_Error =>
         --  The mission or its world is wrong (the message says where).
         Put_Line (Standard_Error, "sancta team: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (1);
      when E : Constraint_Error | Options.Usage_Error =>
         Put_Line (Standard_Error, "sancta team: " & Ada.Exceptions.Exception_Message (E)
                   & " (sancta team --help)");
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Team;
