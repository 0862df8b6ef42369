with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Hash;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with RCL.Contexts;
with Sancta.Commands.Options;
with Sancta.Geometry;
with Sancta.Team.Agents;
with Sancta.Team.Missions;
with Sancta.Team.Plans;

package body Sancta.Commands.Team_Agent is

   use Ada.Command_Line;
   use Ada.Real_Time;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   use Sancta.Geometry;
   use Sancta.Team;

   procedure Usage is
   begin
      Put_Line ("usage: sancta team-agent --id ID --x X --y Y [--speed M/S] [--rate X]");
      Put_Line ("          [--team NAME] [--method annealer|auctions] [--lease S] [--for S]");
      Put_Line ("          [--linger S]");
      Put_Line ("       sancta team-agent --operator MISSION.xml [--team NAME] [--lease S]");
      Put_Line ("          [--for S] [--linger S]");
      Put_Line ("One team node in this process (one per host or network namespace): a robot");
      Put_Line ("moving in straight lines to its tasks, or the operator publishing a mission.");
      Put_Line ("  --id ID             the robot's id");
      Put_Line ("  --x X, --y Y        its start (m)");
      Put_Line ("  --speed M/S         its speed (default 1)");
      Put_Line ("  --rate X            time runs X times faster for its motion (default 10)");
      Put_Line ("  --operator MISSION  be the operator and publish this mission");
      Put_Line ("  --team NAME         the team's topics /sancta/NAME/... (default team)");
      Put_Line ("  --method M          annealer (default) or auctions");
      Put_Line ("  --lease S           presence lease, at least 0.1 (default 1)");
      Put_Line ("  --for S             stop after S seconds (default 120)");
      Put_Line ("  --linger S          when the mission is done, stay on the team S seconds");
      Put_Line ("                      (still receiving), then print 'database: N keys,");
      Put_Line ("                      digest H' (convergence tests)");
   end Usage;

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   procedure Run is
      Config   : Agents.Agent_Config;
      Mission  : Unbounded_String;
      X, Y     : Real := 0.0;
      Speed    : Real := 1.0;
      Rate     : Real := 10.0;
      Run_For  : Duration := 120.0;
      Linger   : Duration := 0.0;

      procedure Take (A : String; I : in out Positive) is
         function Value return String is (Options.Next_Value (I));
         function Number return Real is (Real (Options.Number_Value (I)));
      begin
         if A = "--id" then
            Config.Id := To_Unbounded_String (Value);
         elsif A = "--operator" then
            Mission := To_Unbounded_String (Value);
            Config.Id := To_Unbounded_String ("operator");
            Config.Is_Robot := False;
         elsif A = "--x" then
            X := Number;
         elsif A = "--y" then
            Y := Number;
         elsif A = "--speed" then
            Speed := Number;
         elsif A = "--rate" then
            Rate := Number;
         elsif A = "--team" then
            Config.Team := To_Unbounded_String (Value);
         elsif A = "--method" then
            Config.How := Agents.Parse_Method (Value);
         elsif A = "--lease" then
            Config.Lease := Duration (Number);
         elsif A = "--for" then
            Run_For := Duration (Number);
         elsif A = "--linger" then
            Linger := Duration (Number);
            if Linger not in 0.0 .. 3600.0 then
               raise Constraint_Error with "--linger: expected 0 .. 3600 seconds";
            end if;
         else
            raise Constraint_Error with "unknown option " & A;
         end if;
      end Take;

      function Parse is new Options.Parse_Arguments (Usage, Take);
   begin
      Config.Verbose := True;
      if not Parse then
         return;
      end if;
      if Config.Id = Null_Unbounded_String then
         raise Constraint_Error with "--id or --operator is required";
      elsif Speed <= 0.0 or else Rate <= 0.0 or else Config.Lease < 0.1 then
         raise Constraint_Error with "--speed and --rate must be positive, --lease >= 0.1";
      end if;
      declare
         M      : constant Missions.Mission :=
           (if Config.Is_Robot then (others => <>) else Missions.Read (To_String (Mission)));
         Agent  : constant Agents.Agent_Access := Agents.Create (Config);
         Here   : Point := (X, Y);
         Period : constant Duration := 0.05;
         Next   : Time := Clock;
         Stop   : constant Time := Clock + To_Time_Span (Run_For);

         procedure Finish is
            --  Lingers (still a member, no more writes of its own), then
            --  prints its replica's summary and leaves the team.
         begin
            if Linger > 0.0 then
               delay Linger;
               Put_Line (To_String (Config.Id) & ": database:"
                         & Agent.Database.Keys.Length'Image & " keys, digest"
                         & Ada.Strings.Hash (Agent.Database.Digest)'Image);
               Flush;
            end if;
            Agent.Stop;
         end Finish;
         Last_Gen  : Natural := 0;
         Last_Done : Natural := 0;
         Heard_Majority : Boolean := True;
         Beat   : Natural := 0;
      begin
         if not Config.Is_Robot then
            Agent.Publish_Mission (M);
            Put_Line ("operator: mission " & To_String (M.Name) & " published,"
                      & M.Tasks.Length'Image & " tasks");
         end if;
         loop
            exit when Clock > Stop or else RCL.Contexts.Is_Shutdown;
            if Config.Is_Robot and then Agent.All_Done then
               Put_Line (To_String (Config.Id) & ": mission complete");
               Finish;
               return;
            elsif Config.Is_Robot then
               declare
                  Found : Boolean;
                  Goal  : Point;
                  Tid   : Unbounded_String;
                  Done  : Boolean;
                  Step  : constant Real := Speed * Rate * Real (Period);
               begin
                  if Beat mod 5 = 0 then
                     Agent.Set_Pose (Here);
                  end if;
                  if Beat mod 100 = 0 then
                     Put (To_String (Config.Id) & ": members");
                     for Member of Agent.Network.Members loop
                        Put (" " & To_String (Member));
                     end loop;
                     Put_Line (", round" & Agent.Round.Generation'Image & ", plan"
                               & Agent.Adopted.Generation'Image);
                     Flush;
                  end if;
                  Beat := Beat + 1;
                  if Agent.Has_Quorum /= Heard_Majority then
                     --  The partition rule's state, for a reader of the log
                     --  (tests/netns/team-netns.sh checks that nothing new
                     --  is started between these two lines).
                     Heard_Majority := not Heard_Majority;
                     Put_Line (To_String (Config.Id)
                               & (if Heard_Majority then ": hears the majority again"
                                  else ": cut off from the majority"));
                     Flush;
                  end if;
                  Agent.Current_Goal (Found, Goal, Tid);
                  if Found then
                     if Distance (Here, Goal) <= Step then
                        Here := Goal;
                        Agent.Arrived (To_String (Tid), Done);
                        if Done then
                           Put_Line (To_String (Config.Id) & ": did " & To_String (Tid));
                           Flush;
                        end if;
                     else
                        declare
                           D : constant Real := Distance (Here, Goal);
                        begin
                           Here := (Here.X + (Goal.X - Here.X) * Step / D,
                                    Here.Y + (Goal.Y - Here.Y) * Step / D);
                        end;
                     end if;
                  end if;
               end;
            else
               declare
                  S : constant Plans.Snapshot := Agent.Round;
                  D : constant Natural := Agent.Done_Tasks;
               begin
                  if S.Generation /= Last_Gen then
                     Last_Gen := S.Generation;
                     Put ("operator: round " & Trim (S.Generation) & " robots ");
                     for K in 1 .. Natural (S.Robots.Length) loop
                        Put ((if K > 1 then "," else "") & To_String (S.Robots (K).Id));
                     end loop;
                     Put_Line (" tasks " & Trim (Natural (S.Tasks.Length)));
                     Flush;
                  end if;
                  if D /= Last_Done then
                     Last_Done := D;
                     Put_Line ("operator: progress " & Trim (D) & "/"
                               & Trim (Agent.Mission_Tasks));
                     Flush;
                  end if;
                  if Agent.All_Done then
                     for T of M.Tasks loop
                        Put_Line ("done " & To_String (T.Id) & " by "
                                  & Agent.Database.Get_String ("done/" & To_String (T.Id)));
                     end loop;
                     Put_Line ("operator: all done");
                     Flush;
                     Finish;
                     return;
                  end if;
               end;
            end if;
            Next := Next + To_Time_Span (Period);
            delay until Next;
         end loop;
         Agent.Stop;
         if not Config.Is_Robot then
            Put_Line ("operator: time is up with" & Last_Done'Image & " tasks done");
            Set_Exit_Status (Failure);
         end if;
      end;
   exception
      when E : Constraint_Error | Options.Usage_Error | Missions.Format_Error =>
         Put_Line (Standard_Error, "sancta team-agent: " & Ada.Exceptions.Exception_Message (E)
                   & " (sancta team-agent --help)");
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Team_Agent;
