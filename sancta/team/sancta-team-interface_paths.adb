with Ada.Directories;
with Ada.Environment_Variables;
with ROSIDL.Interfaces;
with Sancta.Installation;

package body Sancta.Team.Interface_Paths is

   protected Once is
      procedure Mark (First : out Boolean);
   private
      Done : Boolean := False;
   end Once;

   protected body Once is
      procedure Mark (First : out Boolean) is
      begin
         First := not Done;
         Done := True;
      end Mark;
   end Once;

   procedure Add_Variable_Folders;
   --  Each existing folder of $SANCTA_INTERFACE_PATH.

   procedure Add_Variable_Folders is
      Variable : constant String := Installation.Interface_Path_Variable;
   begin
      if not Ada.Environment_Variables.Exists (Variable) then
         return;
      end if;
      declare
         Value : constant String := Ada.Environment_Variables.Value (Variable) & ":";
         First : Positive := Value'First;
      begin
         for I in Value'Range loop
            if Value (I) = ':' then
               if I > First and then Ada.Directories.Exists (Value (First .. I - 1)) then
                  ROSIDL.Interfaces.Add_Folder (Value (First .. I - 1));
               end if;
               First := I + 1;
            end if;
         end loop;
      end;
   end Add_Variable_Folders;

   procedure Ensure is
      First : Boolean;
   begin
      Once.Mark (First);
      if not First then
         return;
      end if;
      declare
         Folder : constant String := Installation.Share_File ("interfaces");
         Found  : Boolean := False;
      begin
         for P of ROSIDL.Interfaces.Search_Path loop
            Found := Found or else Ada.Directories.Exists (P & "/sancta_msgs/msg/Envelope.msg");
         end loop;
         if not Found then
            if not Ada.Directories.Exists (Folder) then
               raise Program_Error with
                 Folder & ": the project's interface folder (sancta_msgs) is missing";
            end if;
            ROSIDL.Interfaces.Add_Folder (Folder);
         end if;
      end;
      Add_Variable_Folders;
   end Ensure;

end Sancta.Team.Interface_Paths;
