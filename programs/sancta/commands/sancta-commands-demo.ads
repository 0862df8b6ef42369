--  "sancta demo": the team demo with every robot a SANCTA agent of one
--  configuration file, one process per agent, on sancta-sim
--  (Sancta.Commands.Sim_Team_Demos). The README's run command.
--
--     sancta demo [CONFIG.xml] [--set NAME=VALUE]... [--rate 4] [--wall-clock]
--        [--kill ID | --no-kill] [--kill-at 0.25] [--max 1200] [--max-wall 900]
--        [--out out/demo] [--quiet] [--check]
--
--  Without CONFIG, share/config/sim-team.xml of the installation.
--  --set method=auctions chooses sequential auctions instead of the
--  distributed annealer (any constant of the file can be set).
--  --wall-clock: the agents run on the wall clock instead of /clock.
--  --check: exit status 1 unless every task was done exactly once and,
--  when a robot was killed, the survivors re-planned and did its
--  unfinished tasks.
package Sancta.Commands.Demo is

   procedure Run;

end Sancta.Commands.Demo;
