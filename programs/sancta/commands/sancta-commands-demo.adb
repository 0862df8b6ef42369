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
      Check  : Boolean := False;
      I      : Positive := 2;
      Result : Sancta.Commands.Team_Demos.Demo_Result;

      function Value return String is (Options.Next_Value (I));
      function Number (Text : String; Name : String) return Long_Float is
        (Options.Number (Name, Text));
   begin
      Config.Config_File := To_Unbounded_String (Default_Config);
      while I <= Argument_Count loop
         declare
            A : constant String := Argument (I);
         begin
            if A = "--help" or else A = "-h" then
               Usage;
               return;
            elsif A = "--set" then
               Options.Parse_Set (Value, Config.Overrides);
            elsif A = "--rate" then
               Config.Rate := Number (Value, A);
               if Config.Rate <= 0.0 or else Config.Rate > 100.0 then
                  raise Constraint_Error with "option --rate: expected a value in ]0, 100]";
               end if;
            elsif A = "--wall-clock" then
               Config.Sim_Time := False;
            elsif A = "--kill" then
               Config.Kill_Robot := To_Unbounded_String (Value);
            elsif A = "--no-kill" then
               Config.Kill := False;
            elsif A = "--kill-at" then
               Config.Kill_Fraction := Number (Value, A);
               if Config.Kill_Fraction not in 0.0 .. 1.0 then
                  raise Constraint_Error with "option --kill-at: expected a fraction in [0, 1]";
               end if;
            elsif A = "--max" then
               Config.Max_Seconds := Number (Value, A);
            elsif A = "--max-wall" then
               Config.Max_Wall := Duration (Number (Value, A));
            elsif A = "--out" then
               Config.Out_Dir := To_Unbounded_String (Value);
            elsif A = "--quiet" then
               Config.Verbose := False;
            elsif A = "--check" then
               Check := True;
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
         end;
         I := I + 1;
      end loop;
      if not Ada.Directories.Exists (To_String (Config.Config_File)) then
         raise Constraint_Error with To_String (Config.Config_File) & ": no such file";
      end if;
      Sancta.Commands.Sim_Team_Demos.Run (Config, Result);
      Sancta.Commands.Team_Demos.Print_Summary (Result);
      if Check then
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
