--  Reading the simulation's text input files (map YAML, wall worlds,
--  trajectory CSV) line by line, the file closed whatever happens.
--
--     procedure Read_Line (Line : String; Line_No : Positive) is ...;
--     procedure Read_All is new Text_Files.Read_Lines (Read_Line);
--     Read_All (File_Name, Last_Line);
private package Sancta.Simulation.Text_Files is

   generic
      with procedure Read_Line (Line : String; Line_No : Positive);
   procedure Read_Lines (File_Name : String; Last_Line : out Natural);
   --  Passes each line of File_Name and its number to Read_Line; Last_Line
   --  is the number of lines. The file is closed also when Read_Line
   --  raises. Format_Error "FILE: cannot be opened", or "FILE:LINE: line
   --  longer than 65536 characters" (no input of the simulation needs one;
   --  a megabyte line must not exhaust the stack).

   Max_Line_Length : constant := 65_536;

end Sancta.Simulation.Text_Files;
