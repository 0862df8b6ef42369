with Ada.Directories;
with Ada.Strings.Fixed;
with ROSIDL.Definitions;
with ROSIDL.Interfaces;

package body Sancta.Team.Interfaces is

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

   procedure Ensure is
      First : Boolean;
   begin
      Once.Mark (First);
      if not First then
         return;
      end if;
      declare
         Path    : constant ROSIDL.Definitions.String_Vectors.Vector :=
           ROSIDL.Interfaces.Search_Path;
         Bundled : constant String := (if Path.Is_Empty then "" else Path.First_Element);
         Suffix  : constant String := "ros2_interfaces";
         Cut     : constant Natural :=
           Ada.Strings.Fixed.Index (Bundled, Suffix, Going => Ada.Strings.Backward);
         Folder  : constant String :=
           (if Cut = 0 then "share/interfaces"
            else Bundled (Bundled'First .. Cut - 1) & "interfaces");
      begin
         for P of Path loop
            if Ada.Directories.Exists (P)
              and then Ada.Directories.Exists (P & "/sancta_msgs/msg/Envelope.msg")
            then
               return;  --  already searched (the project's folder is on the path)
            end if;
         end loop;
         if not Ada.Directories.Exists (Folder) then
            raise Program_Error with
              Folder & ": the project's interface folder (sancta_msgs) is missing";
         end if;
         ROSIDL.Interfaces.Add_Folder (Folder);
      end;
   end Ensure;

end Sancta.Team.Interfaces;
