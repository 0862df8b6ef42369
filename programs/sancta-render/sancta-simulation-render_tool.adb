with Ada.Command_Line;
with Ada.Directories;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Interfaces;
with Sancta.Geometry;              use Sancta.Geometry;
with Sancta.Robot.Grids;
with Sancta.Simulation.Demos;
with Sancta.Simulation.Raster_Images;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Rendering;
with Sancta.Simulation.Tool_Arguments;
with Sancta.Simulation.Worlds;

package body Sancta.Simulation.Render_Tool is

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;

   use Tool_Arguments;

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   Max_Picture_Side : constant := 1.0E6;
   Max_PNG_Pixels   : constant := 4.0E8;

   function Rendering_Number (X : Real) return String is
     (if abs X < 1.0E15 and then X = Real'Rounding (X)
      then Ada.Strings.Fixed.Trim (Long_Long_Integer (X)'Image, Ada.Strings.Left)
      else Ada.Strings.Fixed.Trim (X'Image, Ada.Strings.Left));
   --  Example: 4.0E2 -> "400"; 0.05 -> " 5.00000000000000E-02" trimmed.

   procedure Usage is
   begin
      Put_Line ("usage: sancta-render WORLD [options]");
      Put_Line ("  WORLD                 a map-server YAML file or a wall world (.walls)");
      Put_Line ("  --svg FILE            write an SVG picture");
      Put_Line ("  --png FILE            write a PNG picture");
      Put_Line ("  --scale PIXELS        pixels per metre (default 20)");
      Put_Line ("  --trajectories CSV    draw trajectories (lines robot,x,y)");
      Put_Line ("  --poi X,Y[,LABEL]     mark a point of interest (repeatable)");
      Put_Line ("  --demo N              simulate N robots touring random goals first");
      Put_Line ("  --seconds S           demo length in simulated seconds (default 120)");
      Put_Line ("  --goals G             goals per robot in the demo (default 4)");
      Put_Line ("  --seed K              demo seed (default 1)");
      Put_Line ("  --csv FILE            write the demo trajectories as CSV");
      Put_Line ("  --rasterize BASE      write the world as BASE.pgm + BASE.yaml");
   end Usage;

   function To_Natural (Option, Text : String) return Natural is
   begin
      return Natural'Value (Text);
   exception
      when Constraint_Error =>
         raise Usage_Error with Option & ": expected a whole number, found """ & Text & """";
   end To_Natural;

   procedure Run is
      World_Name  : Unbounded_String;
      SVG, PNG, CSV, Trajectories, Raster : Unbounded_String;
      Scale       : Real := 20.0;
      Demo        : Demos.Demo_Config;
      Demo_Robots : Natural := 0;
      Scene       : Rendering.Scene;

      procedure Take (A : String; K : in out Positive) is
         function Value return String is (Next_Value (K));
      begin
         if A = "--svg" then
            SVG := To_Unbounded_String (Value);
         elsif A = "--png" then
            PNG := To_Unbounded_String (Value);
         elsif A = "--csv" then
            CSV := To_Unbounded_String (Value);
         elsif A = "--rasterize" then
            Raster := To_Unbounded_String (Value);
         elsif A = "--trajectories" then
            Trajectories := To_Unbounded_String (Value);
         elsif A = "--scale" then
            Scale := To_Real (A, Value);
            if Scale <= 0.0 or else Scale > 1000.0 then
               raise Usage_Error with "--scale: expected 0 < PIXELS <= 1000";
            end if;
         elsif A = "--demo" then
            Demo_Robots := To_Natural (A, Value);
            if Demo_Robots not in 1 .. 200 then
               raise Usage_Error with "--demo: expected 1 .. 200 robots";
            end if;
         elsif A = "--seconds" then
            Demo.Seconds := To_Real (A, Value);
            if Demo.Seconds not in 0.0 .. 36_000.0 then
               raise Usage_Error with "--seconds: expected 0 .. 36000";
            end if;
         elsif A = "--goals" then
            Demo.Goals_Per_Robot := Positive'Max (1, To_Natural (A, Value));
         elsif A = "--seed" then
            Demo.Seed := Interfaces.Unsigned_64 (To_Natural (A, Value));
         elsif A = "--poi" then
            declare
               V  : constant String := Value;
               C1 : constant Natural := Ada.Strings.Fixed.Index (V, ",");
               C2 : constant Natural :=
                 (if C1 = 0 then 0 else Ada.Strings.Fixed.Index (V (C1 + 1 .. V'Last), ","));
               Last_Y : constant Natural := (if C2 = 0 then V'Last else C2 - 1);
            begin
               if C1 = 0 then
                  raise Usage_Error with "--poi: expected X,Y[,LABEL], found """ & V & """";
               end if;
               Scene.Markers.Append
                 (Rendering.Marker'
                    (Where => (To_Real (A, V (V'First .. C1 - 1)),
                               To_Real (A, V (C1 + 1 .. Last_Y))),
                     Label => To_Unbounded_String
                       (if C2 = 0 then "" else V (C2 + 1 .. V'Last))));
            end;
         else
            raise Usage_Error with "unknown option " & A;
         end if;
      end Take;

      function Second_World (A : String) return String is ("more than one world: " & A);
      function Parse is new Parse_Arguments
        (Usage, Take, Second_World, No_World => "no world given");
   begin
      if not Parse (World_Name) then
         return;
      end if;
      declare
         World : constant Worlds.World := Map_Files.Load_World (To_String (World_Name));
         Frame : constant Sancta.Robot.Grids.Frame := Worlds.Frame_Of (World);
         Wide  : constant Real := Real (Frame.Width) * Frame.Resolution * Scale;
         High  : constant Real := Real (Frame.Height) * Frame.Resolution * Scale;
      begin
         --  A world of a few cells but a huge resolution would make a
         --  picture no integer can measure (or no memory can hold).
         if (Length (SVG) > 0 or else Length (PNG) > 0)
           and then (Wide > Max_Picture_Side or else High > Max_Picture_Side
                     or else (Length (PNG) > 0 and then Wide * High > Max_PNG_Pixels))
         then
            raise Usage_Error with To_String (World_Name) & ": the world is"
              & Natural'Image (Frame.Width) & " x" & Natural'Image (Frame.Height)
              & " cells of " & Real'Image (Frame.Resolution) & " m: the picture would be "
              & Rendering_Number (Wide) & " x " & Rendering_Number (High)
              & " pixels at --scale " & Rendering_Number (Scale) & " (at most "
              & Rendering_Number (Max_Picture_Side) & " a side, "
              & Rendering_Number (Max_PNG_Pixels / 1.0E6) & " million pixels for --png)";
         end if;
         if Length (Raster) > 0 then
            Rendering.Write_Map (World, To_String (Raster));
            Put_Line ("wrote " & To_String (Raster) & ".pgm and .yaml");
         end if;
         if Length (Trajectories) > 0 then
            Scene.Trajectories := Rendering.Read_Trajectories (To_String (Trajectories));
         end if;
         if Demo_Robots > 0 then
            Demo.Robots := Demo_Robots;
            declare
               Result  : Demos.Demo_Result;
               Markers : constant Rendering.Marker_Vectors.Vector := Scene.Markers;
            begin
               Demos.Run_Team (World, Demo, Result);
               Scene := Result.Picture;
               Scene.Markers.Append (Markers);
               Put_Line ("demo:" & Demo_Robots'Image & " robots," & Result.Goals_Reached'Image
                         & " of" & Result.Goals_Total'Image & " goals reached,"
                         & Result.Goals_Skipped'Image & " skipped,"
                         & Result.Collisions'Image & " collisions, in"
                         & Natural (Result.Duration)'Image & " simulated seconds");
               Put (To_String (Result.Collision_Log));
               if Length (CSV) > 0 then
                  Rendering.Write_Trajectories (Scene.Trajectories, To_String (CSV));
               end if;
               Scene.Title := To_Unbounded_String
                 (Trim (Demo_Robots) & " robots on random tours, " & Trim (Result.Goals_Reached)
                  & " of " & Trim (Result.Goals_Total) & " goals reached in "
                  & Trim (Natural (Result.Duration)) & " s");
            end;
         elsif Length (Trajectories) > 0 then
            Scene.Title := To_Unbounded_String
              ("Trajectories of " & Ada.Directories.Simple_Name (To_String (Trajectories)));
         end if;
         --  Which colour is which robot, and the scale (as the demo report's
         --  pictures); a world alone is drawn bare.
         for R in 1 .. Scene.Trajectories.Last_Index loop
            Scene.Legend.Append
              (Rendering.Legend_Entry'
                 (Rendering.Color_Of (R),
                  To_Unbounded_String ((if Demo_Robots > 0 then "r" else "robot ") & Trim (R))));
         end loop;
         Scene.Scale_Bar := not Scene.Trajectories.Is_Empty;
         if Length (SVG) > 0 then
            Rendering.Write_SVG (World, Scene, To_String (SVG), Scale);
            Put_Line ("wrote " & To_String (SVG));
         end if;
         if Length (PNG) > 0 then
            Raster_Images.Save_PNG (Rendering.Render (World, Scene, Scale), To_String (PNG));
            Put_Line ("wrote " & To_String (PNG));
         end if;
      end;
   exception
      when E : Ada.IO_Exceptions.Device_Error =>
         --  Our output was closed ("sancta-render --help | head"): done; other
         --  device errors are reported.
         if Ada.Exceptions.Exception_Message (E) /= "Broken pipe" then
            Put_Line (Standard_Error, "sancta-render: " & Ada.Exceptions.Exception_Message (E));
            Set_Exit_Status (Failure);
         end if;
      when E : Usage_Error =>
         Put_Line (Standard_Error, "sancta-render: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
      when E : Format_Error | Constraint_Error =>
         Put_Line (Standard_Error, "sancta-render: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
      when E : Ada.IO_Exceptions.Name_Error | Ada.IO_Exceptions.Use_Error =>
         --  An output file that cannot be created; GNAT's message names it.
         Put_Line (Standard_Error, "sancta-render: cannot write: "
                   & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
      when E : others =>
         --  Last resort: a bug, reported in one line instead of a traceback.
         Put_Line (Standard_Error, "sancta-render: internal error: "
                   & Ada.Exceptions.Exception_Name (E) & ": "
                   & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
   end Run;

end Sancta.Simulation.Render_Tool;
