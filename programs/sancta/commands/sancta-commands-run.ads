--  sancta run FILE (--agent ID | --all) [--set NAME=VALUE]... [--for SECONDS]
--             [--debug] [--level SECTION=LEVEL]... [--log FILE] [--stats] [--managed]
--
--  Runs one agent (--agent, may be repeated) or every agent (--all) of a
--  configuration in this process, each with its own database and
--  scheduler. Ends on Ctrl-C, on a watchdog abort, or after --for SECONDS;
--  components are then stopped in reverse start order. The configuration
--  is checked first: any error and nothing runs (exit status 1).
--  --debug lowers every log section to debug, --level one section ("Ari",
--  "Ari/logger#3", "scheduler Ari", "database", "tasks"); --log also
--  appends the log to FILE; --stats prints each agent's scheduler
--  statistics at the end. --managed makes each agent a ROS 2 lifecycle
--  node /sancta_<ID> that starts unconfigured (see Managed_Agents).
package Sancta.Commands.Run is

   procedure Run;

end Sancta.Commands.Run;
