with Ada.Strings.Fixed;
with Sancta.Robot.Goal_Sequencers;
with Sancta.Robot.Grids;
with Sancta.Robot.Navigators;
with Sancta.Robot.Path_Costs;
with Sancta.Simulation.Generators;
with Sancta.Simulation.Simulators;

package body Sancta.Simulation.Demos is

   use Robot;
   use Simulators;

   procedure Run_Team
     (World  : Worlds.World;
      Config : Demo_Config;
      Result : out Demo_Result)
   is
      F       : constant Grids.Frame := Worlds.Frame_Of (World);
      Map     : Path_Costs.Planner;
      Random  : Generators.Generator := Generators.Create (Config.Seed, 16#DE30#);
      Sim     : Simulator;
      N       : constant Positive := Config.Robots;
      Execs   : array (1 .. N) of Goal_Sequencers.Sequencer;
      Navs    : array (1 .. N) of Navigators.Navigator;
      Started : array (1 .. N) of Real := [others => 0.0];
      Goal_No : array (1 .. N) of Natural := [others => 0];
      Starts  : array (1 .. N) of Point;
      Id      : Robot_Id;
      Next_Record : Real := 0.0;

      Anchor : Point;
      --  Every start and goal must be reachable from here: the free point
      --  nearest to the world's centre (so the outside of a walled world,
      --  free but closed off, is never used).

      function Random_Point return Point is
         --  One draw per declaration (an aggregate's order is the compiler's)
         U : constant Real := Generators.Uniform (Random);
         V : constant Real := Generators.Uniform (Random);
      begin
         return (F.Origin.X + U * Real (F.Width) * F.Resolution,
                 F.Origin.Y + V * Real (F.Height) * F.Resolution);
      end Random_Point;

      function Random_Free (Near_Others : Natural) return Point is
         P : Point;
      begin
         for Attempt in 1 .. 20_000 loop
            P := Random_Point;
            if Map.Is_Free (P)
              and then (for all K in 1 .. Near_Others => Distance (Starts (K), P) >= 1.2)
              and then Map.Cost (Anchor, P) /= Path_Costs.Unreachable
            then
               return P;
            end if;
         end loop;
         raise Constraint_Error with "no room for" & N'Image & " robots in this world";
      end Random_Free;
   begin
      Result := (others => <>);
      Map.Initialize (Worlds.Occupancy (World), Robot_Radius => 0.35);
      Sim.Initialize (World, Config.Seed);
      Anchor := (F.Origin.X + Real (F.Width) * F.Resolution / 2.0,
                 F.Origin.Y + Real (F.Height) * F.Resolution / 2.0);
      declare
         Center : constant Point := Anchor;
         Best   : Real := Real'Last;
         P      : Point;
      begin
         for Attempt in 1 .. 5_000 loop
            P := Random_Point;
            if Map.Is_Free (P) and then Distance (P, Center) < Best then
               Best := Distance (P, Center);
               Anchor := P;
            end if;
         end loop;
      end;
      for R in 1 .. N loop
         Starts (R) := Random_Free (R - 1);
         Sim.Add_Robot (Default_Robot,
                        (Starts (R).X, Starts (R).Y,
                         2.0 * Pi * Generators.Uniform (Random) - Pi), Id);
         Result.Picture.Trajectories.Append (Rendering.Point_Vectors.Empty_Vector);
      end loop;
      for R in 1 .. N loop
         declare
            Last  : Point := Starts (R);
            Goals : Goal_Sequencers.Point_Array (1 .. Config.Goals_Per_Robot);
            G     : Point;
         begin
            for K in Goals'Range loop
               for Attempt in 1 .. 10_001 loop
                  if Attempt > 10_000 then
                     raise Constraint_Error with "no room for" & Goals'Length'Image
                       & " goals per robot in this world";
                  end if;
                  G := Random_Free (0);
                  --  Away from the other goals and starts too: a robot
                  --  that ended its tour parks on its last goal.
                  exit when Distance (G, Last) > 3.0
                    and then (for all M of Result.Picture.Markers =>
                                Distance (M.Where, G) > 1.0)
                    and then (for all K in 1 .. N => Distance (Starts (K), G) > 1.0)
                    and then Map.Cost (Last, G) /= Path_Costs.Unreachable;
               end loop;
               Goals (K) := G;
               Last := G;
               Result.Picture.Markers.Append
                 (Rendering.Marker'
                  (Where => G,
                   Label => Ada.Strings.Unbounded.To_Unbounded_String
                     ("r" & Ada.Strings.Fixed.Trim (R'Image, Ada.Strings.Left)
                      & "." & Ada.Strings.Fixed.Trim (K'Image, Ada.Strings.Left))));
            end loop;
            Execs (R).Assign (Goals, Tolerance => 0.3);
         end;
      end loop;
      Result.Goals_Total := N * Config.Goals_Per_Robot;
      Sim.Step (0.1);
      while Sim.Clock < Config.Seconds
        and then (for some R in 1 .. N => not Execs (R).Is_Done)
      loop
         for R in 1 .. N loop
            declare
               Id    : constant Robot_Id := Robot_Id (R);
               Truth : constant Pose := Sim.Ground_Truth (Id).Pose;
            begin
               Execs (R).Update (Truth);
               if Execs (R).Has_Goal
                 and then Sim.Clock - Started (R) > Config.Goal_Timeout
                 and then Goal_No (R) = Execs (R).Goal_Index
               then
                  Execs (R).Skip;
               end if;
               if Execs (R).Is_Done then
                  Sim.Set_Command (Id, (0.0, 0.0));
               else
                  if Goal_No (R) /= Execs (R).Goal_Index then
                     Goal_No (R) := Execs (R).Goal_Index;
                     Started (R) := Sim.Clock;
                     Navs (R).Set_Goal (Map, Truth, Execs (R).Current_Goal);
                  end if;
                  Sim.Set_Command
                    (Id, Navs (R).Command (Map, Truth, Sim.Latest_Scan (Id), Sim.Clock));
               end if;
               if Sim.Clock >= Next_Record then
                  Result.Picture.Trajectories (R).Append (Position (Truth));
               end if;
            end;
         end loop;
         if Sim.Clock >= Next_Record then
            Next_Record := Next_Record + Config.Record_Period;
         end if;
         Sim.Step (0.1);
         declare
            Events : Event_Vectors.Vector;
         begin
            Sim.Take_Events (Events);
            for E of Events loop
               if E.Kind in Wall_Collision | Robot_Collision then
                  Ada.Strings.Unbounded.Append
                    (Result.Collision_Log,
                     "t=" & Natural (E.Stamp)'Image & " s robot" & E.Robot'Image
                     & (if E.Kind = Wall_Collision then " hit a wall"
                        else " hit robot" & E.Other'Image)
                     & " at" & Integer (E.Where.X)'Image & "," & Integer (E.Where.Y)'Image
                     & ASCII.LF);
               end if;
            end loop;
         end;
      end loop;
      Result.Duration := Sim.Clock;
      for R in 1 .. N loop
         Result.Picture.Robots.Append (Sim.Ground_Truth (Robot_Id (R)).Pose);
         Result.Picture.Trajectories (R).Append (Position (Sim.Ground_Truth (Robot_Id (R)).Pose));
         Result.Collisions := Result.Collisions + Sim.Collision_Count (Robot_Id (R));
         Result.Goals_Skipped := Result.Goals_Skipped + Execs (R).Skipped;
         Result.Goals_Reached := Result.Goals_Reached
           + Execs (R).Completed - Execs (R).Skipped;
      end loop;
   end Run_Team;

end Sancta.Simulation.Demos;
