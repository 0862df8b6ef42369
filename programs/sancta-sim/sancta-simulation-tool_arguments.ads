--  Command-line reading shared by the simulator's two programs, sancta-sim
--  (Sim_Tool) and sancta-render (Render_Tool). Each program keeps its own
--  options and messages; this package walks the arguments.
with Ada.Strings.Unbounded;
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
      with procedure Take (Option : String; Index : in out Positive);
      --  An argument starting with '-'; reads its value with Next_Value.
      with function Second_World (Argument : String) return String;
      --  The message when Argument is a second world.
      No_World : String;
      --  The message when no world is given.
   function Parse_Arguments (World : out Ada.Strings.Unbounded.Unbounded_String)
     return Boolean;
   --  The command line: one world (an argument not starting with '-') and
   --  options, each given to Take (Argument (I), I) in turn. No argument at
   --  all: Usage, a failure exit status and False; "--help" or "-h": Usage
   --  and False (the program then stops); True when every argument is
   --  taken. Usage_Error No_World or Second_World (A) unless exactly one
   --  world is given.

end Sancta.Simulation.Tool_Arguments;
