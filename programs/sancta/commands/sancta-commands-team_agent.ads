--  "sancta team-agent": one team node per process, for teams spanning
--  several hosts (the DDS configuration of the host decides who is seen).
--
--     sancta team-agent --id r1 --x 2 --y 10 [--speed 1.0] [--rate 10]
--        [--team NAME] [--method annealer|auctions] [--lease 1.0] [--for S]
--  a robot agent with a kinematic body (straight lines at --speed metres per
--  simulated second, --rate simulated seconds per second): it takes part
--  in the allocation and "executes" its tasks, printing "did TASK".
--
--     sancta team-agent --operator MISSION.xml [--team NAME] [--for S]
--  the operator: publishes the mission's tasks, prints every new round
--  ("round G robots a,b,c tasks N") and the progress, and when every task
--  is done prints "done TASK by ROBOT" lines and "all done" (exit 0);
--  exit 1 when --for (default 120 s) ends first.
package Sancta.Commands.Team_Agent is

   procedure Run;

end Sancta.Commands.Team_Agent;
