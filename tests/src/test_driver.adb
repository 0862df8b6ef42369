--  The one AUnit driver: runs every suite listed in All_Suites and sets the
--  exit status (non-zero when any test fails or raises).
--
--  Network rule: the suites create DDS participants. When the driver is run
--  by hand without scripts/env.sh, it still keeps them on loopback: an unset
--  CYCLONEDDS_URI is pointed at share/cyclonedds-localhost.xml (found from
--  the executable's folder) and an unset ROS_DOMAIN_ID gets one of this
--  process's own, before any participant exists.
with Ada.Command_Line;
with Ada.Directories;
with Ada.Environment_Variables;
with AUnit;
with AUnit.Reporter.Text;
with AUnit.Run;
with GNAT.OS_Lib;
with All_Suites;

procedure Test_Driver is

   procedure Keep_DDS_On_Loopback is
      package Env renames Ada.Environment_Variables;
      Exe    : constant String :=
        GNAT.OS_Lib.Normalize_Pathname (Ada.Command_Line.Command_Name);
      Config : constant String :=
        Ada.Directories.Containing_Directory (Exe)
        & "/../share/cyclonedds-localhost.xml";
   begin
      if not Env.Exists ("CYCLONEDDS_URI") then
         if not Ada.Directories.Exists (Config) then
            raise Program_Error with "loopback DDS configuration not found: " & Config;
         end if;
         Env.Set ("CYCLONEDDS_URI",
                  "file://" & GNAT.OS_Lib.Normalize_Pathname (Config));
      end if;
      if not Env.Exists ("ROS_DOMAIN_ID") then
         declare
            Id : constant String :=
              Integer'Image (GNAT.OS_Lib.Pid_To_Integer
                               (GNAT.OS_Lib.Current_Process_Id) mod 200 + 1);
         begin
            Env.Set ("ROS_DOMAIN_ID", Id (Id'First + 1 .. Id'Last));
         end;
      end if;
   end Keep_DDS_On_Loopback;

   function Run is new AUnit.Run.Test_Runner_With_Status (All_Suites.Suite);
   Reporter : AUnit.Reporter.Text.Text_Reporter;
   use type AUnit.Status;
begin
   Keep_DDS_On_Loopback;
   if Run (Reporter) /= AUnit.Success then
      Ada.Command_Line.Set_Exit_Status (Ada.Command_Line.Failure);
   end if;
end Test_Driver;
