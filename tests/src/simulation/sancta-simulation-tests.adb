with AUnit.Assertions;   use AUnit.Assertions;
with Interfaces;
with Sancta.Geometry;    use Sancta.Geometry;
with Sancta.Robot.Grids;
with Sancta.Robot.Sensors;
with Sancta.Simulation.Simulators;
with Sancta.Simulation.Worlds;
with Suite_Support; use Suite_Support;

package body Sancta.Simulation.Tests is

   use Sancta.Robot;
   use Simulators;

   function Near (A, B : Real; Tolerance : Real := 1.0E-6) return Boolean is
     (abs (A - B) <= Tolerance);

   function Image (X : Real) return String is (Real'Image (X));

   Sqrt_2 : constant := 1.41421_35623_73095_04880;

   function Box_World return Worlds.World is
      --  A 10 m x 10 m room (walls 0.1 thick along the border) with a wall
      --  0.2 thick centred on x = 5 from y = 2 to y = 8: its face is x = 4.9.
      G : Grids.Grid (199, 199);
   begin
      G.Origin := (0.0, 0.0);
      G.Resolution := 0.05;
      Grids.Draw (G, ((0.0, 0.0), (10.0, 0.0), 0.1));
      Grids.Draw (G, ((0.0, 10.0), (10.0, 10.0), 0.1));
      Grids.Draw (G, ((0.0, 0.0), (0.0, 10.0), 0.1));
      Grids.Draw (G, ((10.0, 0.0), (10.0, 10.0), 0.1));
      Grids.Draw (G, ((5.0, 2.0), (5.0, 8.0), 0.2));
      return Worlds.Create (G);
   end Box_World;

   Exact : constant Robot_Config :=
     (Max_Linear        => 2.0,
      Max_Linear_Accel  => 1.0E6,
      Max_Angular_Accel => 1.0E6,
      Max_Angular       => 4.0,
      Laser             => (Noise_Std_Dev => 0.0, others => <>),
      others            => <>);
   --  Reaches its commanded speed in one tick; noiseless laser.

   Front : constant := 181;
   --  Beam at angle 0 of a 360-beam full-circle laser.

   ---------------------------------------------------------------------

   procedure Ray_Casting (Unused : in out Fixture) is
      W : constant Worlds.World := Box_World;
   begin
      Assert (Near (Worlds.Cast (W, (1.0, 5.0), 0.0, 8.0), 3.9),
              "facing the wall at 3.9:" & Image (Worlds.Cast (W, (1.0, 5.0), 0.0, 8.0)));
      Assert (Near (Worlds.Cast (W, (1.0, 4.0), Pi / 4.0, 8.0), 3.9 * Sqrt_2),
              "45 degrees:" & Image (Worlds.Cast (W, (1.0, 4.0), Pi / 4.0, 8.0)));
      Assert (Near (Worlds.Cast (W, (1.0, 5.0), Pi / 4.0, 8.0), 4.95 * Sqrt_2),
              "45 degrees above the wall's end");
      Assert (Near (Worlds.Cast (W, (1.0, 5.0), 0.0, 2.0), 2.0), "max range");
      Assert (Near (Worlds.Cast (W, (1.0, 5.0), Pi, 8.0), 0.95),
              "back wall (face at 0.05):" & Image (Worlds.Cast (W, (1.0, 5.0), Pi, 8.0)));
      Assert (Near (Worlds.Cast (W, (1.0, 5.0), Pi / 2.0, 8.0), 4.95), "up");
      Assert (Worlds.Cast (W, (5.0, 5.0), 0.3, 8.0) = 0.0, "from inside a wall");
      Assert (Worlds.Disk_Collides (W, (4.75, 5.0), 0.2), "disk touching the wall");
      Assert (not Worlds.Disk_Collides (W, (4.65, 5.0), 0.2), "disk clear of the wall");
   end Ray_Casting;

   procedure Laser_Scan_Sees_Walls_And_Robots (Unused : in out Fixture) is
      S      : Simulator;
      A, B   : Robot_Id;
   begin
      S.Initialize (Box_World, Seed => 1);
      S.Add_Robot (Exact, (1.0, 5.0, 0.0), A);
      S.Step (0.01);
      declare
         Scan : constant Sensors.Laser_Scan := S.Latest_Scan (A);
      begin
         Assert (S.Scan_Count (A) = 1, "one scan after the first tick");
         Assert (Near (Sensors.Beam_Angle (Scan, Front), 0.0), "beam 181 faces forward");
         Assert (Near (Scan.Ranges (Front), 3.9), "wall ahead:" & Image (Scan.Ranges (Front)));
         Assert (Near (Scan.Ranges (Front + 90), 4.95), "wall on the left");
      end;
      S.Add_Robot (Exact, (3.0, 5.0, Pi), B);
      S.Step (0.1);
      Assert (Near (S.Latest_Scan (A).Ranges (Front), 1.8),
              "robot ahead at 2 m (radius 0.2):" & Image (S.Latest_Scan (A).Ranges (Front)));
      Assert (Near (S.Latest_Scan (B).Ranges (Front), 1.8), "B sees A ahead");
      Assert (Near (S.Latest_Scan (B).Ranges (1), 1.9), "B sees the wall behind");
      S.Kill (B);
      S.Step (0.1);
      Assert (Near (S.Latest_Scan (A).Ranges (Front), 3.9), "a dead robot is invisible");
      S.Revive (B);
      S.Step (0.1);
      Assert (Near (S.Latest_Scan (A).Ranges (Front), 1.8), "a revived robot is seen");
   end Laser_Scan_Sees_Walls_And_Robots;

   procedure Partial_Field_Of_View (Unused : in out Fixture) is
      S       : Simulator;
      A, B, C : Robot_Id;
      Config  : Robot_Config := Exact;
   begin
      Config.Laser.Beams := 181;
      Config.Laser.Field_Of_View := Pi;
      S.Initialize (Box_World);
      S.Add_Robot (Config, (2.0, 5.0, 0.0), A);
      S.Add_Robot (Exact, (4.0, 5.0, 0.0), B);
      S.Add_Robot (Exact, (2.0, 3.0, 0.0), C);
      S.Step (0.01);
      declare
         Scan : constant Sensors.Laser_Scan := S.Latest_Scan (A);
      begin
         Assert (Near (Scan.Angle_Min, -Pi / 2.0) and then Near (Scan.Angle_Max, Pi / 2.0),
                 "180 degrees centred ahead");
         Assert (Near (Sensors.Beam_Angle (Scan, 91), 0.0), "beam 91 ahead");
         Assert (Near (Scan.Ranges (91), 1.8), "robot ahead:" & Image (Scan.Ranges (91)));
         Assert (Near (Scan.Ranges (1), 1.8), "robot on the right, first beam:"
                 & Image (Scan.Ranges (1)));
         Assert (Near (Scan.Ranges (181), 4.95), "wall on the left, last beam");
      end;
   end Partial_Field_Of_View;

   procedure Kinematics (Unused : in out Fixture) is
      S : Simulator;
      R : Robot_Id;
      P : Pose;
   begin
      S.Initialize (Box_World);
      S.Add_Robot (Exact, (1.0, 1.0, 0.0), R);
      S.Set_Command (R, (1.0, 0.0));
      S.Step (1.0);
      P := S.Ground_Truth (R).Pose;
      Assert (Near (P.X, 2.0) and then Near (P.Y, 1.0), "straight 1 m:" & Image (P.X));
      --  Half a circle of radius 1 at pi/2 rad/s takes 2 s.
      S.Set_Command (R, (Pi / 2.0, Pi / 2.0));
      S.Step (2.0);
      P := S.Ground_Truth (R).Pose;
      Assert (Near (P.X, 2.0, 1.0E-6) and then Near (P.Y, 3.0, 1.0E-6),
              "half circle:" & Image (P.X) & Image (P.Y));
      Assert (Near (abs P.Yaw, Pi, 1.0E-6), "heading reversed");
      --  Quarter circle more: centre (2, 2), radius 1, now at (1, 2).
      S.Step (1.0);
      P := S.Ground_Truth (R).Pose;
      Assert (Near (P.X, 1.0, 1.0E-6) and then Near (P.Y, 2.0, 1.0E-6),
              "three quarters:" & Image (P.X) & Image (P.Y));
      Assert (Near (P.Yaw, -Pi / 2.0, 1.0E-6), "heading south");
      Assert (S.Clock = 4.0, "clock" & Image (S.Clock));
   end Kinematics;

   procedure Acceleration_And_Speed_Limits (Unused : in out Fixture) is
      S : Simulator;
      R : Robot_Id;
      C : constant Robot_Config :=
        (Max_Linear => 0.5, Max_Linear_Accel => 2.0, others => <>);
   begin
      S.Initialize (Box_World);
      S.Add_Robot (C, (1.0, 1.0, 0.0), R);
      S.Set_Command (R, (3.0, 0.0));
      S.Step (0.1);
      --  Speeds 0.02, 0.04 .. 0.2 over ten ticks of 0.01 s.
      Assert (Near (S.Ground_Truth (R).Pose.X, 1.011), "accelerating:"
              & Image (S.Ground_Truth (R).Pose.X));
      S.Step (1.0);
      S.Step (1.0);
      declare
         X0 : constant Real := S.Ground_Truth (R).Pose.X;
      begin
         S.Step (1.0);
         Assert (Near (S.Ground_Truth (R).Pose.X - X0, 0.5), "capped at 0.5 m/s");
      end;
   end Acceleration_And_Speed_Limits;

   procedure Wall_Collision (Unused : in out Fixture) is
      S      : Simulator;
      R      : Robot_Id;
      Events : Event_Vectors.Vector;
      Hits   : Natural := 0;
   begin
      S.Initialize (Box_World);
      S.Add_Robot (Exact, (3.0, 5.0, 0.0), R);
      S.Set_Command (R, (1.0, 0.0));
      S.Step (4.0);
      Assert (S.Is_Colliding (R), "pushing against the wall");
      Assert (S.Collision_Count (R) = 1, "one contact:" & S.Collision_Count (R)'Image);
      Assert (S.Ground_Truth (R).Pose.X <= 4.7
              and then S.Ground_Truth (R).Pose.X > 4.68,
              "stopped at the wall:" & Image (S.Ground_Truth (R).Pose.X));
      S.Take_Events (Events);
      for E of Events loop
         if E.Kind = Simulators.Wall_Collision then
            Hits := Hits + 1;
            Assert (E.Robot = R, "event names the robot");
         end if;
      end loop;
      Assert (Hits = 1, "one wall collision event");
      --  Backing off clears the contact.
      S.Set_Command (R, (-0.5, 0.0));
      S.Step (0.5);
      Assert (not S.Is_Colliding (R), "backed off");
   end Wall_Collision;

   procedure Robot_Collision (Unused : in out Fixture) is
      S      : Simulator;
      A, B   : Robot_Id;
      Events : Event_Vectors.Vector;
      Found  : Boolean := False;
   begin
      S.Initialize (Box_World);
      S.Add_Robot (Exact, (1.0, 3.0, 0.0), A);
      S.Add_Robot (Exact, (3.0, 3.0, Pi), B);
      S.Set_Command (A, (0.5, 0.0));
      S.Set_Command (B, (0.5, 0.0));
      S.Step (3.0);
      Assert (Distance (Position (S.Ground_Truth (A).Pose),
                        Position (S.Ground_Truth (B).Pose)) >= 0.4 - 1.0E-9,
              "robots never overlap");
      Assert (S.Is_Colliding (A) and then S.Is_Colliding (B), "both blocked");
      S.Take_Events (Events);
      for E of Events loop
         if E.Kind = Simulators.Robot_Collision and then E.Robot = A then
            Found := E.Other = B;
         end if;
      end loop;
      Assert (Found, "A's collision with B reported");
   end Robot_Collision;

   procedure Odometry_Drift (Unused : in out Fixture) is
      S : Simulator;
      R : Robot_Id;
      C : Robot_Config := Exact;
   begin
      C.Odometry.Linear_Scale_Error := 0.1;
      C.Odometry.Angular_Bias := 0.05;
      S.Initialize (Box_World);
      S.Add_Robot (C, (1.0, 1.0, 0.0), R);
      S.Set_Command (R, (1.0, 0.0));
      S.Step (2.0);
      Assert (S.Odometry_Count (R) = 41,
              "20 Hz (first at the first tick):" & S.Odometry_Count (R)'Image);
      declare
         O : constant Sensors.Odometry := S.Latest_Odometry (R);
      begin
         Assert (Near (S.Ground_Truth (R).Pose.X, 3.0), "truth straight");
         Assert (Near (O.Pose.Yaw, 0.1, 1.0E-6), "heading drift 0.05 rad/s:" & Image (O.Pose.Yaw));
         Assert (Distance ((1.0, 1.0), Position (O.Pose)) > 2.19, "distance scaled by 1.1");
      end;
   end Odometry_Drift;

   procedure Determinism (Unused : in out Fixture) is
      C : Robot_Config;

      function Run (Seed : Interfaces.Unsigned_64) return Real is
         S   : Simulator;
         A   : Robot_Id;
         Sum : Real := 0.0;
      begin
         S.Initialize (Box_World, Seed);
         for K in 1 .. 3 loop
            S.Add_Robot (C, (1.0, Real (K) * 2.0, 0.0), A);
            S.Set_Command (A, (0.3, 0.1 * Real (K)));
         end loop;
         S.Step (3.0);
         for Id in Robot_Id range 1 .. 3 loop
            Sum := Sum + S.Latest_Odometry (Id).Pose.X + S.Latest_GPS (Id).Position.Y;
            for R of S.Latest_Scan (Id).Ranges loop
               Sum := Sum + R;
            end loop;
         end loop;
         return Sum;
      end Run;
   begin
      C.Odometry.Linear_Noise := 0.05;
      C.Odometry.Angular_Noise := 0.05;
      C.GPS.Enabled := True;
      Assert (Run (7) = Run (7), "same seed, same run");
      Assert (Run (7) /= Run (8), "another seed, another run");
   end Determinism;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;

      procedure Add (Name : String; Test : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("simulation: " & Name, Test));
      end Add;
   begin
      Add ("ray casting against analytic distances", Ray_Casting'Access);
      Add ("laser sees walls, robots; kill and revive",
           Laser_Scan_Sees_Walls_And_Robots'Access);
      Add ("laser with a partial field of view", Partial_Field_Of_View'Access);
      Add ("kinematics: straight line and known arcs", Kinematics'Access);
      Add ("acceleration and speed limits", Acceleration_And_Speed_Limits'Access);
      Add ("wall collision stops and is reported once", Wall_Collision'Access);
      Add ("robot collision stops both and is reported", Robot_Collision'Access);
      Add ("odometry drift as configured", Odometry_Drift'Access);
      Add ("determinism for a seed", Determinism'Access);
      return Result;
   end Suite;

end Sancta.Simulation.Tests;
