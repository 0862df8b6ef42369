with Ada.Containers.Generic_Array_Sort;
with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Robot.Scan_Matchers is

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   function To_Points (Scan : Laser_Scan) return Scan_Points is
      Result : Scan_Points;
   begin
      Result.Angle_Min := Scan.Angle_Min;
      Result.Increment := Scan.Angle_Increment;
      Result.Beams := Scan.Beams;
      for B in 1 .. Scan.Beams loop
         if Is_Valid (Scan, B) then
            Result.Points.Append (Beam_Point'(B, Sensors.Beam_Point (Scan, B)));
            Result.By_Beam.Append (Result.Points.Last_Index);
         else
            Result.By_Beam.Append (0);
         end if;
      end loop;
      return Result;
   end To_Points;

   type Real_Array is array (Positive range <>) of Real;
   procedure Sort is new Ada.Containers.Generic_Array_Sort (Positive, Real, Real_Array);

   -----------
   -- Match --
   -----------

   function Match
     (Config    : Matcher_Config;
      Reference : Scan_Points;
      Current   : Scan_Points;
      Guess     : Pose) return Match_Result
   is
      T      : Pose := Guess;
      Result : Match_Result;
      N      : constant Natural := Natural (Current.Points.Length);

      type Pair is record
         Used   : Boolean := False;
         Normal : Point;
         Q      : Point;
         --  The reference point on the line.
         P      : Point;
         --  The current point, in its own frame.
         Err    : Real := 0.0;
      end record;
      type Pair_Array is array (Positive range <>) of Pair;
      Pairs : Pair_Array (1 .. N);

      --  Plain copies of the containers: the loops below index them a lot.
      Ref_Count : constant Natural := Natural (Reference.Points.Length);
      Ref_Point : array (1 .. Ref_Count) of Point;
      Ref_Beam  : array (1 .. Ref_Count) of Positive;
      Beam_Ref  : array (1 .. Reference.Beams) of Natural;
      Cur_Point : array (1 .. N) of Point;

      function Ref (Beam : Integer) return Natural is
        (if Reference.Beams = 0 then 0
         else Beam_Ref (((Beam - 1) mod Reference.Beams) + 1));
      --  Wraps around: scans are usually full circles.

      Full : constant Boolean :=
        abs (Real (Reference.Beams) * Reference.Increment - 2.0 * Pi) < 1.0E-6;
   begin
      if Reference.Points.Is_Empty or else N = 0 or else Reference.Increment <= 0.0 then
         Result.Relative := Guess;
         return Result;
      end if;
      for K in 1 .. Ref_Count loop
         Ref_Point (K) := Reference.Points (K).P;
         Ref_Beam (K) := Reference.Points (K).Beam;
      end loop;
      for B in 1 .. Reference.Beams loop
         Beam_Ref (B) := Reference.By_Beam (B);
      end loop;
      for K in 1 .. N loop
         Cur_Point (K) := Current.Points (K).P;
      end loop;
      for Iteration in 1 .. Config.Max_Iterations loop
         Result.Iterations := Iteration;
         declare
            C     : constant Real := Math.Cos (T.Yaw);
            S     : constant Real := Math.Sin (T.Yaw);
            Count : Natural := 0;
         begin
            for K in 1 .. N loop
               Pairs (K).Used := False;
               if (K - 1) mod Config.Subsample = 0 then
                  declare
                     P       : constant Point := Cur_Point (K);
                     Q       : constant Point :=
                       (T.X + C * P.X - S * P.Y, T.Y + S * P.X + C * P.Y);
                     Bearing : constant Real := Math.Arctan (Q.Y, Q.X);
                     Center  : constant Integer := 1 + Integer
                       (Real'Rounding (Normalize_Angle (Bearing - Reference.Angle_Min)
                                       / Reference.Increment));
                     Best    : Natural := 0;
                     Best_D  : Real := Config.Association;
                  begin
                     for B in Center - Config.Search_Window .. Center + Config.Search_Window loop
                        if Full or else B in 1 .. Reference.Beams then
                           declare
                              R : constant Natural := Ref (B);
                           begin
                              if R /= 0
                                and then Distance (Ref_Point (R), Q) < Best_D
                              then
                                 Best := R;
                                 Best_D := Distance (Ref_Point (R), Q);
                              end if;
                           end;
                        end if;
                     end loop;
                     if Best /= 0 then
                        --  The line through Best and its closer neighbour.
                        declare
                           A     : constant Point := Ref_Point (Best);
                           Beam  : constant Integer := Ref_Beam (Best);
                           Other : Natural := 0;
                           Dist  : Real := 0.3;
                        begin
                           for D in -1 .. 1 loop
                              if D /= 0 and then (Full or else Beam + D in 1 .. Reference.Beams)
                              then
                                 declare
                                    R : constant Natural := Ref (Beam + D);
                                 begin
                                    if R /= 0 and then R /= Best
                                      and then Distance (Ref_Point (R), A) < Dist
                                    then
                                       Other := R;
                                       Dist := Distance (Ref_Point (R), A);
                                    end if;
                                 end;
                              end if;
                           end loop;
                           if Other /= 0 and then Dist > 1.0E-6 then
                              declare
                                 B2 : constant Point := Ref_Point (Other);
                                 Nx : constant Real := -(B2.Y - A.Y) / Dist;
                                 Ny : constant Real := (B2.X - A.X) / Dist;
                              begin
                                 Count := Count + 1;
                                 Pairs (K) :=
                                   (Used   => True,
                                    Normal => (Nx, Ny),
                                    Q      => A,
                                    P      => P,
                                    Err    => Nx * (Q.X - A.X) + Ny * (Q.Y - A.Y));
                              end;
                           end if;
                        end;
                     end if;
                  end;
               end if;
            end loop;
            if Count < Config.Min_Pairs then
               Result.Relative := Guess;
               Result.Converged := False;
               Result.Pairs := Count;
               return Result;
            end if;
            --  Keep the best Filter fraction.
            declare
               Errors : Real_Array (1 .. Count);
               M      : Natural := 0;
               Cut    : Real;
            begin
               for K in 1 .. N loop
                  if Pairs (K).Used then
                     M := M + 1;
                     Errors (M) := abs Pairs (K).Err;
                  end if;
               end loop;
               Sort (Errors);
               Cut := Errors (Positive'Max (1, Natural (Real (Count) * Config.Filter)));
               --  Gauss-Newton on (x, y, yaw): J = [nx, ny, n . dq/dyaw].
               declare
                  H    : array (1 .. 3, 1 .. 3) of Real := [others => [others => 0.0]];
                  G    : array (1 .. 3) of Real := [others => 0.0];
                  Kept : Natural := 0;
                  Sum  : Real := 0.0;
               begin
                  for K in 1 .. N loop
                     if Pairs (K).Used and then abs Pairs (K).Err <= Cut then
                        declare
                           P  : constant Point := Pairs (K).P;
                           Nx : constant Real := Pairs (K).Normal.X;
                           Ny : constant Real := Pairs (K).Normal.Y;
                           J3 : constant Real :=
                             Nx * (-S * P.X - C * P.Y) + Ny * (C * P.X - S * P.Y);
                           J  : constant array (1 .. 3) of Real := [Nx, Ny, J3];
                           E  : constant Real := Pairs (K).Err;
                        begin
                           Kept := Kept + 1;
                           Sum := Sum + abs E;
                           for R in 1 .. 3 loop
                              G (R) := G (R) + J (R) * E;
                              for Q in 1 .. 3 loop
                                 H (R, Q) := H (R, Q) + J (R) * J (Q);
                              end loop;
                           end loop;
                        end;
                     end if;
                  end loop;
                  Result.Pairs := Kept;
                  Result.Error := Sum / Real (Natural'Max (1, Kept));
                  --  Solve H d = -G by Cramer's rule (with a little damping).
                  for R in 1 .. 3 loop
                     H (R, R) := H (R, R) + 1.0E-6;
                  end loop;
                  declare
                     function Det (A : Real_Array) return Real is
                       (A (1) * (A (5) * A (9) - A (6) * A (8))
                        - A (2) * (A (4) * A (9) - A (6) * A (7))
                        + A (3) * (A (4) * A (8) - A (5) * A (7)));
                     M0 : constant Real_Array (1 .. 9) :=
                       [H (1, 1), H (1, 2), H (1, 3), H (2, 1), H (2, 2), H (2, 3),
                        H (3, 1), H (3, 2), H (3, 3)];
                     D  : constant Real := Det (M0);
                     X  : array (1 .. 3) of Real;
                  begin
                     if abs D < 1.0E-12 then
                        Result.Relative := T;
                        return Result;
                     end if;
                     for Col in 1 .. 3 loop
                        declare
                           M1 : Real_Array := M0;
                        begin
                           for R in 1 .. 3 loop
                              M1 ((R - 1) * 3 + Col) := -G (R);
                           end loop;
                           X (Col) := Det (M1) / D;
                        end;
                     end loop;
                     T := (T.X + X (1), T.Y + X (2), Normalize_Angle (T.Yaw + X (3)));
                     if abs X (1) + abs X (2) + abs X (3) < Config.Error_Ratio then
                        Result.Converged := True;
                        exit;
                     end if;
                  end;
               end;
            end;
         end;
      end loop;
      Result.Relative := T;
      if not Result.Converged then
         --  Out of iterations but still moving only a little: accept.
         Result.Converged := Result.Error < Config.Association / 3.0;
      end if;
      return Result;
   end Match;

   ---------------
   -- Corrector --
   ---------------

   procedure Update
     (This     : in out Corrector;
      Config   : Matcher_Config;
      Odometry : Pose;
      Scan     : Laser_Scan)
   is
      Points : constant Scan_Points := To_Points (Scan);
   begin
      if not This.Started then
         This.Started := True;
         This.Key := Points;
         This.Key_Odometry := Odometry;
         This.Key_Corrected := Odometry;
         This.Estimate := Odometry;
         return;
      end if;
      declare
         Guess : constant Pose := Relative (This.Key_Odometry, Odometry);
         R     : constant Match_Result := Match (Config, This.Key, Points, Guess);
         Jump  : constant Real := Distance ((R.Relative.X, R.Relative.Y), (Guess.X, Guess.Y));
         Delta_Pose : constant Pose :=
           (if R.Converged and then Jump < 0.5
              and then abs Normalize_Angle (R.Relative.Yaw - Guess.Yaw) < 0.3
            then R.Relative else Guess);
      begin
         This.Last := R;
         This.Estimate := Compose (This.Key_Corrected, Delta_Pose);
         if Distance ((0.0, 0.0), (Delta_Pose.X, Delta_Pose.Y)) > Config.Keyframe_Distance
           or else abs Delta_Pose.Yaw > Config.Keyframe_Angle
         then
            This.Key := Points;
            This.Key_Odometry := Odometry;
            This.Key_Corrected := This.Estimate;
         end if;
      end;
   end Update;

   function Corrected (This : Corrector) return Pose is (This.Estimate);

   function Last_Result (This : Corrector) return Match_Result is (This.Last);

end Sancta.Robot.Scan_Matchers;
