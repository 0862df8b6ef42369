with Ada.Strings.Fixed;
with Ada.Text_IO;

package body Sancta.Simulation.Text_Files is

   function Trimmed_Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

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
         declare
            Buffer : String (1 .. Max_Line_Length + 1);
            Last   : Natural;
         begin
            Get_Line (F, Buffer, Last);
            if Last = Buffer'Last then
               raise Format_Error with File_Name & ":" & Trimmed_Image (Last_Line)
                 & ": line longer than" & Max_Line_Length'Image & " characters";
            end if;
            Read_Line (Buffer (1 .. Last), Last_Line);
         end;
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
