package body Sancta.Robot.Navigators is

   Waypoint_Reach : constant := 0.35;
   --  An intermediate waypoint counts as passed this close.

   Stall_Time : constant := 8.0;
   --  Replan after this long without getting closer to the goal.

   Clear_Progress : constant := 1.0;
   --  Drop the temporary obstacle layer this much closer to the goal.

   procedure Configure
     (This : in out Navigator; Config : Controllers.Controller_Config) is
   begin
      This.Config := Config;
   end Configure;

   procedure Plan (This : in out Navigator; Map : Path_Costs.Planner; Current : Pose) is
   begin
      if not This.Seen.Is_Empty then
         This.Path := Path_Costs.Path (Map, Position (Current), This.Goal, This.Seen);
         if This.Path.Is_Empty then
            --  Nothing round what is seen (e.g. a robot on the goal): the
            --  map's path, as without the layer.
            This.Seen.Clear;
         end if;
      end if;
      if This.Seen.Is_Empty then
         This.Path := Path_Costs.Path (Map, Position (Current), This.Goal);
      end if;
      This.Planned := not This.Path.Is_Empty;
      if not This.Planned then
         This.Path.Clear;
         This.Path.Append (This.Goal);
      end if;
      This.Next := 1;
   end Plan;

   procedure Set_Goal
     (This    : in out Navigator;
      Map     : Path_Costs.Planner;
      Current : Pose;
      Goal    : Point) is
   begin
      This.Goal := Goal;
      This.Active := True;
      This.Done := False;
      This.Best := Real'Last;
      This.Seen.Clear;
      Plan (This, Map, Current);
   end Set_Goal;

   function Seen_Obstacles
     (Map : Path_Costs.Planner; Current : Pose; Scan : Laser_Scan)
      return Path_Costs.Point_Vectors.Vector
   is
      --  The scan's points (in the map frame) that fall where the map is
      --  free: not walls, so other robots or anything not on the map.
      Result : Path_Costs.Point_Vectors.Vector;
   begin
      for B in 1 .. Scan.Beams loop
         if Is_Valid (Scan, B) then
            declare
               P : constant Point := Transform (Current, Beam_Point (Scan, B));
            begin
               if Path_Costs.Is_Free (Map, P) then
                  Result.Append (P);
               end if;
            end;
         end if;
      end loop;
      return Result;
   end Seen_Obstacles;

   function Has_Path (This : Navigator) return Boolean is (This.Planned);

   function Arrived (This : Navigator) return Boolean is (This.Done);

   function Waypoint (This : Navigator) return Point is
     (if This.Active and then not This.Path.Is_Empty then This.Path (This.Next)
      else This.Goal);

   function Command
     (This    : in out Navigator;
      Map     : Path_Costs.Planner;
      Current : Pose;
      Scan    : Laser_Scan;
      Now     : Real) return Twist
   is
      To_Goal : constant Real := Distance (Position (Current), This.Goal);
   begin
      if not This.Active or else This.Done then
         return (0.0, 0.0);
      end if;
      if Controllers.Reached (This.Config, Current, This.Goal) then
         This.Done := True;
         return (0.0, 0.0);
      end if;
      if To_Goal < This.Best - 0.05 then
         This.Best := To_Goal;
         This.Best_Time := Now;
         if To_Goal < This.Seen_From - Clear_Progress then
            This.Seen.Clear;
         end if;
      elsif Now - This.Best_Time > Stall_Time then
         This.Seen := Seen_Obstacles (Map, Current, Scan);
         This.Seen_From := To_Goal;
         Plan (This, Map, Current);
         This.Best := To_Goal;
         This.Best_Time := Now;
      end if;
      --  Skip the waypoints already reached or already in sight beyond.
      while This.Next < This.Path.Last_Index
        and then (Distance (Position (Current), This.Path (This.Next)) < Waypoint_Reach
                  or else (This.Seen.Is_Empty
                           --  (the map's line of sight does not know Seen)
                           and then Path_Costs.Line_Of_Sight
                             (Map, Position (Current), This.Path (This.Next + 1))
                           and then Distance (Position (Current), This.Path (This.Next))
                                      < 1.0))
      loop
         This.Next := This.Next + 1;
      end loop;
      declare
         Config : Controllers.Controller_Config := This.Config;
      begin
         if This.Next < This.Path.Last_Index then
            Config.Goal_Tolerance := 0.0;
         end if;
         return Controllers.Command (Config, Current, This.Path (This.Next), Scan);
      end;
   end Command;

end Sancta.Robot.Navigators;
