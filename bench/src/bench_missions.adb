--  Team missions benchmark (bench/bench-missions.sh):
--  1. plan quality: makespan and total distance of the annealer, the
--     sequential single-item auctions and the greedy baseline on the same
--     random missions (10, 50, 200 tasks; 4 and 10 robots; 30 m x 20 m);
--  2. re-planning after a robot loss: team agents over DDS (loopback), the
--     time from the loss to the new round (detection: lease + settling) and
--     from the new round to the adopted plan, annealer and auctions;
--  3. team database convergence time with 2, 5 and 10 nodes.
--  Prints tables; writes out/bench/missions.csv and missions.json.
with Ada.Command_Line;
with Ada.Directories;
with Ada.Real_Time;           use Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;   use Ada.Strings.Unbounded;
with Ada.Text_IO;             use Ada.Text_IO;
with Bench_Arguments;
with Interfaces;
with Sancta.Geometry;
with Sancta.Team.Agents;
with Sancta.Team.Replicated_Databases;
with Sancta.Team.Missions;    use Sancta.Team.Missions;
with Sancta.Team.Networks;
with Sancta.Team.Plans;       use Sancta.Team.Plans;

procedure Bench_Missions is

   use type Interfaces.Unsigned_64;

   subtype Real is Sancta.Geometry.Real;
   type Count_List is array (Positive range <>) of Positive;
   Task_Counts  : constant Count_List := [10, 50, 200];
   Robot_Counts : constant Count_List := [4, 10];
   Node_Counts  : constant Count_List := [2, 5, 10];

   Read   : constant Boolean := Bench_Arguments.Checked
     ("bench_missions [--quick]" & ASCII.LF
      & "team missions benchmark (bench/bench-missions.sh): plan quality of the annealer,"
      & ASCII.LF & "auctions and greedy; re-planning after a robot loss over DDS; team database"
      & ASCII.LF & "convergence; writes out/bench/missions.csv and missions.json" & ASCII.LF
      & "  --quick   annealer budget 0.3 s instead of 2 s, re-planning with 20 tasks"
      & " instead of 50",
      Min => 0, Max => 1);
   pragma Unreferenced (Read);
   Quick  : constant Boolean :=
     Ada.Command_Line.Argument_Count > 0
     and then Bench_Arguments.One_Of (1, "option", "--quick") = "--quick";
   Budget : constant Duration := (if Quick then 0.3 else 2.0);
   CSV    : Unbounded_String :=
     To_Unbounded_String ("part,method,tasks,robots,nodes,makespan_m,total_m,time_s" & ASCII.LF);
   JSON   : Unbounded_String := To_Unbounded_String ("[" & ASCII.LF);
   First_Row : Boolean := True;

   function F (X : Long_Float; Decimals : Natural := 1) return String is
      Scale  : constant Long_Float := 10.0 ** Decimals;
      Scaled : constant Long_Long_Integer := Long_Long_Integer (X * Scale);
      Whole  : constant String := Ada.Strings.Fixed.Trim
        (Long_Long_Integer'Image (Scaled / Long_Long_Integer (Scale)), Ada.Strings.Left);
      Frac   : constant String := Ada.Strings.Fixed.Trim
        (Long_Long_Integer'Image (Scaled mod Long_Long_Integer (Scale)), Ada.Strings.Left);
   begin
      return Whole & (if Decimals = 0 then ""
                      else "." & [1 .. Decimals - Frac'Length => '0'] & Frac);
   end F;

   function Pad (S : String; N : Positive) return String is
     (if S'Length >= N then S else [1 .. N - S'Length => ' '] & S);

   procedure Row (Part, Method : String; Tasks, Robots, Nodes : Natural;
                  Makespan, Total, Time : Long_Float) is
      function I (N : Natural) return String is
        (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));
   begin
      Append (CSV, Part & "," & Method & "," & I (Tasks) & "," & I (Robots) & "," & I (Nodes)
              & "," & F (Makespan, 2) & "," & F (Total, 2) & "," & F (Time, 4) & ASCII.LF);
      Append (JSON, (if First_Row then "" else "," & ASCII.LF)
              & "  {""part"": """ & Part & """, ""method"": """ & Method & """, ""tasks"": "
              & I (Tasks) & ", ""robots"": " & I (Robots) & ", ""nodes"": " & I (Nodes)
              & ", ""makespan_m"": " & F (Makespan, 2) & ", ""total_m"": " & F (Total, 2)
              & ", ""time_s"": " & F (Time, 4) & "}");
      First_Row := False;
   end Row;

   --  A deterministic pseudo-random generator (xorshift).
   State : Interfaces.Unsigned_64 := 16#9E37_79B9_7F4A_7C15#;
   function Uniform return Long_Float is
   begin
      State := State xor Interfaces.Shift_Left (State, 13);
      State := State xor Interfaces.Shift_Right (State, 7);
      State := State xor Interfaces.Shift_Left (State, 17);
      return Long_Float (Interfaces.Shift_Right (State, 11)) / 2.0 ** 53;
   end Uniform;

   function Random_Point return Point is
     ((Real (30.0 * Uniform), Real (20.0 * Uniform)));

   function Random_Round (Tasks, Robots : Positive) return Snapshot is
      S : Snapshot;
   begin
      S.Generation := 1;
      for R in 1 .. Robots loop
         S.Robots.Append (Robot_Position'(To_Unbounded_String
           ("r" & Ada.Strings.Fixed.Trim (R'Image, Ada.Strings.Left)), Random_Point));
      end loop;
      for T in 1 .. Tasks loop
         declare
            M : Mission_Task;
         begin
            M.Id := To_Unbounded_String ("t" & Ada.Strings.Fixed.Trim (T'Image, Ada.Strings.Left));
            if T mod 10 = 0 then
               M.Kind := Explore_Segment;
               M.Points.Append (Point'(Random_Point));
               M.Points.Append (Point'(Random_Point));
            elsif T mod 10 = 5 then
               M.Kind := Choose_Entry;
               M.Points.Append (Point'(Random_Point));
               M.Points.Append (Point'(Random_Point));
            else
               M.Points.Append (Point'(Random_Point));
            end if;
            S.Tasks.Append (M);
         end;
      end loop;
      return S;
   end Random_Round;

   function Seconds (From : Time) return Long_Float is
     (Long_Float (To_Duration (Clock - From)));

   procedure Plan_Quality is
   begin
      Put_Line ("== 1. plan quality (random missions 30 m x 20 m, straight-line costs;"
                & " annealer budget" & Duration'Image (Budget) & " s, from the greedy plan)");
      Put_Line ("tasks robots | greedy mksp  total | auction mksp  total | annealer mksp  total"
                & " | auction s");
      for Tasks of Task_Counts loop
         for Robots of Robot_Counts loop
            declare
               S  : constant Snapshot := Random_Round (Tasks, Robots);
               T0 : Time := Clock;
               G  : constant Plan := Greedy (S, "greedy");
               TG : constant Long_Float := Seconds (T0);
               A  : Plan;
               TA : Long_Float;
               N  : Plan;
               TN : Long_Float;
            begin
               T0 := Clock;
               A := Auction (S, "auction");
               TA := Seconds (T0);
               T0 := Clock;
               N := Anneal (S, 1, Budget, G, "annealer");
               TN := Seconds (T0);
               Row ("quality", "greedy", Tasks, Robots, 1, Makespan (S, G), Total (S, G), TG);
               Row ("quality", "auctions", Tasks, Robots, 1, Makespan (S, A), Total (S, A), TA);
               Row ("quality", "annealer", Tasks, Robots, 1, Makespan (S, N), Total (S, N), TN);
               Put_Line (Pad (Tasks'Image, 5) & Pad (Robots'Image, 7) & " |"
                         & Pad (F (Makespan (S, G)), 12) & Pad (F (Total (S, G)), 7) & " |"
                         & Pad (F (Makespan (S, A)), 13) & Pad (F (Total (S, A)), 7) & " |"
                         & Pad (F (Makespan (S, N)), 14) & Pad (F (Total (S, N)), 7) & " |"
                         & Pad (F (TA, 3), 10));
            end;
         end loop;
      end loop;
   end Plan_Quality;

   Run_Count : Natural := 0;

   procedure Replan (How : Sancta.Team.Agents.Method; Robots, Tasks : Positive) is
      use Sancta.Team.Agents;
      Lease : constant Duration := 0.5;
      Team  : constant String := "bench_replan" & Ada.Strings.Fixed.Trim
        (Natural'Image (Run_Count), Ada.Strings.Left);
      List  : array (1 .. Robots) of Agent_Access;
      Op    : Agent_Access;
      S     : constant Snapshot := Random_Round (Tasks, Robots);
      M     : Mission;
      T0    : Time;
      Limit : constant Time := Clock + Seconds (60);
      Gen   : Natural;
      Round_Time, Plan_Time : Long_Float := -1.0;
   begin
      Run_Count := Run_Count + 1;
      M.Tasks := S.Tasks;
      for R in 1 .. Robots loop
         List (R) := Create ((Id => S.Robots (R).Id, Team => To_Unbounded_String (Team),
                              Lease => Lease, How => How, Verbose => False,
                              Seed => Interfaces.Unsigned_64 (R), others => <>));
         List (R).Set_Pose (S.Robots (R).Where);
      end loop;
      Op := Create ((Id => To_Unbounded_String ("operator"), Team => To_Unbounded_String (Team),
                     Is_Robot => False, Lease => Lease, Verbose => False, others => <>));
      Op.Publish_Mission (M);
      while List (2).Adopted.Generation = 0 and then Clock < Limit loop
         delay 0.01;
      end loop;
      delay 0.5;  --  let the annealers' improvement rounds settle
      Gen := List (2).Round.Generation;
      --  Lose robot r1: the coordinator (the smallest id), the worst case.
      T0 := Clock;
      List (1).Stop;
      while Clock < Limit loop
         declare
            Now_Round : constant Snapshot := List (2).Round;
         begin
            if Round_Time < 0.0 and then Now_Round.Generation > Gen then
               Round_Time := Seconds (T0);
            end if;
            if Round_Time >= 0.0 and then List (2).Adopted.Generation = Now_Round.Generation
            then
               Plan_Time := Seconds (T0) - Round_Time;
               exit;
            end if;
         end;
         delay 0.002;
      end loop;
      for R in 2 .. Robots loop
         List (R).Stop;
      end loop;
      Op.Stop;
      Row ("replan", (case How is when Annealing => "annealer", when Auctions => "auctions"),
           Tasks, Robots, Robots, 0.0, 0.0, Plan_Time);
      Put_Line (Pad ((case How is when Annealing => "annealer", when Auctions => "auctions"), 9)
                & Pad (Robots'Image, 7) & Pad (Tasks'Image, 6) & " |"
                & Pad (F (Round_Time, 3), 16) & Pad (F (Plan_Time, 3), 21));
   end Replan;

   procedure Convergence (Nodes : Positive) is
      use Sancta.Team.Networks;
      use Sancta.Team.Replicated_Databases;
      Team : constant String := "bench_db" & Ada.Strings.Fixed.Trim (Nodes'Image, Ada.Strings.Left);
      Nets : array (1 .. Nodes) of Network_Access;
      Dbs  : array (1 .. Nodes) of Team_Database_Access;
      T0   : Time;
      Limit : constant Time := Clock + Seconds (60);
      Took : Long_Float := -1.0;
   begin
      for N in 1 .. Nodes loop
         Nets (N) := Create ("n" & Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left),
                             Lease => 1.0, Team => Team);
         Dbs (N) := new Team_Database (Nets (N));
         Dbs (N).Attach;
         Nets (N).Start;
      end loop;
      while (for some N of Nets => Natural (N.Members.Length) < Nodes) and then Clock < Limit loop
         delay 0.01;
      end loop;
      delay 0.5;
      T0 := Clock;
      for N in 1 .. Nodes loop
         for K in 1 .. 20 loop
            Dbs (N).Put ("own/" & Nets (N).Id & "/" & K'Image, "v" & K'Image);
         end loop;
         for K in 1 .. 5 loop
            Dbs (N).Put ("shared/" & K'Image, Nets (N).Id);
         end loop;
      end loop;
      while Clock < Limit loop
         if (for all N in 2 .. Nodes => Dbs (N).Digest = Dbs (1).Digest)
           and then Natural (Dbs (1).Keys.Length) = 20 * Nodes + 5
         then
            Took := Seconds (T0);
            exit;
         end if;
         delay 0.001;
      end loop;
      for N of Nets loop
         N.Stop;
      end loop;
      Row ("database", "replicated", 20 * Nodes + 5, 0, Nodes, 0.0, 0.0, Took);
      Put_Line (Pad (Nodes'Image, 6) & Pad (Natural'Image (25 * Nodes), 8)
                & Pad (F (Took * 1000.0, 1), 16));
   end Convergence;

   File : File_Type;
begin
   Plan_Quality;
   New_Line;
   Put_Line ("== 2. re-planning after the loss of the coordinator (DDS loopback, lease 0.5 s)");
   Put_Line ("   method robots tasks | loss->round (s) | round->adopted plan (s)");
   for How in Sancta.Team.Agents.Method loop
      for Robots of Robot_Counts loop
         Replan (How, Robots, (if Quick then 20 else 50));
      end loop;
   end loop;
   New_Line;
   Put_Line ("== 3. team database convergence (each node writes 20 own keys + 5 shared keys)");
   Put_Line (" nodes  writes  converged (ms)");
   for Nodes of Node_Counts loop
      Convergence (Nodes);
   end loop;
   Append (JSON, ASCII.LF & "]" & ASCII.LF);
   Ada.Directories.Create_Path ("out/bench");
   Create (File, Out_File, "out/bench/missions.csv");
   Put (File, To_String (CSV));
   Close (File);
   Create (File, Out_File, "out/bench/missions.json");
   Put (File, To_String (JSON));
   Close (File);
   Put_Line ("written: out/bench/missions.csv, out/bench/missions.json");
end Bench_Missions;
