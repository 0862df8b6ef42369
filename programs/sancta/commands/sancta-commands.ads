--  The subcommands of the "sancta" program, one child package each with a
--  procedure Run that reads Ada.Command_Line (argument 1 is the command
--  name) and sets the exit status.
package Sancta.Commands is
end Sancta.Commands;
