with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Geometry is

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   function Norm (A : Point) return Real is
     (Math.Sqrt (A.X * A.X + A.Y * A.Y));

   function Distance (A, B : Point) return Real is (Norm (A - B));

   function Normalize_Angle (A : Real) return Real is
      Two_Pi : constant Real := 2.0 * Pi;
      R      : Real := A - Two_Pi * Real'Floor (A / Two_Pi);
      --  R in [0, 2 Pi)
   begin
      if R > Pi then
         R := R - Two_Pi;
      end if;
      return Real'Max (-Pi, Real'Min (Pi, R));
   end Normalize_Angle;

   function Transform (Frame : Pose; Local : Point) return Point is
      C : constant Real := Math.Cos (Frame.Yaw);
      S : constant Real := Math.Sin (Frame.Yaw);
   begin
      return (Frame.X + C * Local.X - S * Local.Y,
              Frame.Y + S * Local.X + C * Local.Y);
   end Transform;

   function Compose (Frame : Pose; Local : Pose) return Pose is
      P : constant Point := Transform (Frame, (Local.X, Local.Y));
   begin
      return (P.X, P.Y, Normalize_Angle (Frame.Yaw + Local.Yaw));
   end Compose;

   function Relative (Frame : Pose; Global : Pose) return Pose is
      C  : constant Real := Math.Cos (Frame.Yaw);
      S  : constant Real := Math.Sin (Frame.Yaw);
      DX : constant Real := Global.X - Frame.X;
      DY : constant Real := Global.Y - Frame.Y;
   begin
      return (C * DX + S * DY, -S * DX + C * DY,
              Normalize_Angle (Global.Yaw - Frame.Yaw));
   end Relative;

end Sancta.Geometry;
