--  Heading correction from walls of known orientation (multiples of
--  pi/2, as in most buildings): local wall directions are measured from
--  short straight runs of scan points, brought to the world frame with the
--  estimated heading and folded into (-pi/4, pi/4]; when enough of them
--  lie within the tolerance of a wall direction, their median is the
--  heading error.
--
--     Align (Estimate, Scan, Aligned => Ok);  --  Estimate.Yaw corrected
with Sancta.Geometry;       use Sancta.Geometry;
with Sancta.Robot.Sensors;  use Sancta.Robot.Sensors;

package Sancta.Robot.Aligners
  with Pure
is

   Default_Tolerance : constant := 0.17;

   type Aligner_Config is record
      Tolerance   : Real := Default_Tolerance;
      --  Largest heading error corrected, rad.
      Min_Support : Positive := 15;
      --  Wall pieces needed to decide.
      Span        : Positive := 4;
      --  Beams between the ends of a wall piece.
      Straightness : Real := 0.02;
      --  Largest distance of the middle beam to the piece's line, m.
   end record;

   procedure Estimate_Error
     (Config  : Aligner_Config;
      Heading : Real;
      Scan    : Laser_Scan;
      Error   : out Real;
      Found   : out Boolean);
   --  Error: how much Heading exceeds the walls' direction (subtract it).

   procedure Align
     (Estimate : in out Pose;
      Scan     : Laser_Scan;
      Aligned  : out Boolean;
      Config   : Aligner_Config := (others => <>));

end Sancta.Robot.Aligners;
