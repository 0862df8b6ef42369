with Ada.Command_Line;
with Ada.Directories;
with RCL.Names;

package body RCL.Utils is

   function Command_Name return String is
      Name : constant String :=
        RCL.Names.Name_Token (Ada.Directories.Simple_Name (Ada.Command_Line.Command_Name));
   begin
      if Name'Length = 0 then
         return "ada_node";
      elsif Name (Name'First) in '0' .. '9' then
         return "n" & Name;
      end if;
      return Name;
   end Command_Name;

end RCL.Utils;
