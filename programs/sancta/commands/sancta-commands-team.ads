--  "sancta team": the team mission demo (Sancta.Commands.Team_Demos).
--
--     sancta team [MISSION.xml] [--method annealer|auctions] [--rate 25]
--        [--kill ID | --no-kill] [--kill-at 0.3] [--lease 0.5] [--max 1200]
--        [--world FILE] [--out out/demo] [--quiet] [--check]
--
--  Without MISSION, share/missions/office-team.xml of the installation.
--  --check: exit status 1 unless every task was done exactly once (and,
--  when a robot was killed, the survivors re-planned).
package Sancta.Commands.Team is

   procedure Run;

end Sancta.Commands.Team;
