with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Command_Line_Options; use Command_Line_Options;
with RCL.Contexts;
with Sancta.Simulation.Map_Files;
with Sancta.Views.Drawing;
with Sancta.Views.Feeds;
with Sancta.Views.Scenes;
with Sancta.Views.Windows;

procedure Sancta.Views.Main is

   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   package Map_Files renames Sancta.Simulation.Map_Files;

   Help : constant String :=
     "usage: sancta-view [options]" & ASCII.LF
     & "The live mission view of a SANCTA team: joins the team over DDS as an observer"
     & ASCII.LF
     & "(its agents need a gui_relay component) and shows robots, plans, tasks and events."
     & ASCII.LF & ASCII.LF
     & "  --team NAME          the team's topics /sancta/NAME/... (default team)" & ASCII.LF
     & "  --world NAME|FILE    the map: a bundled world (" & Map_Files.Bundled_Worlds
     & ")" & ASCII.LF
     & "                       or a map file; without it, the map of --map-topic (or none)"
     & ASCII.LF
     & "  --map-topic TOPIC    a nav_msgs/OccupancyGrid topic (default /map; 'none')"
     & ASCII.LF
     & "  --lost-after S       a robot silent for S seconds is shown lost (default 3)"
     & ASCII.LF
     & "  --follow ID          keep robot ID at the centre" & ASCII.LF
     & "  --scans              show the laser scans (/ID/scan)" & ASCII.LF
     & "  --size WxH           window or snapshot size in pixels (default 1280x820)"
     & ASCII.LF
     & "  --snapshot FILE.png  no window: draw off-screen into FILE.png after --after S"
     & ASCII.LF
     & "  --after S            seconds to watch before the snapshot (default 5)" & ASCII.LF
     & "  --describe FILE      write what was drawn as JSON (transform, robots, tours)"
     & ASCII.LF
     & "  --for S              close the window after S seconds" & ASCII.LF
     & "Window: drag to pan, wheel to zoom; tool bar: zoom, fit, follow, scans, trails,"
     & ASCII.LF
     & "pause, load a mission (published to the team), kill/revive a simulated robot.";

   Feed     : Feeds.Feed_Config;
   Window   : Windows.Window_Config;
   Snapshot : Unbounded_String;
   After    : Duration := 5.0;

   function Seconds (Option, Text : String) return Duration is
      Value : constant Long_Float := Number (Option, Text);
   begin
      if not (Value >= 0.0 and then Value <= 1.0E6) then
         raise Usage_Error with "option " & Option & ": " & Text & " is not in 0 .. 1e6 s";
      end if;
      return Duration (Value);
   end Seconds;

   procedure Parse_Size (Text : String) is
      X : constant Natural := Ada.Strings.Fixed.Index (Text, "x");
      function Side (Part : String) return Positive is
      begin
         return Result : constant Positive := Positive'Value (Part) do
            if Result < 200 or else Result > 8000 then
               raise Constraint_Error;
            end if;
         end return;
      exception
         when Constraint_Error =>
            raise Usage_Error with "option --size: """ & Text
              & """ is not WIDTHxHEIGHT (200 .. 8000 pixels each)";
      end Side;
   begin
      if X = 0 then
         raise Usage_Error with "option --size: """ & Text & """ is not WIDTHxHEIGHT";
      end if;
      Window.Width := Side (Text (Text'First .. X - 1));
      Window.Height := Side (Text (X + 1 .. Text'Last));
   end Parse_Size;

   procedure Parse is
      use Ada.Command_Line;
      I : Positive := 1;
      function Value return String is (Next_Value (I));
   begin
      while I <= Argument_Count loop
         declare
            A : constant String := Argument (I);
         begin
            if A = "--help" or else A = "-h" then
               Put_Line (Help);
               raise Usage_Error with "";
            elsif A = "--team" then
               Feed.Team := To_Unbounded_String (Value);
            elsif A = "--world" then
               Feed.World := To_Unbounded_String (Value);
            elsif A = "--map-topic" then
               Feed.Map_Topic := To_Unbounded_String (Value);
               if Feed.Map_Topic = "none" then
                  Feed.Map_Topic := Null_Unbounded_String;
               end if;
            elsif A = "--lost-after" then
               Feed.Lost_After := Seconds (A, Value);
            elsif A = "--follow" then
               Window.Options.Follow := To_Unbounded_String (Value);
            elsif A = "--scans" then
               Window.Options.Show_Scans := True;
            elsif A = "--size" then
               Parse_Size (Value);
            elsif A = "--snapshot" then
               Snapshot := To_Unbounded_String (Value);
            elsif A = "--after" then
               After := Seconds (A, Value);
            elsif A = "--describe" then
               Window.Describe := To_Unbounded_String (Value);
            elsif A = "--for" then
               Window.Quit_After := Seconds (A, Value);
            elsif A = "--ros-args" then
               exit;
            else
               raise Usage_Error with "unknown option " & A & " (sancta-view --help)";
            end if;
         end;
         I := I + 1;
      end loop;
   end Parse;

   procedure Take_Snapshot is
      T : Drawing.Transform;
   begin
      if Window.Options.Show_Scans then
         Feeds.Show_Scans;
      end if;
      while Scenes.Elapsed < After and then not Feeds.Interrupted loop
         delay 0.1;
      end loop;
      declare
         S : constant Scenes.Scene := Feeds.Scene_Store.Get;
      begin
         Drawing.Write_Snapshot
           (S, Window.Width, Window.Height, Window.Options, To_String (Snapshot), T);
         if Window.Describe /= Null_Unbounded_String then
            Drawing.Write_Description (S, T, To_String (Window.Describe));
         end if;
         Put_Line ("sancta-view: " & To_String (Snapshot) & ":" & S.Robots.Length'Image
                   & " robots," & S.Tasks.Length'Image & " tasks, round" & S.Round'Image
                   & ", " & Natural'Image (S.Samples) & " samples ("
                   & Natural'Image (S.Rejected) & " rejected)");
      end;
   end Take_Snapshot;

begin
   Parse;
   Feeds.Start (Feed);
   begin
      if Snapshot /= Null_Unbounded_String then
         Take_Snapshot;
      else
         Windows.Run (Window);
      end if;
   exception
      when others =>
         Feeds.Stop;
         raise;
   end;
   Feeds.Stop;
   RCL.Contexts.Shutdown;
exception
   when E : Usage_Error =>
      if Ada.Exceptions.Exception_Message (E) /= "" then
         Put_Line (Standard_Error, "sancta-view: " & Ada.Exceptions.Exception_Message (E));
         Ada.Command_Line.Set_Exit_Status (2);
      end if;
   when E : others =>
      --  "Broken pipe": our output was closed ("sancta-view --help | head").
      if Ada.Exceptions.Exception_Message (E) /= "Broken pipe" then
         Put_Line (Standard_Error, "sancta-view: " & Ada.Exceptions.Exception_Message (E));
         Ada.Command_Line.Set_Exit_Status (1);
      end if;
end Sancta.Views.Main;
