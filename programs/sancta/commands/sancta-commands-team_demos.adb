with Interfaces;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with RCL.Contexts;
with Sancta.Commands.Options;
with Sancta.Robot.Navigators;
with Sancta.Runtime.Values;
with Sancta.Simulation.Glyphs;
with Sancta.Simulation.Raster_Images;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Simulators;
with Sancta.Team.Replicated_Databases;

package body Sancta.Commands.Team_Demos is

   use Ada.Text_IO;
   use Sancta.Geometry;
   use Sancta.Simulation;
   use Sancta.Simulation.Simulators;

   function Img (X : Long_Float) return String is
     (Runtime.Values.Real_Image (Long_Float'Rounding (X * 1000.0) / 1000.0));
   --  Seconds and metres in summary.json, to the millisecond / millimetre.

   function F1 (X : Long_Float) return String is
      Scaled : constant Long_Long_Integer := Long_Long_Integer (X * 10.0);
      Whole  : constant String :=
        Ada.Strings.Fixed.Trim (Long_Long_Integer'Image (abs Scaled / 10), Ada.Strings.Left);
   begin
      return (if Scaled < 0 then "-" else "") & Whole & "."
        & Ada.Strings.Fixed.Trim (Long_Long_Integer'Image (abs Scaled mod 10), Ada.Strings.Left);
   end F1;

   function Take_Run_Option
     (Option : String; Index : in out Positive; Into : in out Run_Options) return Boolean
   is
      function Value return String is (Options.Next_Value (Index));
   begin
      if Option = "--kill" then
         Into.Kill_Robot := To_Unbounded_String (Value);
      elsif Option = "--no-kill" then
         Into.Kill := False;
      elsif Option = "--kill-at" then
         Into.Kill_Fraction := Options.Number (Option, Value);
         if Into.Kill_Fraction not in 0.0 .. 1.0 then
            raise Constraint_Error with "option --kill-at: expected a fraction in [0, 1]";
         end if;
      elsif Option = "--max" then
         Into.Max_Seconds := Options.Number (Option, Value);
      elsif Option = "--out" then
         Into.Out_Dir := To_Unbounded_String (Value);
      elsif Option = "--quiet" then
         Into.Verbose := False;
      elsif Option = "--check" then
         Into.Check := True;
      else
         return False;
      end if;
      return True;
   end Take_Run_Option;

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function F2 (X : Long_Float) return String is
     (Runtime.Values.Real_Image (Long_Float'Rounding (X * 100.0) / 100.0));
   function F2 (P : Point) return String is
     (F2 (Long_Float (P.X)) & "," & F2 (Long_Float (P.Y)));
   --  Metres to the centimetre, as in the unfinished-robot lines.

   --  Planned tours as polylines (for the pictures) -------------------------------

   function Planned_Scene
     (S   : Plans.Snapshot;
      P   : Plans.Plan;
      Ids : Robot_Summary_Vectors.Vector;
      Map : access Sancta.Robot.Path_Costs.Planner := null) return Rendering.Scene
   is
      Result : Rendering.Scene;
   begin
      for R of Ids loop
         declare
            Path : Rendering.Point_Vectors.Vector;
         begin
            for K in 1 .. Natural (S.Robots.Length) loop
               if S.Robots (K).Id = R.Id and then K <= Natural (P.Tours.Length) then
                  Path.Append (S.Robots (K).Where);
                  for St of P.Tours (K) loop
                     declare
                        T : constant Missions.Mission_Task :=
                          Plans.Task_Of (S, To_String (St.Task_Id));
                     begin
                        if Map /= null and then not Path.Is_Empty then
                           --  The leg along the A* path the robot would drive.
                           for W of Robot.Path_Costs.Path
                             (Map.all, Path.Last_Element, Missions.Entry_Point (T, St.Choice))
                           loop
                              Path.Append (W);
                           end loop;
                        end if;
                        Path.Append (Missions.Entry_Point (T, St.Choice));
                        Path.Append (Missions.Exit_Point (T, St.Choice));
                        Result.Markers.Append
                          (Rendering.Marker'(Missions.Entry_Point (T, St.Choice),
                                             St.Task_Id & ">" & R.Id));
                     end;
                  end loop;
               end if;
            end loop;
            Result.Trajectories.Append (Path);
         end;
      end loop;
      return Result;
   end Planned_Scene;

   function Unfinished
     (S      : Plans.Snapshot;
      P      : Plans.Plan;
      Robot  : String;
      Is_Done : not null access function (Task_Id : String) return Boolean)
      return Completion_Vectors.Vector
   is
      Result : Completion_Vectors.Vector;
   begin
      for K in 1 .. Natural'Min (Natural (S.Robots.Length), Natural (P.Tours.Length)) loop
         if To_String (S.Robots (K).Id) = Robot then
            for St of P.Tours (K) loop
               if not Is_Done (To_String (St.Task_Id)) then
                  Result.Append (Completion'(Task_Id => St.Task_Id, others => <>));
               end if;
            end loop;
         end if;
      end loop;
      return Result;
   end Unfinished;

   function Check_Passed (Result : Demo_Result) return Boolean is
      Passed : Boolean := Result.All_Done and then Result.Duplicates = 0;
   begin
      if Result.Killed /= Null_Unbounded_String then
         Passed := Passed and then Result.Replanned;
         for O of Result.Orphans loop
            Passed := Passed and then O.Robot /= Null_Unbounded_String
              and then O.Robot /= Result.Killed;
         end loop;
      end if;
      return Passed;
   end Check_Passed;

   procedure Follow_Replan (Result : in out Demo_Result; Adopted : Plans.Plan) is
   begin
      if Adopted.Generation = Result.Round_After.Generation
        and then Adopted.Value < Result.Plan_After.Value
      then
         Result.Plan_After := Adopted;
      end if;
   end Follow_Replan;

   procedure Resolve_Orphans (Result : in out Demo_Result) is
   begin
      for O of Result.Orphans loop
         for C of Result.Completions loop
            if C.Task_Id = O.Task_Id then
               O.Robot := C.Robot;
               O.Time := C.Time;
            end if;
         end loop;
      end loop;
   end Resolve_Orphans;

   -------------------
   -- Note_Arrivals --
   -------------------

   procedure Note_Arrivals
     (Result : in out Demo_Result;
      Tasks  : Missions.Task_Vectors.Vector)
   is
      use type Missions.Task_Kind;

      function Task_Of (Id : Unbounded_String; Found : out Boolean)
        return Missions.Mission_Task is
      begin
         for T of Tasks loop
            if T.Id = Id then
               Found := True;
               return T;
            end if;
         end loop;
         Found := False;
         return (others => <>);
      end Task_Of;

      function Moving (A, B : Track_Sample) return Boolean is
         DT : constant Long_Float := Long_Float'Max (B.Time - A.Time, 1.0E-6);
      begin
         return Long_Float (Distance (Position (A.Where), Position (B.Where))) / DT
                  >= Still_Speed
           or else abs Long_Float (Normalize_Angle (B.Where.Yaw - A.Where.Yaw)) / DT
                     >= Still_Turn;
      end Moving;

      function Stopped_In (R : Positive; From, To : Long_Float) return Long_Float is
         Sum : Long_Float := 0.0;
      begin
         for S of Result.Robots (R).Stops loop
            Sum := Sum + Long_Float'Max
              (0.0, Long_Float'Min (S.To, To) - Long_Float'Max (S.From, From));
         end loop;
         return Sum;
      end Stopped_In;

      function Stay_Start
        (Track : Track_Vectors.Vector; Last : Natural; Since : Long_Float; Where : Point)
         return Long_Float
      is
         --  The start of the last stay within Reach_Radius of Where among
         --  samples 1 .. Last from Since on; -1.0 when there is none.
         K : Natural := Last;

         function Near (I : Positive) return Boolean is
           (Track (I).Time >= Since
            and then Long_Float (Distance (Position (Track (I).Where), Where)) <= Reach_Radius);
      begin
         while K > 0 and then Track (K).Time >= Since and then not Near (K) loop
            K := K - 1;
         end loop;
         if K = 0 or else not Near (K) then
            return -1.0;
         end if;
         while K > 1 and then Near (K - 1) loop
            K := K - 1;
         end loop;
         return Track (K).Time;
      end Stay_Start;
   begin
      Result.Last_Leg := (others => <>);
      for R in 1 .. Natural (Result.Robots.Length) loop
         declare
            Robot : Robot_Summary renames Result.Robots (R);
            Track : Track_Vectors.Vector renames Robot.Track;
            Since : Long_Float := Result.Plan_Time;
            Still : Natural := 0;
            --  The first sample of the current still run (0: moving).
         begin
            Robot.Stops.Clear;
            for K in 2 .. Natural (Track.Length) loop
               if not Moving (Track (K - 1), Track (K)) then
                  if Still = 0 then
                     Still := K - 1;
                  end if;
               else
                  if Still > 0 and then Track (K - 1).Time - Track (Still).Time >= Min_Stop then
                     Robot.Stops.Append (Span'(Track (Still).Time, Track (K - 1).Time));
                  end if;
                  Still := 0;
               end if;
            end loop;
            if Still > 0 and then Track.Last_Element.Time - Track (Still).Time >= Min_Stop then
               Robot.Stops.Append (Span'(Track (Still).Time, Track.Last_Element.Time));
            end if;
            Robot.Travel := 0.0;
            Robot.At_Task := 0.0;
            Robot.Stopped := 0.0;
            for C of Result.Completions loop
               if C.Robot = Robot.Id then
                  declare
                     Found : Boolean;
                     T     : constant Missions.Mission_Task := Task_Of (C.Task_Id, Found);
                     Last  : Natural := 0;
                     --  The last sample at most Grace after the completion.
                     Entry_Point : Point;
                  begin
                     C.Reached := -1.0;
                     for K in 1 .. Natural (Track.Length) loop
                        exit when Track (K).Time > C.Time + Grace;
                        Last := K;
                     end loop;
                     if Found and then Last > 0 and then not T.Points.Is_Empty then
                        declare
                           Here : constant Point := Position (Track (Last).Where);
                           Best : Real := Real'Last;
                        begin
                           if T.Kind = Missions.Explore_Segment then
                              --  Entered at the end away from where it finished.
                              Entry_Point :=
                                (if Distance (Here, T.Points.First_Element)
                                      >= Distance (Here, T.Points.Last_Element)
                                 then T.Points.First_Element else T.Points.Last_Element);
                           else
                              for P of T.Points loop
                                 if Distance (Here, P) < Best then
                                    Best := Distance (Here, P);
                                    Entry_Point := P;
                                 end if;
                              end loop;
                           end if;
                        end;
                        C.Reached := Stay_Start (Track, Last, Since, Entry_Point);
                        if C.Reached >= 0.0 then
                           C.Reached := Long_Float'Min (C.Reached, C.Time);
                        end if;
                     end if;
                     declare
                        Reached : constant Long_Float :=
                          (if C.Reached < 0.0 then C.Time else C.Reached);
                        Away    : constant Long_Float := Stopped_In (R, Since, Reached);
                        There   : constant Long_Float := Stopped_In (R, Reached, C.Time);
                     begin
                        Robot.Travel := Robot.Travel
                          + Long_Float'Max (0.0, Reached - Since - Away);
                        Robot.At_Task := Robot.At_Task
                          + Long_Float'Max (0.0, C.Time - Reached - There);
                        Robot.Stopped := Robot.Stopped + Away + There;
                     end;
                     Since := Long_Float'Max (Since, C.Time);
                  end;
               end if;
            end loop;
            if Robot.Id = Result.Killed and then Result.Kill_Time > Since then
               --  Its last leg: toward (or at) the first task of its tour it
               --  had not done, entered at any of its points.
               Result.Last_Leg :=
                 (Task_Id => (if Result.Orphans.Is_Empty then Null_Unbounded_String
                              else Result.Orphans.First_Element.Task_Id),
                  Robot   => Robot.Id,
                  Time    => Result.Kill_Time,
                  Reached => -1.0);
               declare
                  Found : Boolean;
                  T     : constant Missions.Mission_Task :=
                    Task_Of (Result.Last_Leg.Task_Id, Found);
                  Last  : Natural := 0;
               begin
                  for K in 1 .. Natural (Track.Length) loop
                     exit when Track (K).Time > Result.Kill_Time;
                     Last := K;
                  end loop;
                  if Found then
                     for P of T.Points loop
                        Result.Last_Leg.Reached := Long_Float'Max
                          (Result.Last_Leg.Reached, Stay_Start (Track, Last, Since, P));
                     end loop;
                  end if;
               end;
            end if;
         end;
      end loop;
   end Note_Arrivals;

   -----------------
   -- Write_Gantt --
   -----------------

   procedure Write_Gantt (Result : Demo_Result; Dir : String) is
      --  Tasks per robot over simulated time: a bar per task from the
      --  robot's previous completion (or the first plan) to its own, light
      --  until the robot reached the task, dark from there, grey where it
      --  stood still (Note_Arrivals); the first plan, the loss of a robot
      --  and the re-plan as vertical lines, named below the axis.
      --  gantt.svg, gantt.png.
      package Glyphs renames Sancta.Simulation.Glyphs;
      Rows    : constant Natural := Natural (Result.Robots.Length);
      Left    : constant := 64;
      Row_H   : constant := 26;
      Top     : constant := 30;
      Width   : constant := 900;
      Span    : constant Long_Float :=
        Long_Float'Max (1.0, Long_Float'Max (Result.Makespan, Result.Kill_Time + 1.0));
      Plot_W  : constant Natural := Width - Left - 16;
      Height  : constant Natural := Top + Rows * Row_H + 55;
      Label_Lines : constant := 3;
      Line_End    : array (0 .. Label_Lines - 1) of Integer := [others => Integer'First / 2];
      --  Right end of the event names on each line below the axis.
      Px      : constant Long_Float := Long_Float (Plot_W) / Span;
      Tick    : constant Long_Float :=
        (if Span <= 60.0 then 10.0 elsif Span <= 300.0 then 30.0 else 60.0);
      Replan  : constant Long_Float := Result.Kill_Time + Result.Replan_Sim;
      Red     : constant Raster_Images.Color := (200, 0, 0);
      Replan_Ink : constant Raster_Images.Color := (40, 40, 40);
      --  Red is the loss's only; robots have the palette's colours.
      Still_Grey : constant Raster_Images.Color := (160, 160, 160);
      function Tint (C : Raster_Images.Color) return Raster_Images.Color is
        ((Raster_Images.Byte ((Natural (C.R) + 255) / 2),
          Raster_Images.Byte ((Natural (C.G) + 255) / 2),
          Raster_Images.Byte ((Natural (C.B) + 255) / 2)));
      --  Half way to white: a bar's travel part.
      Img     : Raster_Images.Image := Raster_Images.Create (Width, Height);
      SVG     : File_Type;

      function X_Of (T : Long_Float) return Integer is (Left + Integer (T * Px));
      function Row_Y (R : Positive) return Integer is (Top + (R - 1) * Row_H);

      procedure Box (X0, Y0, X1, Y1 : Integer; C : Raster_Images.Color) is
      begin
         for X in X0 .. X1 loop
            for Y in Y0 .. Y1 loop
               Raster_Images.Set (Img, X, Y, C);
            end loop;
         end loop;
      end Box;

      procedure Mark (T : Long_Float; C : Raster_Images.Color; Label, Hex : String) is
         --  The line at T, its name on the first line below the axis where
         --  it clears the names already there (SVG's wider font counted).
         X    : constant Integer := X_Of (T);
         W    : constant Natural := Natural'Max (Glyphs.Text_Width (Label), Label'Length * 7);
         LX   : constant Integer := Integer'Max (2, Integer'Min (X + 3, Width - W - 2));
         Line : Natural := Label_Lines - 1;
      begin
         for L in Line_End'Range loop
            if LX > Line_End (L) + 8 then
               Line := L;
               exit;
            end if;
         end loop;
         Line_End (Line) := LX + W;
         declare
            LY : constant Integer := Top + Rows * Row_H + 18 + Line * 13;
         begin
            Box (X, Top - 4, X + 1, Top + Rows * Row_H, C);
            Glyphs.Draw_Text (Img, LX, LY, Label, C, Halo => False);
            Put_Line (SVG, "<line class=""event"" x1=""" & Trim (X) & """ y1="""
                      & Trim (Top - 4) & """ x2=""" & Trim (X) & """ y2="""
                      & Trim (Top + Rows * Row_H) & """ stroke=""" & Hex
                      & """ stroke-width=""2"" stroke-dasharray=""5,3""/>");
            Put_Line (SVG, "<text class=""label"" x=""" & Trim (LX) & """ y="""
                      & Trim (LY + 9) & """ data-width=""" & Trim (Label'Length * 7)
                      & """ fill=""" & Hex & """ font-size=""11"" font-family=""sans-serif"">"
                      & Label & "</text>");
         end;
      end Mark;

      function Stem (S : String) return String is
        (if S'Length > 1 and then S (S'Last) in '_' | '-' | ' ' | '.'
         then Stem (S (S'First .. S'Last - 1)) else S);
      --  S without the separators it ends with ("EXIT_" -> "EXIT").

      function Fitted (Name : String; Room, Char_W : Natural) return String is
        (if Name'Length * Char_W + 4 <= Room then Name
         elsif Room < 4 + 3 * Char_W then ""
         else Stem (Name (Name'First .. Name'First + (Room - 4) / Char_W - 2)) & ".");
      --  Name when it fits in Room pixels, else its longest prefix that
      --  fits (separators at its end left out) followed by '.' (at least
      --  one letter), else nothing.

      procedure Draw_Row (R : Positive; Names : Boolean) is
         --  Names: only the tasks' names, else the robot and the bars:
         --  light from the previous completion to reaching the task
         --  (travel), dark from there to the completion (at the task),
         --  grey where the robot stood still.
         Id    : constant String := To_String (Result.Robots (R).Id);
         Color : constant Raster_Images.Color := Rendering.Color_Of (R);
         Light : constant Raster_Images.Color := Tint (Color);
         Y     : constant Integer := Row_Y (R);
         Since : Long_Float := Result.Plan_Time;

         procedure Bar (C : Completion; Done : Boolean) is
            --  C's bar from Since; not Done: the lost robot's last leg
            --  (C.Time its loss, C.Task_Id the task it had not done).
         begin
            declare
               From : constant Long_Float := Long_Float'Min (Since, C.Time);
               X0   : constant Integer := X_Of (From);
               X1   : constant Integer := Integer'Max (X0 + 2, X_Of (C.Time) - 1);
               Name : constant String :=
                 (if Done then To_String (C.Task_Id)
                  elsif C.Task_Id = Null_Unbounded_String then "(not done)"
                  else To_String (C.Task_Id) & " (not done)");
               PNG_Name : constant String := Fitted (Name, X1 - X0, Glyphs.Advance);
               SVG_Name : constant String := Fitted (Name, X1 - X0, 7);
               Reached  : constant Long_Float :=
                 (if C.Reached < 0.0 then C.Time else Long_Float'Max (From, C.Reached));

               procedure Part (T0, T1 : Long_Float; Shade : Raster_Images.Color;
                               Class : String) is
                  --  The bar's part from T0 to T1 (within the bar).
                  P0 : constant Integer := Integer'Max (X0 + 1, X_Of (T0));
                  P1 : constant Integer := Integer'Min (X1, X_Of (T1));
               begin
                  if P1 >= P0 then
                     Box (P0, Y + 4, P1, Y + Row_H - 4, Shade);
                     Put_Line (SVG, "<rect class=""" & Class & """ x=""" & Trim (P0)
                               & """ y=""" & Trim (Y + 4) & """ width="""
                               & Trim (P1 - P0 + 1) & """ height=""" & Trim (Row_H - 8)
                               & """ fill=""" & Rendering.Hex (Shade) & """/>");
                  end if;
               end Part;
            begin
               if not Names then
                  Box (X0 + 1, Y + 4, X1, Y + Row_H - 4, Light);
                  Put_Line (SVG, "<rect class=""" & (if Done then "task" else "unfinished")
                            & """ x=""" & Trim (X0 + 1) & """ y="""
                            & Trim (Y + 4) & """ width=""" & Trim (X1 - X0) & """ height="""
                            & Trim (Row_H - 8) & """ fill=""" & Rendering.Hex (Light)
                            & """ stroke=""white""><title>" & To_String (C.Task_Id) & ": "
                            & (if C.Reached < 0.0 then ""
                               else "reached at " & F1 (Reached) & " s, ")
                            & (if Done then "done at " else "not done, robot lost at ")
                            & F1 (C.Time) & " s</title></rect>");
                  if C.Reached >= 0.0 then
                     Part (Reached, C.Time, Color, "at-task");
                  end if;
                  for S of Result.Robots (R).Stops loop
                     if S.To > From and then S.From < C.Time then
                        Part (S.From, S.To, Still_Grey, "stopped");
                     end if;
                  end loop;
               else
                  --  The task's name inside its bar, cut to fit, in a white
                  --  outline (a patch would hide the shades under it).
                  if PNG_Name /= "" then
                     Glyphs.Draw_Text (Img, X0 + 3, Y + Row_H / 2 - 3, PNG_Name,
                                       Raster_Images.Black, Halo => True);
                  end if;
                  if SVG_Name /= "" then
                     Put_Line (SVG, "<text class=""label"" x=""" & Trim (X0 + 3)
                               & """ y=""" & Trim (Y + Row_H / 2 + 4) & """ data-width="""
                               & Trim (SVG_Name'Length * 7) & """ fill=""black"""
                               & " stroke=""white"" stroke-width=""3"""
                               & " paint-order=""stroke"""
                               & " font-size=""11"" font-family=""sans-serif"">"
                               & SVG_Name & "</text>");
                  end if;
               end if;
               Since := C.Time;
            end;
         end Bar;
      begin
         if not Names then
            Glyphs.Draw_Text (Img, 8, Y + Row_H / 2 - 3, Id, Raster_Images.Black, Halo => False);
            Put_Line (SVG, "<text class=""robot"" x=""8"" y=""" & Trim (Y + Row_H / 2 + 4)
                      & """ font-size=""12"" font-family=""sans-serif"">" & Id & "</text>");
         end if;
         for C of Result.Completions loop
            if To_String (C.Robot) = Id then
               Bar (C, Done => True);
            end if;
         end loop;
         if To_String (Result.Last_Leg.Robot) = Id and then Result.Last_Leg.Time > Since then
            Bar (Result.Last_Leg, Done => False);
         end if;
         if not Names and then Id = To_String (Result.Killed) then
            --  Lost: the rest of its row hatched.
            for X in X_Of (Result.Kill_Time) .. X_Of (Span) loop
               for Yy in Y + 4 .. Y + Row_H - 4 loop
                  if (X + Yy) mod 6 = 0 then
                     Raster_Images.Set (Img, X, Yy, Red);
                  end if;
               end loop;
            end loop;
            Put_Line (SVG, "<rect class=""lost"" x=""" & Trim (X_Of (Result.Kill_Time))
                      & """ y=""" & Trim (Y + 4) & """ width="""
                      & Trim (X_Of (Span) - X_Of (Result.Kill_Time)) & """ height="""
                      & Trim (Row_H - 8) & """ fill=""#c80000"" fill-opacity=""0.15""/>");
         end if;
      end Draw_Row;
   begin
      Create (SVG, Out_File, Dir & "/gantt.svg");
      Put_Line (SVG, "<?xml version=""1.0"" encoding=""UTF-8""?>");
      Put_Line (SVG, "<svg xmlns=""http://www.w3.org/2000/svg"" width=""" & Trim (Width)
                & """ height=""" & Trim (Height) & """ viewBox=""0 0 " & Trim (Width) & " "
                & Trim (Height) & """>");
      Put_Line (SVG, "<rect width=""100%"" height=""100%"" fill=""white""/>");
      Put_Line (SVG, "<text class=""title"" x=""8"" y=""18"" font-size=""14"""
                & " font-weight=""bold"" font-family=""sans-serif"">Tasks per robot over"
                & " simulated time (s)</text>");
      Glyphs.Draw_Text (Img, 8, 8, "Tasks per robot over simulated time (s)", Raster_Images.Black,
                        Halo => False);
      --  What the shades mean, in the first robot's colours.
      declare
         X : Integer := 360;

         procedure Key (Shade : Raster_Images.Color; Text : String) is
            W : constant Natural := Natural'Max (Glyphs.Text_Width (Text), Text'Length * 7);
         begin
            Box (X, 8, X + 15, 15, Shade);
            Put_Line (SVG, "<rect class=""key"" x=""" & Trim (X) & """ y=""8"" width=""16"""
                      & " height=""8"" fill=""" & Rendering.Hex (Shade) & """/>");
            Glyphs.Draw_Text (Img, X + 20, 8, Text, Raster_Images.Black, Halo => False);
            Put_Line (SVG, "<text class=""legend"" x=""" & Trim (X + 20) & """ y=""17"""
                      & " data-width=""" & Trim (Text'Length * 7) & """ font-size=""11"""
                      & " font-family=""sans-serif"">" & Text & "</text>");
            X := X + 20 + W + 14;
         end Key;
      begin
         Key (Tint (Rendering.Color_Of (1)), "going to the task");
         Key (Rendering.Color_Of (1), "at the task");
         Key (Still_Grey, "stopped");
      end;
      --  Time axis.
      declare
         T : Long_Float := 0.0;
      begin
         while T <= Span loop
            declare
               X    : constant Integer := X_Of (T);
               Text : constant String := Trim (Integer (T));
            begin
               Box (X, Top + Rows * Row_H, X, Top + Rows * Row_H + 4, Raster_Images.Black);
               for Y in Top .. Top + Rows * Row_H loop
                  if Y mod 3 = 0 then
                     Raster_Images.Set (Img, X, Y, (200, 200, 200));
                  end if;
               end loop;
               Glyphs.Draw_Text (Img, X - Glyphs.Text_Width (Text) / 2, Top + Rows * Row_H + 6,
                                 Text, Raster_Images.Black, Halo => False);
               Put_Line (SVG, "<line x1=""" & Trim (X) & """ y1=""" & Trim (Top)
                         & """ x2=""" & Trim (X) & """ y2=""" & Trim (Top + Rows * Row_H + 4)
                         & """ stroke=""#c8c8c8""/>");
               Put_Line (SVG, "<text class=""tick"" x=""" & Trim (X) & """ y="""
                         & Trim (Top + Rows * Row_H + 15) & """ text-anchor=""middle"""
                         & " font-size=""10"" font-family=""sans-serif"">" & Text & "</text>");
            end;
            T := T + Tick;
         end loop;
      end;
      --  Bars, then the event lines over them, then the bars' names over
      --  the lines (in a white outline: a line never cuts a name).
      for R in 1 .. Rows loop
         Draw_Row (R, Names => False);
      end loop;
      if Result.Plan_Time > 0.0 then
         Mark (Result.Plan_Time, (110, 110, 110), "first plan", "#6e6e6e");
      end if;
      if Result.Killed /= Null_Unbounded_String then
         Mark (Result.Kill_Time, Red, To_String (Result.Killed) & " lost", "#c80000");
         if Result.Replanned then
            Mark (Replan, Replan_Ink, "re-planned", Rendering.Hex (Replan_Ink));
         end if;
      end if;
      for R in 1 .. Rows loop
         Draw_Row (R, Names => True);
      end loop;
      Put_Line (SVG, "</svg>");
      Close (SVG);
      Raster_Images.Save_PNG (Img, Dir & "/gantt.png");
   end Write_Gantt;

   procedure Write_Report
     (Result : Demo_Result;
      World  : Worlds.World;
      Scene  : Rendering.Scene;
      Dir    : String)
   is
      F   : File_Type;
      Map : aliased Robot.Path_Costs.Planner;
      Lost : constant String :=
        (if Result.Killed = Null_Unbounded_String then ""
         else To_String (Result.Killed) & " lost at " & F1 (Result.Kill_Time) & " s");

      procedure Picture (Name, Title : String; S : Rendering.Scene; Tasks : Boolean) is
         --  With a title, a legend (a colour per robot; the planned tasks'
         --  crosses) and a scale bar.
         Framed : Rendering.Scene := S;
      begin
         Framed.Title := To_Unbounded_String (Title);
         for R in 1 .. Natural (Result.Robots.Length) loop
            Framed.Legend.Append
              (Rendering.Legend_Entry'(Rendering.Color_Of (R),
                Result.Robots (R).Id
                & (if Result.Robots (R).Id = Result.Killed then " (lost)" else "")));
         end loop;
         if not S.Lost.Is_Empty then
            Framed.Legend.Append
              (Rendering.Legend_Entry'((200, 0, 0), To_Unbounded_String ("x robot lost")));
         end if;
         if Tasks then
            Framed.Legend.Append
              (Rendering.Legend_Entry'(Raster_Images.Black,
                                        To_Unbounded_String ("x task>robot")));
         end if;
         Framed.Scale_Bar := True;
         Rendering.Write_SVG (World, Framed, Dir & "/" & Name & ".svg");
         Raster_Images.Save_PNG (Rendering.Render (World, Framed), Dir & "/" & Name & ".png");
      end Picture;
   begin
      Ada.Directories.Create_Path (Dir);
      Map.Initialize (Worlds.Occupancy (World), Robot_Radius => 0.3);
      Picture ("trajectories", "Trajectories, " & Trim (Result.Tasks_Done) & "/"
               & Trim (Result.Tasks_Total) & " tasks done in " & F1 (Result.Makespan) & " s"
               & (if Lost = "" then "" else ", " & Lost), Scene, Tasks => False);
      if Result.Plan_Before.Generation > 0 then
         Picture ("plan-before", "First plan (round" & Result.Plan_Before.Generation'Image
                  & "), longest tour " & F1 (Result.Grid_Makespan) & " m along the paths drawn ("
                  & F1 (Result.Planned_Makespan) & " m with straight legs)",
                  Planned_Scene (Result.Round_Before, Result.Plan_Before, Result.Robots,
                                 Map'Access), Tasks => True);
      end if;
      if Result.Plan_After.Generation > 0 then
         Picture ("plan-after", "Plan after the re-planning (round"
                  & Result.Plan_After.Generation'Image & ")"
                  & (if Lost = "" then "" else ", " & Lost),
                  Planned_Scene (Result.Round_After, Result.Plan_After, Result.Robots,
                                 Map'Access), Tasks => True);
      end if;
      Write_Gantt (Result, Dir);
      Create (F, Out_File, Dir & "/summary.json");
      Put (F, Summary_JSON (Result));
      Close (F);
      Put_Line ("report: " & Dir & "/{summary.json,trajectories,plan-before,plan-after}"
                & ".{svg,png}, gantt.{svg,png}");
   end Write_Report;

   function Summary_JSON (Result : Demo_Result) return String is
      J : Unbounded_String;
      function Q (S : String) return String renames Runtime.Values.JSON_String;
   begin
      Append (J, "{" & ASCII.LF);
      Append (J, "  ""tasks_total"": " & Trim (Result.Tasks_Total) & "," & ASCII.LF);
      Append (J, "  ""tasks_done"": " & Trim (Result.Tasks_Done) & "," & ASCII.LF);
      Append (J, "  ""duplicates"": " & Trim (Result.Duplicates) & "," & ASCII.LF);
      Append (J, "  ""all_done"": " & (if Result.All_Done then "true" else "false") & ","
              & ASCII.LF);
      Append (J, "  ""makespan_s"": " & Img (Result.Makespan) & "," & ASCII.LF);
      Append (J, "  ""killed"": " & Q (To_String (Result.Killed)) & "," & ASCII.LF);
      Append (J, "  ""kill_time_s"": " & Img (Result.Kill_Time) & "," & ASCII.LF);
      Append (J, "  ""replanned"": " & (if Result.Replanned then "true" else "false") & ","
              & ASCII.LF);
      Append (J, "  ""replan_wall_s"": " & Img (Result.Replan_Wall) & "," & ASCII.LF);
      Append (J, "  ""replan_sim_s"": " & Img (Result.Replan_Sim) & "," & ASCII.LF);
      Append (J, "  ""cut_robot"": " & Q (To_String (Result.Cut_Robot)) & "," & ASCII.LF);
      Append (J, "  ""converged"": " & (if Result.Converged then "true" else "false") & ","
              & ASCII.LF);
      Append (J, "  ""converge_wall_s"": " & Img (Result.Converge_Wall) & "," & ASCII.LF);
      Append (J, "  ""converge_keys"": " & Trim (Result.Converge_Keys) & "," & ASCII.LF);
      Append (J, "  ""first_plan_s"": " & Img (Result.Plan_Time) & "," & ASCII.LF);
      Append (J, "  ""planned_total_m"": " & Img (Result.Planned_Total) & "," & ASCII.LF);
      Append (J, "  ""planned_makespan_m"": " & Img (Result.Planned_Makespan) & ","
              & ASCII.LF);
      Append (J, "  ""planned_grid_total_m"": " & Img (Result.Grid_Total) & "," & ASCII.LF);
      Append (J, "  ""planned_grid_makespan_m"": " & Img (Result.Grid_Makespan) & ","
              & ASCII.LF);
      Append (J, "  ""executed_total_m"": " & Img (Result.Executed_Total) & "," & ASCII.LF);
      Append (J, "  ""rounds"": " & Trim (Result.Rounds) & "," & ASCII.LF);
      Append (J, "  ""collisions"": " & Trim (Result.Collisions) & "," & ASCII.LF);
      Append (J, "  ""robots"": [" & ASCII.LF);
      for K in 1 .. Natural (Result.Robots.Length) loop
         declare
            R : constant Robot_Summary := Result.Robots (K);
         begin
            Append (J, "    {""id"": " & Q (To_String (R.Id)) & ", ""tasks"": "
                    & Trim (R.Tasks) & ", ""distance_m"": " & Img (R.Distance)
                    & ", ""alive"": " & (if R.Alive then "true" else "false")
                    & ", ""travel_s"": " & Img (R.Travel) & ", ""at_task_s"": "
                    & Img (R.At_Task) & ", ""stopped_s"": " & Img (R.Stopped) & "}"
                    & (if K < Natural (Result.Robots.Length) then "," else "") & ASCII.LF);
         end;
      end loop;
      Append (J, "  ]," & ASCII.LF & "  ""completions"": [" & ASCII.LF);
      for K in 1 .. Natural (Result.Completions.Length) loop
         declare
            C : constant Completion := Result.Completions (K);
         begin
            Append (J, "    {""task"": " & Q (To_String (C.Task_Id)) & ", ""robot"": "
                    & Q (To_String (C.Robot)) & ", ""time_s"": " & Img (C.Time)
                    & (if C.Reached < 0.0 then "" else ", ""reached_s"": " & Img (C.Reached))
                    & "}" & (if K < Natural (Result.Completions.Length) then "," else "")
                    & ASCII.LF);
         end;
      end loop;
      Append (J, "  ]," & ASCII.LF & "  ""reallocated"": [" & ASCII.LF);
      for K in 1 .. Natural (Result.Orphans.Length) loop
         declare
            C : constant Completion := Result.Orphans (K);
         begin
            Append (J, "    {""task"": " & Q (To_String (C.Task_Id)) & ", ""done_by"": "
                    & Q (To_String (C.Robot)) & ", ""time_s"": " & Img (C.Time) & "}"
                    & (if K < Natural (Result.Orphans.Length) then "," else "")
                    & ASCII.LF);
         end;
      end loop;
      Append (J, "  ]" & ASCII.LF & "}" & ASCII.LF);
      return To_String (J);
   end Summary_JSON;

   procedure Print_Summary (Result : Demo_Result) is
   begin
      Put_Line ("== summary ==");
      Put_Line ("tasks done:" & Result.Tasks_Done'Image & " /" & Result.Tasks_Total'Image
                & (if Result.All_Done then "  (all done)" else "  (NOT all done)")
                & "; completed more than once:" & Result.Duplicates'Image);
      Put_Line ("robot       tasks   distance (m)   going (s)   at tasks (s)   stopped (s)");
      for R of Result.Robots loop
         Put_Line (Ada.Strings.Fixed.Head (To_String (R.Id) & (if R.Alive then "" else " (lost)"),
                   12) & Ada.Strings.Fixed.Tail (Trim (R.Tasks), 5) & "   "
                   & Ada.Strings.Fixed.Tail (F1 (R.Distance), 12)
                   & Ada.Strings.Fixed.Tail (F1 (R.Travel), 12)
                   & Ada.Strings.Fixed.Tail (F1 (R.At_Task), 15)
                   & Ada.Strings.Fixed.Tail (F1 (R.Stopped), 14));
      end loop;
      Put_Line ("(going, at tasks, stopped: from the first plan to the robot's last task done;"
                & " gantt.png)");
      Put_Line ("makespan: " & F1 (Result.Makespan) & " s simulated, from the start to the last"
                & " task done (first plan at " & F1 (Result.Plan_Time) & " s)");
      if Result.Killed /= Null_Unbounded_String then
         Put_Line ("robot lost: " & To_String (Result.Killed) & " at " & F1 (Result.Kill_Time)
                   & " s; re-planned: " & (if Result.Replanned then "yes" else "no")
                   & ", " & F1 (Result.Replan_Wall) & " s wall ("
                   & F1 (Result.Replan_Sim) & " s simulated) after the loss, lease included");
         Put ("its unfinished tasks, re-allocated (task>robot that did it):");
         for O of Result.Orphans loop
            Put (" " & To_String (O.Task_Id) & ">"
                 & (if O.Robot = Null_Unbounded_String then "nobody" else To_String (O.Robot)));
         end loop;
         New_Line;
      end if;
      if Result.Cut_Robot /= Null_Unbounded_String then
         Put_Line ("partition: " & To_String (Result.Cut_Robot) & " cut off and healed; replicas "
                   & (if Result.Converged
                      then "converged" & Result.Converge_Keys'Image & " keys in "
                           & F1 (Result.Converge_Wall) & " s wall after the heal"
                      else "did NOT converge"));
      end if;
      Put_Line ("planned cost (first plan): total " & F1 (Result.Planned_Total)
                & " m, longest tour " & F1 (Result.Planned_Makespan) & " m with straight"
                & " legs; " & F1 (Result.Grid_Total) & " m, longest tour "
                & F1 (Result.Grid_Makespan) & " m along A* paths");
      Put_Line ("executed: total distance " & F1 (Result.Executed_Total) & " m; rounds of"
                & " allocation:" & Result.Rounds'Image & "; collisions:" & Result.Collisions'Image);
   end Print_Summary;

   procedure Note_First_Plan
     (Result : in out Demo_Result;
      S      : Plans.Snapshot;
      P      : Plans.Plan;
      Grid   : Worlds.World)
   is
      Map : Robot.Path_Costs.Planner;

      function Leg (From, To : Point) return Long_Float is
         C : constant Real := Map.Cost (From, To);
      begin
         return (if C = Robot.Path_Costs.Unreachable then Long_Float (Distance (From, To))
                 else Long_Float (C));
      end Leg;
   begin
      Map.Initialize (Worlds.Occupancy (Grid), Robot_Radius => 0.3);
      Result.Planned_Total := Plans.Total (S, P);
      Result.Planned_Makespan := Plans.Makespan (S, P);
      Result.Grid_Total := Plans.Total (S, P, Leg'Access);
      Result.Grid_Makespan := Plans.Makespan (S, P, Leg'Access);
   end Note_First_Plan;

   procedure Run (Config : Demo_Config; Result : out Demo_Result) is
      use type Ada.Real_Time.Time;
      M       : constant Missions.Mission := Missions.Read (To_String (Config.Mission_File));
      World_F : constant String :=
        (if Config.World_File /= Null_Unbounded_String then To_String (Config.World_File)
         else To_String (M.World));
      World   : Worlds.World;
      Map     : Robot.Path_Costs.Planner;
      Sim     : Simulator;
      N       : constant Natural := Natural (M.Robots.Length);
   begin
      Result := (others => <>);
      if N < 2 then
         raise Constraint_Error with To_String (Config.Mission_File)
           & ": the demo needs at least two <robot> starts";
      elsif World_F = "" then
         raise Constraint_Error with To_String (Config.Mission_File)
           & ": no world (attribute world= of <mission>, or --world)";
      end if;
      World := Map_Files.Load_World (World_F);
      Map.Initialize (Worlds.Occupancy (World), Robot_Radius => 0.3);
      Sim.Initialize (World, Seed => 1);
      for R of M.Robots loop
         if not Map.Is_Free (Position (R.Start)) then
            raise Missions.Format_Error with To_String (Config.Mission_File) & ": robot "
              & To_String (R.Id) & ": start " & F1 (Long_Float (R.Start.X)) & ","
              & F1 (Long_Float (R.Start.Y)) & " is outside the world or in a wall of "
              & World_F;
         end if;
      end loop;
      for T of M.Tasks loop
         for P of T.Points loop
            if not Map.Is_Free (P)
              or else Map.Cost (Position (M.Robots (1).Start), P) = Robot.Path_Costs.Unreachable
            then
               raise Missions.Format_Error with To_String (Config.Mission_File) & ": task "
                 & To_String (T.Id) & ": point " & F1 (Long_Float (P.X)) & ","
                 & F1 (Long_Float (P.Y)) & " is not reachable in " & World_F;
            end if;
         end loop;
      end loop;
      declare
         Agent_List : array (1 .. N) of Agents.Agent_Access;
         Navs       : array (1 .. N) of Robot.Navigators.Navigator;
         Nav_Task   : array (1 .. N) of Unbounded_String;
         Nav_Goal   : array (1 .. N) of Point := [others => (Real'Last, Real'Last)];
         Last_Pos   : array (1 .. N) of Point;
         Next_Pose  : Long_Float := 0.0;
         Next_Track : array (1 .. N) of Long_Float := [others => 0.0];
         Next_Rec   : Long_Float := 0.0;
         Next_Print : Long_Float := 0.0;
         Alive      : array (1 .. N) of Boolean := [others => True];
         Stopped    : array (0 .. N) of Boolean := [others => False];
         --  Agents (0: the operator) already stopped by Stop_All.
         Victim     : Natural := 0;
         Kill_Wall  : Ada.Real_Time.Time;
         Kill_Gen   : Natural := 0;
         Scene      : Rendering.Scene;
         Operator   : Agents.Agent_Access;
         Start_Wall : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
         Id         : Robot_Id;
         Count      : array (1 .. Natural (M.Tasks.Length)) of Natural := [others => 0];
         type Cut_Phase is (Before_Cut, Cut_Off, Healed, Measured);
         Cut_State  : Cut_Phase := (if Config.Cut_For > 0.0 then Before_Cut else Measured);
         Cut_Index  : Natural := 0;
         Cut_Wall   : Ada.Real_Time.Time;
         Heal_Wall  : Ada.Real_Time.Time;
         Next_Check : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
         type Version is record
            Revision : Long_Long_Integer := 0;
            Writer   : Unbounded_String;
         end record;
         package Version_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Version);
         Target     : Version_Maps.Map;

         function Newer (A, B : Version) return Boolean is
           (A.Revision > B.Revision
            or else (A.Revision = B.Revision and then A.Writer > B.Writer));
         --  The order of the replicated databases: by revision, then writer.

         function Version_Of
           (Db : Replicated_Databases.Team_Database_Access; Key : String) return Version is
           ((Db.Revision (Key), To_Unbounded_String (Db.Writer (Key))));

         function Observer return Agents.Agent_Access is
         begin
            for R in 1 .. N loop
               if Alive (R) then
                  return Agent_List (R);
               end if;
            end loop;
            return Operator;
         end Observer;

         function Robot_Of (Id : Unbounded_String) return Natural is
         begin
            for R in 1 .. N loop
               if M.Robots (R).Id = Id then
                  return R;
               end if;
            end loop;
            return 0;
         end Robot_Of;

         procedure Record_Completion (R : Positive; Task_Id : Unbounded_String) is
         begin
            Result.Completions.Append
              (Completion'(Task_Id, M.Robots (R).Id, Long_Float (Sim.Clock), others => <>));
            Result.Robots (R).Tasks := Result.Robots (R).Tasks + 1;
            for T in 1 .. Natural (M.Tasks.Length) loop
               if M.Tasks (T).Id = Task_Id then
                  Count (T) := Count (T) + 1;
               end if;
            end loop;
            if Config.Run.Verbose then
               Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  " & To_String (M.Robots (R).Id)
                         & " did " & To_String (Task_Id) & "  ("
                         & Trim (Natural (Result.Completions.Length)) & "/"
                         & Trim (Result.Tasks_Total)
                         & ")");
            end if;
         end Record_Completion;

         function Done_Here (Task_Id : String) return Boolean is
           (Operator.Database.Contains ("done/" & Task_Id));

         procedure Kill (R : Positive) is
         begin
            Victim := R;
            Alive (R) := False;
            Sim.Kill (Robot_Id (R));
            Agent_List (R).Stop;
            Kill_Wall := Ada.Real_Time.Clock;
            Result.Killed := M.Robots (R).Id;
            Result.Kill_Time := Long_Float (Sim.Clock);
            Result.Robots (R).Alive := False;
            Kill_Gen := Observer.Round.Generation;
            Result.Plan_Before := Observer.Adopted;
            Result.Round_Before := Observer.Round;
            Result.Orphans := Unfinished
              (Result.Round_Before, Result.Plan_Before, To_String (M.Robots (R).Id),
               Done_Here'Access);
            Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  ** robot "
                      & To_String (M.Robots (R).Id) & " killed (simulator kill, agent stopped)");
         end Kill;

         procedure Newest_At_Heal is
            --  The newest (revision, writer) of every key on any node.
            procedure Take (Db : Replicated_Databases.Team_Database_Access) is
            begin
               for K of Db.Keys loop
                  if not Target.Contains (K) or else Newer (Version_Of (Db, K), Target (K)) then
                     Target.Include (K, Version_Of (Db, K));
                  end if;
               end loop;
            end Take;
         begin
            Target.Clear;
            Take (Operator.Database);
            for R in 1 .. N loop
               if Alive (R) then
                  Take (Agent_List (R).Database);
               end if;
            end loop;
         end Newest_At_Heal;

         function Caught_Up return Boolean is
            function Holds (Db : Replicated_Databases.Team_Database_Access) return Boolean is
              (for all C in Target.Iterate =>
                 not Newer (Version_Maps.Element (C), Version_Of (Db, Version_Maps.Key (C))));
            --  Db has every key of Target at its version or newer.
         begin
            return Holds (Operator.Database)
              and then (for all R in 1 .. N =>
                          not Alive (R) or else Holds (Agent_List (R).Database));
         end Caught_Up;

         procedure Partition_Step is
            use type Ada.Real_Time.Time_Span;
            Now : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
         begin
            case Cut_State is
               when Before_Cut =>
                  if Long_Float (Operator.Done_Tasks)
                    >= Config.Cut_Fraction * Long_Float (Result.Tasks_Total)
                  then
                     for R in reverse 1 .. N loop
                        if Alive (R) and then Cut_Index = 0 then
                           Cut_Index := R;
                        end if;
                     end loop;
                     Agent_List (Cut_Index).Network.Isolate (True);
                     Cut_Wall := Now;
                     Cut_State := Cut_Off;
                     Result.Cut_Robot := M.Robots (Cut_Index).Id;
                     Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  ** robot "
                               & To_String (M.Robots (Cut_Index).Id) & " cut off from the team"
                               & " for " & F1 (Long_Float (Config.Cut_For)) & " s (wall)");
                  end if;
               when Cut_Off =>
                  if Now - Cut_Wall >= Ada.Real_Time.To_Time_Span (Config.Cut_For) then
                     Agent_List (Cut_Index).Network.Isolate (False);
                     Heal_Wall := Now;
                     Newest_At_Heal;
                     Result.Converge_Keys := Natural (Target.Length);
                     Cut_State := Healed;
                     Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  ** robot "
                               & To_String (M.Robots (Cut_Index).Id) & " reconnected");
                  end if;
               when Healed =>
                  if Now >= Next_Check then
                     Next_Check := Now + Ada.Real_Time.Milliseconds (50);
                     if Caught_Up then
                        Result.Converged := True;
                        Result.Converge_Wall :=
                          Long_Float (Ada.Real_Time.To_Duration (Now - Heal_Wall));
                        Cut_State := Measured;
                        Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  replicas converged"
                                  & Result.Converge_Keys'Image & " keys in "
                                  & F1 (Result.Converge_Wall) & " s (wall) after the heal");
                     end if;
                  end if;
               when Measured =>
                  null;
            end case;
         end Partition_Step;

         procedure Stop_All is
            --  Every agent still running (and the operator), each even if
            --  another fails: their tasks would keep the program alive.
         begin
            for R in 1 .. N loop
               if Alive (R) and then not Stopped (R) then
                  Stopped (R) := True;
                  begin
                     Agent_List (R).Stop;
                  exception
                     when E : others =>
                        Put_Line (Standard_Error, "demo: stopping " & To_String (M.Robots (R).Id)
                                  & ": " & Ada.Exceptions.Exception_Message (E));
                  end;
               end if;
            end loop;
            if not Stopped (0) then
               Stopped (0) := True;
               begin
                  Operator.Stop;
               exception
                  when E : others =>
                     Put_Line (Standard_Error, "demo: stopping the operator: "
                               & Ada.Exceptions.Exception_Message (E));
               end;
            end if;
         end Stop_All;

         procedure Report_Unfinished is
            --  The mission ran out of time: where each robot with a task
            --  left stands, what it heads for, how far it moved in the last
            --  60 s (the trajectory keeps a point every 0.5 s) and the
            --  nearest other robot, so that a stall can be told from a slow
            --  robot.
         begin
            for R in 1 .. N loop
               if Alive (R) then
                  declare
                     Found : Boolean;
                     Goal  : Point;
                     Tid   : Unbounded_String;
                     Here  : constant Point := Position (Sim.Ground_Truth (Robot_Id (R)).Pose);
                     Path  : Rendering.Point_Vectors.Vector renames Scene.Trajectories (R);
                     Moved : Long_Float := 0.0;
                     Near  : Long_Float := Long_Float'Last;
                     Who   : Natural := 0;
                  begin
                     Agent_List (R).Current_Goal (Found, Goal, Tid);
                     if Found then
                        for K in Integer'Max (Path.First_Index + 1, Path.Last_Index - 119)
                                 .. Path.Last_Index
                        loop
                           Moved := Moved + Long_Float (Distance (Path (K - 1), Path (K)));
                        end loop;
                        for O in 1 .. N loop
                           if O /= R and then Alive (O) and then Long_Float
                             (Distance (Here, Position (Sim.Ground_Truth (Robot_Id (O)).Pose)))
                             < Near
                           then
                              Near := Long_Float (Distance
                                (Here, Position (Sim.Ground_Truth (Robot_Id (O)).Pose)));
                              Who := O;
                           end if;
                        end loop;
                        Put_Line
                          ("t=" & F1 (Long_Float (Sim.Clock)) & " s  unfinished: "
                           & To_String (M.Robots (R).Id) & " on " & To_String (Tid) & " at "
                           & F2 (Here) & " heading for " & F2 (Navs (R).Waypoint)
                           & (if Navs (R).Has_Path then " (A* path to " else " (no path to ")
                           & F2 (Goal) & "), moved " & F1 (Moved) & " m in the last 60 s"
                           & (if Who = 0 then ""
                              else ", nearest robot " & To_String (M.Robots (Who).Id) & " at "
                                   & F2 (Position (Sim.Ground_Truth (Robot_Id (Who)).Pose))
                                   & " (" & F2 (Near) & " m)"));
                     end if;
                  end;
               end if;
            end loop;
         end Report_Unfinished;

         function Choose_Victim return Positive is
            Best   : Positive := 1;
            Most   : Integer := -1;
            P      : constant Plans.Plan := Observer.Adopted;
            S      : constant Plans.Snapshot := Observer.Round;
         begin
            if Config.Run.Kill_Robot /= Null_Unbounded_String then
               if Robot_Of (Config.Run.Kill_Robot) = 0 then
                  raise Constraint_Error with "--kill " & To_String (Config.Run.Kill_Robot)
                    & ": no such robot in the mission";
               end if;
               return Robot_Of (Config.Run.Kill_Robot);
            end if;
            for K in 1 .. Natural (P.Tours.Length) loop
               declare
                  Left : Natural := 0;
               begin
                  for St of P.Tours (K) loop
                     if not Operator.Database.Contains ("done/" & To_String (St.Task_Id)) then
                        Left := Left + 1;
                     end if;
                  end loop;
                  if Left > Most and then Robot_Of (S.Robots (K).Id) /= 0 then
                     Most := Left;
                     Best := Robot_Of (S.Robots (K).Id);
                  end if;
               end;
            end loop;
            return Best;
         end Choose_Victim;
      begin
         Result.Tasks_Total := Natural (M.Tasks.Length);
         Put_Line ("demo: mission " & To_String (M.Name) & ":" & Result.Tasks_Total'Image
                   & " tasks," & N'Image & " robots, world " & World_F & ", allocation by "
                   & (case Config.How is when Agents.Annealing => "the distributed annealer",
                                         when Agents.Auctions => "auctions")
                   & ", simulation at" & Integer (Config.Rate)'Image & "x");
         for R in 1 .. N loop
            Sim.Add_Robot (Default_Robot, M.Robots (R).Start, Id,
                           Name => To_String (M.Robots (R).Id));
            Last_Pos (R) := Position (M.Robots (R).Start);
            Scene.Trajectories.Append (Rendering.Point_Vectors.Empty_Vector);
            Result.Robots.Append (Robot_Summary'(Id => M.Robots (R).Id, others => <>));
            Agent_List (R) := Agents.Create
              ((Id => M.Robots (R).Id, Team => Config.Team, Is_Robot => True,
                Lease => Config.Lease, Verbose => Config.Run.Verbose,
                How => Config.How, Seed => Interfaces.Unsigned_64 (R), others => <>));
            Agent_List (R).Set_Pose (Position (M.Robots (R).Start));
         end loop;
         Operator := Agents.Create
           ((Id => To_Unbounded_String ("operator"), Team => Config.Team, Is_Robot => False,
             Lease => Config.Lease,
             How => Config.How, others => <>));
         Operator.Publish_Mission (M);
         Sim.Step (0.1);
         begin
            while Long_Float (Sim.Clock) < Config.Run.Max_Seconds and then not Operator.All_Done
              and then not RCL.Contexts.Is_Shutdown
            loop
               for R in 1 .. N loop
                  if Alive (R) then
                     declare
                        Rid   : constant Robot_Id := Robot_Id (R);
                        Truth : constant Pose := Sim.Ground_Truth (Rid).Pose;
                        Here  : constant Point := Position (Truth);
                        Found : Boolean;
                        Goal  : Point;
                        Tid   : Unbounded_String;
                        Done  : Boolean;
                     begin
                        Result.Robots (R).Distance := Result.Robots (R).Distance
                          + Long_Float (Distance (Here, Last_Pos (R)));
                        Last_Pos (R) := Here;
                        if Long_Float (Sim.Clock) >= Next_Pose then
                           Agent_List (R).Set_Pose (Here);
                        end if;
                        Agent_List (R).Current_Goal (Found, Goal, Tid);
                        if not Found then
                           Sim.Set_Command (Rid, (0.0, 0.0));
                        else
                           if Tid /= Nav_Task (R) or else Goal /= Nav_Goal (R) then
                              Nav_Task (R) := Tid;
                              Nav_Goal (R) := Goal;
                              Navs (R).Set_Goal (Map, Truth, Goal);
                           end if;
                           if Distance (Here, Goal) < 0.35 then
                              Agent_List (R).Arrived (To_String (Tid), Done);
                              if Done then
                                 Record_Completion (R, Tid);
                              end if;
                              Sim.Set_Command (Rid, (0.0, 0.0));
                           else
                              Sim.Set_Command
                                (Rid, Navs (R).Command (Map, Truth, Sim.Latest_Scan (Rid),
                                                        Sim.Clock));
                           end if;
                        end if;
                        if Long_Float (Sim.Clock) >= Next_Rec then
                           Scene.Trajectories (R).Append (Here);
                        end if;
                        if Long_Float (Sim.Clock) >= Next_Track (R) then
                           Result.Robots (R).Track.Append
                             (Track_Sample'(Long_Float (Sim.Clock), Truth));
                           Next_Track (R) := Long_Float (Sim.Clock) + 0.9 * Track_Period;
                        end if;
                     end;
                  end if;
               end loop;
               if Long_Float (Sim.Clock) >= Next_Pose then
                  Next_Pose := Next_Pose + 0.5;
               end if;
               if Long_Float (Sim.Clock) >= Next_Rec then
                  Next_Rec := Next_Rec + 0.5;
               end if;
               if Result.Planned_Total = 0.0 and then Observer.Adopted.Generation > 0 then
                  Note_First_Plan (Result, Observer.Round, Observer.Adopted, World);
                  Result.Plan_Time := Long_Float (Sim.Clock);
                  Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  first plan adopted: total "
                            & F1 (Result.Planned_Total) & " m, longest tour "
                            & F1 (Result.Planned_Makespan) & " m (" & F1 (Result.Grid_Total)
                            & " m, " & F1 (Result.Grid_Makespan) & " m along A* paths)");
               end if;
               if Config.Run.Kill and then Victim = 0
                 and then Long_Float (Operator.Done_Tasks)
                   >= Config.Run.Kill_Fraction * Long_Float (Result.Tasks_Total)
                 and then Observer.Adopted.Generation > 0
               then
                  Kill (Choose_Victim);
               end if;
               if Result.Replanned then
                  Follow_Replan (Result, Observer.Adopted);
               end if;
               if Victim /= 0 and then not Result.Replanned then
                  declare
                     S : constant Plans.Snapshot := Observer.Round;
                     P : constant Plans.Plan := Observer.Adopted;
                  begin
                     if S.Generation > Kill_Gen and then P.Generation = S.Generation
                       and then (for all R of S.Robots => R.Id /= M.Robots (Victim).Id)
                     then
                        Result.Replanned := True;
                        Result.Replan_Wall := Long_Float
                          (Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Kill_Wall));
                        Result.Replan_Sim := Long_Float (Sim.Clock) - Result.Kill_Time;
                        Result.Plan_After := P;
                        Result.Round_After := S;
                        Put_Line ("t=" & F1 (Long_Float (Sim.Clock)) & " s  survivors re-planned "
                                  & Trim (Natural (S.Tasks.Length)) & " tasks among "
                                  & Trim (Natural (S.Robots.Length)) & " robots in "
                                  & F1 (Result.Replan_Wall) & " s (wall, lease included)");
                     end if;
                  end;
               end if;
               if Config.Run.Verbose and then Long_Float (Sim.Clock) >= Next_Print then
                  Next_Print := Next_Print + 20.0;
                  Put ("t=" & F1 (Long_Float (Sim.Clock)) & " s  progress "
                       & Trim (Operator.Done_Tasks) & "/" & Trim (Result.Tasks_Total)
                       & " tasks done  round" & Observer.Round.Generation'Image
                       & "  [ done per robot:");
                  for R in 1 .. N loop
                     Put (" " & To_String (M.Robots (R).Id) & ":" & Trim (Result.Robots (R).Tasks)
                          & (if Alive (R) then "" else " (lost)"));
                  end loop;
                  Put_Line (" ]");
               end if;
               Partition_Step;
               Sim.Step (0.1);
               delay until Start_Wall + Ada.Real_Time.To_Time_Span
                 (Duration (Long_Float (Sim.Clock) / Config.Rate));
            end loop;
         exception
            when E : RCL.ROS_Exception =>
               if not RCL.Contexts.Is_Shutdown then
                  Stop_All;
                  Ada.Exceptions.Reraise_Occurrence (E);
               end if;
               --  Else published as the context shut down (SIGINT/SIGTERM).
            when others =>
               Stop_All;  --  Their tasks would keep the program alive.
               raise;
         end;
         if RCL.Contexts.Is_Shutdown then
            Put_Line ("demo: interrupted (SIGINT or SIGTERM) at" & Integer (Sim.Clock)'Image
                      & " s (simulated): stopping the agents");
         end if;
         if not Operator.All_Done and then not RCL.Contexts.Is_Shutdown then
            Report_Unfinished;
         end if;
         Result.Makespan := Long_Float (Sim.Clock);
         declare
            Give_Up : constant Ada.Real_Time.Time :=
              Ada.Real_Time.Clock + Ada.Real_Time.Seconds (15);
         begin
            --  The mission may end before the replicas have converged (or
            --  before the heal): the measurement goes on, time stopped.
            while Cut_State in Cut_Off | Healed and then Ada.Real_Time.Clock < Give_Up
              and then not RCL.Contexts.Is_Shutdown
            loop
               Partition_Step;
               delay 0.02;
            end loop;
         end;
         Result.Tasks_Done := Operator.Done_Tasks;
         Result.All_Done := Operator.All_Done;
         Result.Rounds := Observer.Round.Generation;
         for C of Count loop
            if C > 1 then
               Result.Duplicates := Result.Duplicates + 1;
            end if;
         end loop;
         for R in 1 .. N loop
            Result.Executed_Total := Result.Executed_Total + Result.Robots (R).Distance;
            Result.Collisions := Result.Collisions + Sim.Collision_Count (Robot_Id (R));
            Scene.Robots.Append (Sim.Ground_Truth (Robot_Id (R)).Pose);
            if not Alive (R) then
               Scene.Lost.Append (Position (Sim.Ground_Truth (Robot_Id (R)).Pose));
            end if;
         end loop;
         for T of M.Tasks loop
            Scene.Markers.Append
              (Rendering.Marker'(T.Points (1),
                                 T.Id & ">"
                                 & Operator.Database.Get_String ("done/" & To_String (T.Id))));
         end loop;
         Stop_All;
         Resolve_Orphans (Result);
         Note_Arrivals (Result, M.Tasks);
         if Config.Run.Out_Dir /= Null_Unbounded_String then
            Write_Report (Result, World, Scene, To_String (Config.Run.Out_Dir));
         end if;
      exception
         when others =>
            Stop_All;  --  Our output closed after the loop ("| head"), say.
            raise;
      end;
   end Run;

end Sancta.Commands.Team_Demos;
