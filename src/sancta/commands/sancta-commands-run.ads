--  sancta run FILE (--agent ID | --all) [--set NAME=VALUE]... [--for SECONDS]
--             [--debug] [--log FILE]
--
--  Runs one agent (--agent, may be repeated) or every agent (--all) of a
--  configuration in this process, each with its own database and
--  scheduler. Ends on Ctrl-C, on a watchdog abort, or after --for SECONDS;
--  components are then stopped in reverse start order. The configuration
--  is checked first: any error and nothing runs (exit status 1).
package Sancta.Commands.Run is

   procedure Run;

end Sancta.Commands.Run;
