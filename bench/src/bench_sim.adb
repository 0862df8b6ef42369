--  Simulator benchmark: real-time factor of the simulator alone (physics
--  at 100 Hz, 360-beam lasers at 10 Hz, odometry at 20 Hz) for teams of
--  1, 10, 50 and 100 robots wandering in the bundled office world, on one
--  core; then scan matching (point-to-line ICP) on a drive with drifting
--  odometry: time per scan and pose error against ground truth.
--
--     bench_sim [WORLD [SECONDS_SCALE [team|icp|all]]]   (bench/bench-sim.sh)
--  Prints a table; writes out/bench/sim.csv and out/bench/sim-icp.csv.
with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Execution_Time;
with Ada.Real_Time;             use Ada.Real_Time;
with Ada.Text_IO;               use Ada.Text_IO;
with Bench_Arguments;
with Sancta.Geometry;           use Sancta.Geometry;
with Sancta.Robot.Goal_Sequencers;
with Sancta.Robot.Grids;
with Sancta.Robot.Navigators;
with Sancta.Robot.Path_Costs;
with Sancta.Robot.Scan_Matchers;
with Sancta.Robot.Sensors;
with Sancta.Simulation.Generators;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Simulators;
with Sancta.Simulation.Worlds;

procedure Bench_Sim is
   use Sancta;
   use Sancta.Simulation;
   use Sancta.Simulation.Simulators;

   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_sim [WORLD [SECONDS_SCALE [team|icp|all]]]" & ASCII.LF
      & "simulator benchmark (bench/bench-sim.sh): real-time factor with 1, 10, 50, 100"
      & ASCII.LF & "robots, then scan matching; writes out/bench/sim.csv, out/bench/sim-icp.csv"
      & ASCII.LF
      & "  WORLD           a map-server YAML file or a .walls world"
      & " (default share/worlds/office.yaml)" & ASCII.LF
      & "  SECONDS_SCALE   multiplies the simulated durations (default 1; 0.2 for a quick look)"
      & ASCII.LF
      & "  team|icp|all    which part to run (default all)",
      Min => 0, Max => 3);
   pragma Unreferenced (Read);
   World_Name : constant String :=
     (if Ada.Command_Line.Argument_Count >= 1 then Ada.Command_Line.Argument (1)
      else "share/worlds/office.yaml");
   Scale : constant Real := Real (Bench_Arguments.Number (2, "SECONDS_SCALE", Default => 1.0));
   --  Multiplies the simulated durations (0.2 for a quick look).
   Part : constant String :=
     (if Ada.Command_Line.Argument_Count >= 3
      then Bench_Arguments.One_Of (3, "PART", "team|icp|all") else "all");

   function Load (Name : String) return Worlds.World is
   begin
      return Map_Files.Load_World (Name);
   exception
      when E : Format_Error =>
         Bench_Arguments.Fail (Ada.Exceptions.Exception_Message (E));
   end Load;

   World : constant Worlds.World := Load (World_Name);
   Map   : Robot.Path_Costs.Planner;

   function Fixed (X : Real; Decimals : Natural := 2) return String is
      M  : constant Long_Long_Integer := 10 ** Decimals;
      V  : constant Long_Long_Integer :=
        Long_Long_Integer (Real'Rounding (abs X * Real (M)));
      I  : constant String := Long_Long_Integer'Image (V / M);
      F  : constant String := Long_Long_Integer'Image (V mod M);
      Fr : constant String := [1 .. Decimals - (F'Length - 1) => '0'] & F (F'First + 1 .. F'Last);
   begin
      return (if X < 0.0 then "-" else "") & I (I'First + 1 .. I'Last)
        & (if Decimals = 0 then "" else "." & Fr);
   end Fixed;

   function Pad (S : String; Width : Positive) return String is
     ((if S'Length < Width then [1 .. Width - S'Length => ' '] else "") & S);

   CSV : File_Type;

   procedure Team (N : Positive; Seconds : Real) is
      Sim    : Simulator;
      Random : Generators.Generator := Generators.Create (77);
      Id     : Robot_Id;
      Starts : array (1 .. N) of Point;
      F      : constant Sancta.Robot.Grids.Frame := Worlds.Frame_Of (World);
      Start_Time, Stop_Time : Time;
      CPU_Start, CPU_Stop   : Ada.Execution_Time.CPU_Time;
      Rays   : Long_Long_Integer := 0;
   begin
      Sim.Initialize (World, Seed => 1, Physics_Period => 0.01);
      for R in 1 .. N loop
         loop
            declare
               --  One draw per declaration (an aggregate's order is the compiler's)
               U : constant Real := Generators.Uniform (Random);
               V : constant Real := Generators.Uniform (Random);
            begin
               Starts (R) := (F.Origin.X + U * Real (F.Width) * F.Resolution,
                              F.Origin.Y + V * Real (F.Height) * F.Resolution);
            end;
            exit when Map.Is_Free (Starts (R))
              and then Map.Cost (Starts (R), (10.0, 10.0)) /= Robot.Path_Costs.Unreachable
              and then (for all K in 1 .. R - 1 => Distance (Starts (K), Starts (R)) > 0.7);
         end loop;
         Sim.Add_Robot (Default_Robot,
                        (Starts (R).X, Starts (R).Y, 2.0 * Pi * Generators.Uniform (Random)),
                        Id);
      end loop;
      Start_Time := Clock;
      CPU_Start := Ada.Execution_Time.Clock;
      while Sim.Clock < Seconds loop
         --  Wander: forward unless something is close ahead, then turn.
         for R in 1 .. N loop
            declare
               Scan  : constant Robot.Sensors.Laser_Scan := Sim.Latest_Scan (Robot_Id (R));
               Ahead : Real := Scan.Range_Max;
            begin
               for B in 166 .. 196 loop
                  Ahead := Real'Min (Ahead, Scan.Ranges (B));
               end loop;
               Sim.Set_Command
                 (Robot_Id (R),
                  (if Ahead < 0.8 then (0.0, 1.2)
                   else (0.6, 0.4 * (Generators.Uniform (Random) - 0.5))));
            end;
         end loop;
         Sim.Step (0.1);
      end loop;
      Stop_Time := Clock;
      CPU_Stop := Ada.Execution_Time.Clock;
      for R in 1 .. N loop
         Rays := Rays + Long_Long_Integer (Sim.Scan_Count (Robot_Id (R))) * 360;
      end loop;
      declare
         use type Ada.Execution_Time.CPU_Time;
         Wall : constant Real := Real (To_Duration (Stop_Time - Start_Time));
         CPU  : constant Real := Real (To_Duration (CPU_Stop - CPU_Start));
         RTF  : constant Real := Sim.Clock / Wall;
      begin
         Put_Line (Pad (N'Image, 7) & Pad (Fixed (Sim.Clock, 1), 9) & Pad (Fixed (Wall, 3), 9)
                   & Pad (Fixed (CPU, 3), 9) & Pad (Fixed (RTF, 1), 9)
                   & Pad (Fixed (Sim.Clock / CPU, 1), 9)
                   & Pad (Fixed (Real (Rays) / CPU / 1.0E6, 2), 9));
         Put_Line (CSV, Fixed (Real (N), 0) & "," & Fixed (Sim.Clock, 1) & "," & Fixed (Wall, 4)
                   & "," & Fixed (CPU, 4) & "," & Fixed (RTF, 2) & ","
                   & Fixed (Sim.Clock / CPU, 2) & "," & Fixed (Real (Rays) / CPU / 1.0E6, 3));
      end;
   end Team;

   procedure Scan_Matching (Seconds : Real) is
      Sim    : Simulator;
      Id     : Robot_Id;
      Config : Robot_Config := Default_Robot;
      M      : constant Robot.Scan_Matchers.Matcher_Config := (others => <>);
      C      : Robot.Scan_Matchers.Corrector;
      Nav    : Robot.Navigators.Navigator;
      E      : Robot.Goal_Sequencers.Sequencer;
      Last   : Natural := 0;
      Samples, Converged : Natural := 0;
      Odom_Sum, ICP_Sum, Odom_Final, ICP_Final : Real := 0.0;
      Spent  : Time_Span := Time_Span_Zero;
      T0     : Time;
      function Pt (X, Y : Real) return Point is ((X, Y));
   begin
      Config.Odometry.Linear_Scale_Error := 0.03;
      Config.Odometry.Angular_Bias := 0.02;
      Config.Odometry.Linear_Noise := 0.02;
      Config.Odometry.Angular_Noise := 0.02;
      Sim.Initialize (World, Seed => 3);
      Sim.Add_Robot (Config, (2.5, 10.0, 0.0), Id);
      E.Assign ([Pt (17.0, 10.0), Pt (17.0, 4.0), Pt (25.0, 10.0), Pt (10.0, 14.5),
                 Pt (2.5, 10.0), Pt (9.0, 3.0), Pt (25.0, 12.0)], Tolerance => 0.3);
      Sim.Step (0.1);
      while Sim.Clock < Seconds and then not E.Is_Done loop
         declare
            Truth : constant Pose := Sim.Ground_Truth (Id).Pose;
         begin
            E.Update (Truth);
            exit when E.Is_Done;
            if Nav.Arrived or else Sim.Clock < 0.15 then
               Nav.Set_Goal (Map, Truth, E.Current_Goal);
            end if;
            Sim.Set_Command (Id, Nav.Command (Map, Truth, Sim.Latest_Scan (Id), Sim.Clock));
            if Sim.Scan_Count (Id) /= Last then
               Last := Sim.Scan_Count (Id);
               T0 := Clock;
               C.Update (M, Sim.Latest_Odometry (Id).Pose, Sim.Latest_Scan (Id));
               Spent := Spent + (Clock - T0);
               Samples := Samples + 1;
               if C.Last_Result.Converged then
                  Converged := Converged + 1;
               end if;
               Odom_Final := Distance (Position (Sim.Latest_Odometry (Id).Pose), Position (Truth));
               ICP_Final := Distance (Position (C.Corrected), Position (Truth));
               Odom_Sum := Odom_Sum + Odom_Final;
               ICP_Sum := ICP_Sum + ICP_Final;
            end if;
            Sim.Step (0.1);
         end;
      end loop;
      declare
         Per_Scan : constant Real := Real (To_Duration (Spent)) / Real (Samples) * 1000.0;
         ICP_CSV  : File_Type;
      begin
         New_Line;
         Put_Line ("Scan matching (point-to-line ICP, keyframes) on a" & Natural (Sim.Clock)'Image
                   & " s drive with drifting odometry," & Samples'Image & " scans:");
         Put_Line ("  time per scan      " & Fixed (Per_Scan, 3) & " ms");
         Put_Line ("  converged          " & Converged'Image & " of" & Samples'Image);
         Put_Line ("  mean position error: odometry " & Fixed (Odom_Sum / Real (Samples), 3)
                   & " m, corrected " & Fixed (ICP_Sum / Real (Samples), 3) & " m");
         Put_Line ("  final position error: odometry " & Fixed (Odom_Final, 3)
                   & " m, corrected " & Fixed (ICP_Final, 3) & " m");
         Create (ICP_CSV, Out_File, "out/bench/sim-icp.csv");
         Put_Line (ICP_CSV, "scans,ms_per_scan,converged,mean_err_odom,mean_err_icp,"
                   & "final_err_odom,final_err_icp");
         Put_Line (ICP_CSV, Fixed (Real (Samples), 0) & "," & Fixed (Per_Scan, 4) & ","
                   & Fixed (Real (Converged), 0) & "," & Fixed (Odom_Sum / Real (Samples), 4)
                   & "," & Fixed (ICP_Sum / Real (Samples), 4) & "," & Fixed (Odom_Final, 4)
                   & "," & Fixed (ICP_Final, 4));
         Close (ICP_CSV);
      end;
   end Scan_Matching;

begin
   Map.Initialize (Worlds.Occupancy (World), Robot_Radius => 0.25);
   Create (CSV, Out_File, "out/bench/sim.csv");
   Put_Line (CSV, "robots,sim_seconds,wall_seconds,cpu_seconds,rtf_wall,rtf_cpu,"
             & "mrays_per_cpu_s");
   Put_Line ("Simulator alone, " & World_Name & ": physics 100 Hz, 360-beam lasers at 10 Hz,"
             & " odometry 20 Hz, one core");
   Put_Line ("RTF wall: simulated / elapsed seconds; RTF CPU: simulated / CPU seconds of"
             & " this process (what one core gives when the machine is shared)");
   Put_Line (" robots  sim (s) wall (s)  CPU (s) RTF wall  RTF CPU  Mrays/s");
   if Part /= "icp" then
      Team (1, 60.0 * Scale);
      Team (10, 30.0 * Scale);
      Team (50, 20.0 * Scale);
      Team (100, 10.0 * Scale);
   end if;
   Close (CSV);
   if Part /= "team" then
      Scan_Matching (150.0);
   end if;
end Bench_Sim;
