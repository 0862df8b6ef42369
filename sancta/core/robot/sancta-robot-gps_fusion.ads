--  Fusion of wheel odometry with absolute GPS-like fixes: a Kalman filter
--  on the position. Odometry increments (taken in the robot frame, turned
--  into the world frame with the estimated heading) predict, and grow the
--  variance in proportion to the distance travelled; each fix corrects
--  with gain P / (P + sigma^2). A single fix does not observe the heading,
--  but a track does: every Track_Length metres the direction of the fixes'
--  displacement is compared with the direction of the odometry's
--  displacement (turned into the world with the estimated heading), and a
--  share (Heading_Gain) of the difference corrects the heading.
--
--     F.Initialize (Start, Variance => 0.01, Config => (Odometry_Noise => 0.05, others => <>));
--     F.Predict (Odometry.Pose);   --  at every odometry reading
--     F.Correct (Fix);             --  at every GPS reading
--     Estimate := F.Estimate;
with Sancta.Geometry;       use Sancta.Geometry;
with Sancta.Robot.Sensors;  use Sancta.Robot.Sensors;

package Sancta.Robot.GPS_Fusion
  with Pure
is

   type Filter is tagged private;

   type Fusion_Config is record
      Odometry_Noise : Real := 0.01;
      --  Variance added per metre travelled, m^2/m.
      Track_Length   : Real := 3.0;
      --  Metres of fixes whose direction corrects the heading.
      Heading_Gain   : Real := 0.5;
      --  The share of the heading difference corrected.
   end record;
   --  The filter's tuning.

   procedure Initialize
     (This     : in out Filter;
      Start    : Pose;
      Variance : Real := 0.0;
      Config   : Fusion_Config := (others => <>))
     with Pre => Variance >= 0.0 and then Config.Odometry_Noise >= 0.0
                 and then Config.Heading_Gain in 0.0 .. 1.0;

   procedure Predict (This : in out Filter; Odometry : Pose);
   --  An odometry reading (its increment since the previous one is used).

   procedure Correct (This : in out Filter; Fix : GPS_Fix);

   function Estimate (This : Filter) return Pose;

   function Variance (This : Filter) return Real;

private

   type Filter is tagged record
      Estimate  : Pose;
      Variance  : Real := 0.0;
      Noise     : Real := 0.01;
      Last_Odom : Pose;
      Have_Odom : Boolean := False;
      Track     : Real := 3.0;
      Gain      : Real := 0.5;
      Anchored  : Boolean := False;
      Anchor    : Point;
      --  The fix where the current track starts.
      Travel    : Point;
      --  Odometry displacement (world frame) since the anchor.
   end record
     with Type_Invariant =>
       Filter.Variance >= 0.0 and then Filter.Noise >= 0.0
       and then Filter.Gain in 0.0 .. 1.0;
   --  A variance is never negative: prediction adds Noise (>= 0) per metre,
   --  correction scales it by 1 - K with the gain K = P / (P + sigma^2) in
   --  0 .. 1; Heading_Gain is a share.

end Sancta.Robot.GPS_Fusion;
