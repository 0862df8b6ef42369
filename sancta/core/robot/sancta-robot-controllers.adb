with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Robot.Controllers is

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   function Clamp (V, Limit : Real) return Real is
     (Real'Max (-Limit, Real'Min (Limit, V)));

   type Point_Array is array (Positive range <>) of Point;

   function Points_Of (Scan : Laser_Scan) return Point_Array is
      Result : Point_Array (1 .. Scan.Beams);
      Last   : Natural := 0;
   begin
      for B in 1 .. Scan.Beams loop
         if Is_Valid (Scan, B) then
            Last := Last + 1;
            Result (Last) := Beam_Point (Scan, B);
         end if;
      end loop;
      return Result (1 .. Last);
   end Points_Of;

   function Free_Along
     (Config : Controller_Config; Points : Point_Array; Limit, Heading : Real) return Real
   is
      Reach  : constant Real := Config.Robot_Radius + Config.Margin;
      C      : constant Real := Math.Cos (Heading);
      S      : constant Real := Math.Sin (Heading);
      Result : Real := Limit;
   begin
      for P of Points loop
         declare
            Lon : constant Real := C * P.X + S * P.Y;
            Lat : constant Real := -S * P.X + C * P.Y;
         begin
            if Lon > 0.0 and then abs Lat < Reach and then Lon - Reach < Result then
               Result := Real'Min (Result, Lon - Math.Sqrt (Reach * Reach - Lat * Lat));
            end if;
         end;
      end loop;
      return Real'Max (0.0, Result);
   end Free_Along;

   function Free_Distance
     (Config : Controller_Config; Scan : Laser_Scan; Heading : Real) return Real is
     (Free_Along (Config, Points_Of (Scan), Scan.Range_Max, Heading));

   function Command
     (Config  : Controller_Config;
      Current : Pose;
      Goal    : Point;
      Scan    : Laser_Scan) return Twist
   is
      To_Goal : constant Real := Distance (Position (Current), Goal);
      Bearing : constant Real :=
        (if To_Goal = 0.0 then 0.0  --  Arctan (0, 0) is undefined: at the goal
         else Normalize_Angle
                (Math.Arctan (Goal.Y - Current.Y, Goal.X - Current.X) - Current.Yaw));
      Need    : constant Real := Real'Min (To_Goal, Config.Look_Ahead);
      Step    : constant Real := Pi / 36.0;
      Best    : Real := 0.0;
      Best_Score : Real := Real'Last;
      Widest  : Real := 0.0;
      Widest_Free : Real := -1.0;
      Found   : Boolean := False;
      Heading : Real;
      Ahead   : Real;
      Points  : constant Point_Array := Points_Of (Scan);
   begin
      if To_Goal <= Config.Goal_Tolerance then
         return (0.0, 0.0);
      end if;
      for K in -36 .. 35 loop
         declare
            H     : constant Real := Real (K) * Step;
            Free  : constant Real := Free_Along (Config, Points, Scan.Range_Max, H);
            Off   : constant Real := abs Normalize_Angle (H - Bearing);
            Score : constant Real :=
              Off + (if Normalize_Angle (H - Bearing) > 0.0 then 0.05 else 0.0);
         begin
            if Free >= Need and then Score < Best_Score then
               Best := H;
               Best_Score := Score;
               Found := True;
            end if;
            if Free > Widest_Free then
               Widest := H;
               Widest_Free := Free;
            end if;
         end;
      end loop;
      --  The goal's own bearing, if free, beats the 5-degree candidates.
      if Free_Along (Config, Points, Scan.Range_Max, Bearing) >= Need then
         Best := Bearing;
         Found := True;
      end if;
      Heading := (if Found then Best else Widest);
      Ahead := Free_Along (Config, Points, Scan.Range_Max, 0.0);
      declare
         Turn   : constant Real := Clamp (Config.Heading_Gain * Heading, Config.Max_Angular);
         Align  : constant Real := Real'Max (0.0, Math.Cos (Heading));
         Speed  : constant Real :=
           Config.Max_Linear * Align * Align
             * Real'Min (1.0, Ahead / Config.Slow_Down)
             * Real'Min (1.0, To_Goal / 0.5 + 0.2);
      begin
         return (Linear_X  =>
                   (if abs Heading > Pi / 3.0 or else Ahead < 0.05 then 0.0
                    else Real'Min (Speed, Ahead)),
                 Angular_Z => Turn);
      end;
   end Command;

end Sancta.Robot.Controllers;
