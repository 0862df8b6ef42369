with Ada.Directories;
with Ada.Environment_Variables;
with Sancta.Team.Networks;

package body Sancta.Team.Security is

   package Keystores renames RCL.Security.Keystores;

   procedure Create_Keystore
     (Dir, Team : String; Task_Writers, Other_Nodes : Id_List;
      Readers : Id_List := [1 .. 0 => <>])
   is
      Tasks : constant String := "rt" & Networks.Tasks_Topic (Team);
      No_Tasks : constant Keystores.Topic_Rules :=
        [1 => (Allow => False, Kind => Keystores.Publish, Topic => To_Unbounded_String (Tasks)),
         2 => (Allow => True, Kind => Keystores.Publish, Topic => To_Unbounded_String ("*")),
         3 => (Allow => True, Kind => Keystores.Subscribe, Topic => To_Unbounded_String ("*"))];
   begin
      Keystores.Create_Keystore (Dir);
      for Id of Task_Writers loop
         Keystores.Create_Enclave (Dir, Enclave (Team, To_String (Id)));
      end loop;
      for Id of Other_Nodes loop
         Keystores.Create_Enclave (Dir, Enclave (Team, To_String (Id)));
         Keystores.Create_Permission (Dir, Enclave (Team, To_String (Id)), No_Tasks);
      end loop;
      for Id of Readers loop
         Keystores.Create_Enclave (Dir, Enclave (Team, To_String (Id)));
         Keystores.Create_Permission (Dir, Enclave (Team, To_String (Id)), Reader_Rules);
      end loop;
      Keystores.Create_Enclave (Dir, Simulator_Enclave);
      Keystores.Create_Permission (Dir, Simulator_Enclave, No_Tasks);
   end Create_Keystore;

   procedure Enable (Keystore : String) is
   begin
      Ada.Environment_Variables.Set ("ROS_SECURITY_ENABLE", "true");
      Ada.Environment_Variables.Set ("ROS_SECURITY_STRATEGY", "Enforce");
      Ada.Environment_Variables.Set ("ROS_SECURITY_KEYSTORE", Ada.Directories.Full_Name (Keystore));
   end Enable;

   procedure Set_Child_Enclave (Name : String) is
   begin
      if Name = "" then
         Ada.Environment_Variables.Clear ("ROS_SECURITY_ENCLAVE_OVERRIDE");
      else
         Ada.Environment_Variables.Set ("ROS_SECURITY_ENCLAVE_OVERRIDE", Name);
      end if;
   end Set_Child_Enclave;

end Sancta.Team.Security;
