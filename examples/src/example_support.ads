--  What the examples share that is not the RCLAda API they show: their own
--  command-line arguments, which come before ROS 2's (RCL.Arguments:
--  "--ros-args ..."), and the way they report a failure.
--
--     Period : constant Duration := Duration'Value (Argument (1, "1.0"));
--     ...
--  exception
--     when E : RCL.Arguments.Argument_Error | Constraint_Error =>
--        Fail (E);
with Ada.Command_Line;
with Ada.Exceptions;

package Example_Support is

   function Argument (N : Positive; Default : String) return String;
   --  The program's Nth argument, or Default when fewer than N come before
   --  the first "--ros-args" (or the end).

   procedure Fail
     (E      : Ada.Exceptions.Exception_Occurrence;
      Status : Ada.Command_Line.Exit_Status := 2);
   --  Logs E's message as an error (RCL.Logging) and sets the exit status
   --  (2: a bad command line).

end Example_Support;
