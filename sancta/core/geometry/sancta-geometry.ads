--  Plane geometry shared by the planner, the simulator and the robot
--  components: points, poses (x, y, heading) and their operations.
--
--     P : constant Pose := (X => 1.0, Y => 2.0, Yaw => Pi / 2.0);
--     Q : constant Point := Transform (P, (1.0, 0.0));  --  (1.0, 3.0)
with Ada.Numerics;

package Sancta.Geometry
  with Pure
is

   type Real is new Long_Float;
   --  Metres, radians, seconds: geometry is computed in double precision.

   Pi : constant := Ada.Numerics.Pi;

   type Point is record
      X, Y : Real := 0.0;
   end record;

   type Pose is record
      X, Y : Real := 0.0;
      Yaw  : Real := 0.0;
      --  Heading in radians, counter-clockwise from +X.
   end record;

   function "+" (A, B : Point) return Point is ((A.X + B.X, A.Y + B.Y));
   function "-" (A, B : Point) return Point is ((A.X - B.X, A.Y - B.Y));
   function "*" (K : Real; A : Point) return Point is ((K * A.X, K * A.Y));

   function Position (P : Pose) return Point is ((P.X, P.Y));

   function Distance (A, B : Point) return Real;
   --  Euclidean distance.

   function Norm (A : Point) return Real;

   function Normalize_Angle (A : Real) return Real
     with Post => Normalize_Angle'Result in -Pi .. Pi;
   --  The same angle in [-Pi, Pi].

   function Transform (Frame : Pose; Local : Point) return Point;
   --  A point given in Frame's coordinates, expressed in the world frame.

   function Compose (Frame : Pose; Local : Pose) return Pose;
   --  Frame (+) Local: a pose relative to Frame, expressed in the world.

   function Relative (Frame : Pose; Global : Pose) return Pose;
   --  The inverse of Compose: Global expressed in Frame's coordinates.

end Sancta.Geometry;
