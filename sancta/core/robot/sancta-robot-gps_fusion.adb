with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Robot.GPS_Fusion is

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   procedure Initialize
     (This     : in out Filter;
      Start    : Pose;
      Variance : Real := 0.0;
      Config   : Fusion_Config := (others => <>)) is
   begin
      This := (Estimate  => Start,
               Variance  => Variance,
               Noise     => Config.Odometry_Noise,
               Last_Odom => Start,
               Have_Odom => False,
               Track     => Config.Track_Length,
               Gain      => Config.Heading_Gain,
               Anchored  => False,
               Anchor    => (0.0, 0.0),
               Travel    => (0.0, 0.0));
   end Initialize;

   procedure Predict (This : in out Filter; Odometry : Pose) is
   begin
      if This.Have_Odom then
         declare
            Step : constant Pose := Relative (This.Last_Odom, Odometry);
            Next : constant Pose := Compose (This.Estimate, Step);
         begin
            This.Travel := This.Travel + (Position (Next) - Position (This.Estimate));
            This.Estimate := Next;
            This.Variance := This.Variance + This.Noise * Norm ((Step.X, Step.Y));
         end;
      end if;
      This.Last_Odom := Odometry;
      This.Have_Odom := True;
   end Predict;

   procedure Correct (This : in out Filter; Fix : GPS_Fix) is
      R : constant Real := Fix.Std_Dev * Fix.Std_Dev;
      K : constant Real :=
        (if This.Variance + R > 0.0 then This.Variance / (This.Variance + R) else 1.0);
   begin
      if not This.Anchored then
         This.Anchored := True;
         This.Anchor := Fix.Position;
         This.Travel := (0.0, 0.0);
      elsif Norm (This.Travel) >= This.Track then
         declare
            Seen : constant Point := Fix.Position - This.Anchor;
            Err  : constant Real := Normalize_Angle
              (Math.Arctan (Seen.Y, Seen.X) - Math.Arctan (This.Travel.Y, This.Travel.X));
         begin
            if Norm (Seen) >= This.Track / 2.0 and then abs Err < Pi / 3.0 then
               This.Estimate.Yaw := Normalize_Angle (This.Estimate.Yaw + This.Gain * Err);
            end if;
            This.Anchor := Fix.Position;
            This.Travel := (0.0, 0.0);
         end;
      end if;
      This.Estimate.X := This.Estimate.X + K * (Fix.Position.X - This.Estimate.X);
      This.Estimate.Y := This.Estimate.Y + K * (Fix.Position.Y - This.Estimate.Y);
      This.Variance := (1.0 - K) * This.Variance;
   end Correct;

   function Estimate (This : Filter) return Pose is (This.Estimate);

   function Variance (This : Filter) return Real is (This.Variance);

end Sancta.Robot.GPS_Fusion;
