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
      Put_Line ("  --cut-for S: when FRACTION (default 0.5) of the tasks is done, cut one robot");
      Put_Line ("  off the team for S wall-clock seconds, then measure the replicas' convergence");
   end Usage;

   function Default_Mission return String is (Installation.Share_File ("missions/office-team.xml"));

   procedure Run is
      Config : Sancta.Commands.Team_Demos.Demo_Config;
      Check  : Boolean := False;
      I      : Positive := 2;
      Result : Sancta.Commands.Team_Demos.Demo_Result;

      function Value return String is (Options.Next_Value (I));
      function Number (Text : String; Name : String) return Long_Float is
        (Options.Number (Name, Text));
   begin
      Config.Mission_File := To_Unbounded_String (Default_Mission);
      while I <= Argument_Count loop
         declare
            A : constant String := Argument (I);
         begin
            if A = "--help" or else A = "-h" then
               Usage;
               return;
            elsif A = "--method" then
               Config.How := Sancta.Team.Agents.Parse_Method (Value);
            elsif A = "--rate" then
               Config.Rate := Number (Value, A);
               if Config.Rate <= 0.0 then
                  raise Constraint_Error with "option --rate must be positive";
               end if;
            elsif A = "--kill" then
               Config.Kill_Robot := To_Unbounded_String (Value);
            elsif A = "--no-kill" then
               Config.Kill := False;
            elsif A = "--kill-at" then
               Config.Kill_Fraction := Number (Value, A);
               if Config.Kill_Fraction not in 0.0 .. 1.0 then
                  raise Constraint_Error with "option --kill-at: expected a fraction in [0, 1]";
               end if;
            elsif A = "--lease" then
               Config.Lease := Duration (Number (Value, A));
               if Config.Lease < 0.1 then
                  raise Constraint_Error with "option --lease must be at least 0.1 s";
               end if;
            elsif A = "--cut-for" then
               Config.Cut_For := Duration (Number (Value, A));
               if Config.Cut_For not in 0.0 .. 3600.0 then
                  raise Constraint_Error with "option --cut-for: expected 0 .. 3600 seconds";
               end if;
            elsif A = "--cut-at" then
               Config.Cut_Fraction := Number (Value, A);
               if Config.Cut_Fraction not in 0.0 .. 1.0 then
                  raise Constraint_Error with "option --cut-at: expected a fraction in [0, 1]";
               end if;
            elsif A = "--max" then
               Config.Max_Seconds := Number (Value, A);
            elsif A = "--world" then
               Config.World_File := To_Unbounded_String (Value);
            elsif A = "--out" then
               Config.Out_Dir := To_Unbounded_String (Value);
            elsif A = "--quiet" then
               Config.Verbose := False;
            elsif A = "--check" then
               Check := True;
            elsif A'Length > 0 and then A (A'First) = '-' then
               raise Constraint_Error with "unknown option " & A;
            else
               Config.Mission_File := To_Unbounded_String (A);
            end if;
         end;
         I := I + 1;
      end loop;
      Sancta.Commands.Team_Demos.Run (Config, Result);
      Sancta.Commands.Team_Demos.Print_Summary (Result);
      if Check then
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
         Put_Line (Standard_Error, "sancta team: " & Ada.Exceptions.Exception_Message (E));
         Usage;
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Team;
