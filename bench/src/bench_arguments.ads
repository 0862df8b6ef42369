--  The command line of a benchmark program: "--help", and arguments read
--  with an error that names the argument and its position, on standard
--  error with exit status 2 (never an exception trace).
--
--     Read : constant Boolean :=
--       Bench_Arguments.Checked ("bench_cdr [SECONDS] [CSV-FILE]", Min => 0, Max => 2);
--     Budget : constant Duration := Bench_Arguments.Seconds (1, "SECONDS", 1.0);
--     --  "bench_cdr x": bench_cdr: SECONDS (argument 1): "x" is not a number
with Ada.Text_IO;

package Bench_Arguments is

   function Checked (Usage : String; Min, Max : Natural) return Boolean;
   --  To call before the program reads its command line. Usage: the usage
   --  line(s) from the program's name on (what "usage: " precedes), then
   --  what the arguments mean. "-h" or "--help" as any argument: Usage on
   --  standard output, exit status 0. Fewer than Min or more than Max
   --  arguments: Fail. Returns True.

   procedure Fail (Message : String) with No_Return;
   --  "PROGRAM: MESSAGE" then the usage's first line on standard error;
   --  exit status 2.

   function Seconds (Index : Positive; Name : String; Default : Duration) return Duration;
   --  Argument Index, Default when there is none, as a number of seconds
   --  (at least 0); Fail naming Name and Index otherwise.

   function Count (Index : Positive; Name : String; Minimum : Natural := 0) return Natural;
   --  Argument Index as a whole number, at least Minimum; Fail naming Name
   --  and Index when it is missing or no such number.

   function Number (Index : Positive; Name : String; Default : Long_Float) return Long_Float;
   --  Argument Index, Default when there is none, as a number greater
   --  than 0; Fail naming Name and Index otherwise.

   procedure Create_Output (File : in out Ada.Text_IO.File_Type; Name, What : String);
   --  Creates the text file Name; Fail "WHAT: "NAME" cannot be created"
   --  when it cannot (What: the option or argument that named it).

   function One_Of (Index : Positive; Name, Choices : String) return String;
   --  Argument Index when it is one of Choices ("ping|pong"); Fail naming
   --  Name, Index and the choices when it is missing or another word.

end Bench_Arguments;
