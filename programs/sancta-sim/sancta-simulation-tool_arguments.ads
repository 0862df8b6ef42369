--  Command-line reading shared by the simulator's two programs, sancta-sim
--  (Sim_Tool) and sancta-render (Render_Tool). Each program keeps its own
--  options and messages; this package walks the arguments.
with Sancta.Geometry;

package Sancta.Simulation.Tool_Arguments is

   Usage_Error : exception;
   --  A bad command line; the message says what is wrong.

   function Next_Value (Index : in out Positive) return String;
   --  The argument after the option at Index; Index then designates it.
   --  Usage_Error "OPTION: missing value" when the command line ends there.

   function To_Real (Option, Text : String) return Sancta.Geometry.Real;
   --  Text ("2", "0.5", "1e3") as a number; Usage_Error
   --  "OPTION: expected a number, found "TEXT"" otherwise.

   generic
      with procedure Usage;
      with procedure Take (Argument : String; Index : in out Positive);
   function Parse_Arguments return Boolean;
   --  Take (Argument (I), I) for each command-line argument in turn (Take
   --  reads an option's value with Next_Value (I)). No argument at all:
   --  Usage, a failure exit status and False; "--help" or "-h": Usage and
   --  False (the program then stops); True when every argument is taken.

end Sancta.Simulation.Tool_Arguments;
