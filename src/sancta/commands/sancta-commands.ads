--  The subcommands of the "sancta" program, one child package each.
package Sancta.Commands is
end Sancta.Commands;
