with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Robot.Sensors is

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   function Beam_Point (Scan : Laser_Scan; Beam : Positive) return Point is
      A : constant Real := Beam_Angle (Scan, Beam);
      R : constant Real := Scan.Ranges (Beam);
   begin
      return (R * Math.Cos (A), R * Math.Sin (A));
   end Beam_Point;

end Sancta.Robot.Sensors;
