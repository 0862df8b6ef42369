--  SANCTA components for team missions (registered with the factory):
--
--     <component name="team_member" team="team" method="annealer" lease="1.0"
--                tolerance="0.3" costs="grid" world="office" robot_radius="0.2">
--       <requires data="pose" as="pose" type="types.pose"/>
--       <provides data="goal" as="goal" type="types.pose"/>
--       <provides data="status" as="team_status" type="types.string"/>
--     </component>
--  makes the agent a robot of the team (a Sancta.Team.Agents agent whose id
--  is the agent's id): its pose goes to the team, the goal of its current
--  task comes out (for path_costs / go_to_goal), arriving within tolerance
--  of a goal marks the progress of the task. costs="grid" makes the
--  allocation cost legs by A* on the world's grid (Sancta.Team.Grid_Costs;
--  world= a bundled world or a map file); "straight" (default) by straight
--  lines. Every robot of a team must use the same costs. Logs its goals,
--  idle spells and the agent's rounds.
--
--     <component name="team_operator" mission="share/missions/office-team.xml"
--                team="team" lease="1.0" stop_when_done="true">
--       <provides data="progress" as="team_progress" type="types.string"/>
--     </component>
--  publishes the mission to the team, reports "done/total round N" and, with
--  stop_when_done, requests the program's shutdown once every task is done.
package Sancta.Team.Team_Components is
   pragma Elaborate_Body;
end Sancta.Team.Team_Components;
