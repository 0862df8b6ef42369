--  A team demonstration without middleware: N robots in a world, each with
--  a random tour of reachable goals, driven by the robot-side executor,
--  navigator (A* path + go-to-goal with laser avoidance) on ground truth.
--  Used by sancta-render --demo and as the reference closed loop.
--
--     Run_Team (World, (Robots => 6, Seconds => 120.0, others => <>), Result);
--     Rendering.Write_SVG (World, Result.Picture, "team.svg");
with Ada.Strings.Unbounded;
with Interfaces;
with Sancta.Geometry;               use Sancta.Geometry;
with Sancta.Simulation.Rendering;
with Sancta.Simulation.Worlds;

package Sancta.Simulation.Demos is

   type Demo_Config is record
      Robots          : Positive := 6;
      Seconds         : Real := 120.0;
      Seed            : Interfaces.Unsigned_64 := 1;
      Goals_Per_Robot : Positive := 4;
      Goal_Timeout    : Real := 60.0;
      --  A goal not reached in this long is skipped.
      Record_Period   : Real := 0.5;
   end record;

   type Demo_Result is record
      Picture       : Rendering.Scene;
      --  Trajectories, final robot poses and the goals as markers.
      Collisions    : Natural := 0;
      Goals_Total   : Natural := 0;
      Goals_Reached : Natural := 0;
      Goals_Skipped : Natural := 0;
      Duration      : Real := 0.0;
      --  Simulated seconds until every tour ended (or the limit).
      Collision_Log : Ada.Strings.Unbounded.Unbounded_String;
      --  One line per collision.
   end record;

   procedure Run_Team
     (World  : Worlds.World;
      Config : Demo_Config;
      Result : out Demo_Result);
   --  Raises Constraint_Error when the world has no room for the robots.

end Sancta.Simulation.Demos;
