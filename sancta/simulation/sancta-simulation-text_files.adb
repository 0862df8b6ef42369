with Ada.Text_IO;

package body Sancta.Simulation.Text_Files is

   procedure Read_Lines (File_Name : String; Last_Line : out Natural) is
      use Ada.Text_IO;
      F : File_Type;
   begin
      begin
         Open (F, In_File, File_Name);
      exception
         when others =>
            raise Format_Error with File_Name & ": cannot be opened";
      end;
      Last_Line := 0;
      while not End_Of_File (F) loop
         Last_Line := Last_Line + 1;
         Read_Line (Get_Line (F), Last_Line);
      end loop;
      Close (F);
   exception
      when others =>
         if Is_Open (F) then
            Close (F);
         end if;
         raise;
   end Read_Lines;

end Sancta.Simulation.Text_Files;
