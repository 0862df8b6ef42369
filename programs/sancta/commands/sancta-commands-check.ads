--  sancta check FILE [--set NAME=VALUE]... [--output DIR]
--
--  Loads and checks a configuration without running it: prints every
--  diagnostic (file:line:column: error|warning: ...), the wiring of each
--  agent as a table, and writes DIR/<name>.dot (default DIR: out/check),
--  plus DIR/<name>.svg when Graphviz's "dot" is installed. Exit status 0
--  when there is no error (warnings allowed), 1 otherwise, 2 on bad usage.
package Sancta.Commands.Check is

   procedure Run;

end Sancta.Commands.Check;
