with Ada.Command_Line;
with Ada.Directories;

package body RCL.Utils is

   function Command_Name return String is
      Name : String := Ada.Directories.Simple_Name (Ada.Command_Line.Command_Name);
   begin
      for C of Name loop
         if C not in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_' then
            C := '_';
         end if;
      end loop;
      if Name'Length = 0 then
         return "ada_node";
      elsif Name (Name'First) in '0' .. '9' then
         return "n" & Name;
      end if;
      return Name;
   end Command_Name;

end RCL.Utils;
