with Ada.Command_Line;
with Ada.Directories;
with Ada.Environment_Variables;
with GNAT.OS_Lib;

package body Sancta.Installation is

   function Program_Folder return String;
   --  The folder of the running program, "" when it cannot be found.

   function Program_Folder return String is
      use type GNAT.OS_Lib.String_Access;
      Found : GNAT.OS_Lib.String_Access :=
        GNAT.OS_Lib.Locate_Exec_On_Path (Ada.Command_Line.Command_Name);
   begin
      if Found = null then
         return "";
      end if;
      declare
         Result : constant String :=
           Ada.Directories.Containing_Directory (Ada.Directories.Full_Name (Found.all));
      begin
         GNAT.OS_Lib.Free (Found);
         return Result;
      end;
   exception
      when others =>
         return "";
   end Program_Folder;

   function Share_Folder return String is
   begin
      if Ada.Environment_Variables.Exists (Root_Variable)
        and then Ada.Environment_Variables.Value (Root_Variable) /= ""
      then
         return Ada.Environment_Variables.Value (Root_Variable) & "/share";
      end if;
      declare
         Folder : constant String := Program_Folder;
      begin
         return (if Folder = "" then "share" else Folder & "/../share");
      end;
   end Share_Folder;

end Sancta.Installation;
