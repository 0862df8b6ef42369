--  "sancta plan": task allocation on a TSPLIB instance (or SANCTA mission
--  file) from the command line.
--
--     sancta plan eil51.tsp --robots 5 --objective minmax --time 10s --seed 1
--        --svg tours.svg --json -
--
--  Prints each robot's tour and cost; a progress line on standard error
--  while it works (best cost, moves/s, temperature); optional SVG picture
--  and JSON result. Run with --help for every option.
package Sancta.Commands.Plan is

   procedure Run (First_Argument : Positive := 2);
   --  Reads the arguments from First_Argument on; sets the exit status.

end Sancta.Commands.Plan;
