with Ada.Command_Line;
with Ada.Text_IO; use Ada.Text_IO;
with Bench_Arguments;

package body Bench_Rows is

   CSV : File_Type;

   procedure Open (CSV_Argument : Positive) is
   begin
      if Ada.Command_Line.Argument_Count >= CSV_Argument then
         Bench_Arguments.Create_Output
           (CSV, Ada.Command_Line.Argument (CSV_Argument),
            "CSV-FILE (argument" & CSV_Argument'Image & ")");
      end if;
   end Open;

   procedure Put (Row : String) is
   begin
      Put_Line (Row);
      if Is_Open (CSV) then
         Put_Line (CSV, Row);
      end if;
   end Put;

   procedure Close is
   begin
      if Is_Open (CSV) then
         Close (CSV);
      end if;
   end Close;

end Bench_Rows;
