--  Scan matching by point-to-line ICP, and an odometry corrector built on
--  it. Match finds the pose of a new scan relative to a reference scan,
--  starting from a guess (the odometry increment): each point of the new
--  scan is paired with the nearest reference point (searched among the
--  reference beams of similar bearing) and the line through that point and
--  its closer neighbour; the worst pairs are dropped (Filter) and a
--  Gauss-Newton step minimises the point-to-line distances, until the step
--  is below Error_Ratio or Max_Iterations is reached (MbICP's defaults).
--  The corrector matches each scan against a keyframe and chains the
--  keyframes, so odometry drift is replaced by the (much smaller) matching
--  error.
--
--     C.Update (Odometry.Pose, Scan);
--     Estimate := C.Corrected;
with Ada.Containers.Vectors;
with Sancta.Geometry;       use Sancta.Geometry;
with Sancta.Robot.Sensors;  use Sancta.Robot.Sensors;

package Sancta.Robot.Scan_Matchers is

   type Matcher_Config is record
      Max_Iterations    : Positive := 50;
      Error_Ratio       : Real := 1.0E-4;
      --  Stop when a step moves less than this (m and rad).
      Association       : Real := 0.3;
      --  Pairs farther apart than this are ignored, m.
      Filter            : Real := 0.85;
      --  Fraction of the pairs (the best) kept each iteration.
      Search_Window     : Positive := 12;
      --  Reference beams searched either side of the expected bearing.
      Subsample         : Positive := 2;
      --  Use one beam of the new scan out of this many.
      Min_Pairs         : Positive := 30;
      Keyframe_Distance : Real := 0.4;
      Keyframe_Angle    : Real := 0.3;
   end record;

   type Scan_Points is private;
   --  The valid beams of a scan as points, with their beam numbers.

   function To_Points (Scan : Laser_Scan) return Scan_Points;

   type Match_Result is record
      Relative   : Pose;
      --  Pose of the new scan's frame in the reference scan's frame.
      Converged  : Boolean := False;
      Iterations : Natural := 0;
      Pairs      : Natural := 0;
      Error      : Real := 0.0;
      --  Mean point-to-line distance of the kept pairs, m.
   end record;

   function Match
     (Config    : Matcher_Config;
      Reference : Scan_Points;
      Current   : Scan_Points;
      Guess     : Pose) return Match_Result;

   type Corrector is tagged private;

   procedure Update
     (This     : in out Corrector;
      Config   : Matcher_Config;
      Odometry : Pose;
      Scan     : Laser_Scan);
   --  Feeds one odometry pose and the scan taken there.

   function Corrected (This : Corrector) return Pose;
   --  The corrected pose (in the odometry frame's origin: the first
   --  odometry pose is taken as exact).

   function Last_Result (This : Corrector) return Match_Result;

private

   type Beam_Point is record
      Beam : Positive := 1;
      P    : Point;
   end record;

   package Beam_Point_Vectors is new Ada.Containers.Vectors (Positive, Beam_Point);
   package Index_Vectors is new Ada.Containers.Vectors (Positive, Natural);

   type Scan_Points is record
      Points    : Beam_Point_Vectors.Vector;
      By_Beam   : Index_Vectors.Vector;
      --  For each beam number, its point's index (0: none).
      Angle_Min : Real := 0.0;
      Increment : Real := 0.0;
      Beams     : Natural := 0;
   end record
     with Type_Invariant => Is_Indexed (Scan_Points);

   function Is_Indexed (S : Scan_Points) return Boolean is
     (Natural (S.By_Beam.Length) = S.Beams
      and then (for all B in 1 .. S.Beams =>
                  S.By_Beam (B) = 0
                  or else (S.By_Beam (B) <= S.Points.Last_Index
                           and then S.Points (S.By_Beam (B)).Beam = B)));
   --  By_Beam has one entry per beam, and each entry other than 0 is the
   --  index of that beam's point (Match finds a beam's neighbours by it).

   type Corrector is tagged record
      Started       : Boolean := False;
      Key           : Scan_Points;
      Key_Odometry  : Pose;
      Key_Corrected : Pose;
      Estimate      : Pose;
      Last          : Match_Result;
   end record;

end Sancta.Robot.Scan_Matchers;
