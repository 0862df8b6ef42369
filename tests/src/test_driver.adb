--  The one AUnit driver: runs every suite listed in All_Suites and sets the
--  exit status (non-zero when any test fails or raises).
--
--     bin/test_driver                 every test
--     bin/test_driver "scheduler:"    only the tests whose name starts so
--                                     (as the report prints them after OK)
--
--  Network rule: the suites create DDS participants. When the driver is run
--  by hand without scripts/env.sh, it still keeps them on loopback: an unset
--  CYCLONEDDS_URI is pointed at share/cyclonedds-localhost.xml (found from
--  the executable's folder) and an unset ROS_DOMAIN_ID gets one of this
--  process's own, before any participant exists.
with Ada.Command_Line;
with Ada.Directories;
with Ada.Environment_Variables;
with Ada.Text_IO;
with AUnit;
with AUnit.Reporter.Text;
with AUnit.Options;
with AUnit.Run;
with AUnit.Test_Filters;
with GNAT.OS_Lib;
with Interfaces.C;
with All_Suites;

procedure Test_Driver is

   --  A domain id in 1..200 that no other run on this machine holds: the
   --  driver keeps an flock on $TMPDIR/rclada-domain-locks/<id>.lock until
   --  it exits (scripts/env.sh and tests/interop/conftest.py take the same
   --  locks). Falls back to one drawn from the pid if no lock can be taken.
   function Free_Domain_Id return Positive is
      function C_Flock (Fd : Interfaces.C.int; Operation : Interfaces.C.int)
        return Interfaces.C.int with Import, Convention => C, External_Name => "flock";
      Lock_Exclusive : constant := 2;
      Lock_No_Wait   : constant := 4;
      use type Interfaces.C.int;
      use type GNAT.OS_Lib.File_Descriptor;
      Temp    : constant String :=
        (if Ada.Environment_Variables.Exists ("TMPDIR")
         then Ada.Environment_Variables.Value ("TMPDIR") else "/tmp");
      Folder  : constant String := Temp & "/rclada-domain-locks";
      Start   : constant Natural :=
        GNAT.OS_Lib.Pid_To_Integer (GNAT.OS_Lib.Current_Process_Id) mod 200;
   begin
      if not Ada.Directories.Exists (Folder) then
         begin
            Ada.Directories.Create_Directory (Folder);
         exception
            when others => null;  --  another run made it, or /tmp is read-only
         end;
      end if;
      for Step in 0 .. 199 loop
         declare
            Domain : constant Positive := (Start + Step) mod 200 + 1;
            Image  : constant String := Positive'Image (Domain);
            Path   : constant String :=
              Folder & "/" & Image (Image'First + 1 .. Image'Last) & ".lock";
            Fd     : GNAT.OS_Lib.File_Descriptor :=
              GNAT.OS_Lib.Open_Append (Path, GNAT.OS_Lib.Binary);
         begin
            if Fd = GNAT.OS_Lib.Invalid_FD then
               Fd := GNAT.OS_Lib.Create_File (Path, GNAT.OS_Lib.Binary);
            end if;
            if Fd /= GNAT.OS_Lib.Invalid_FD then
               if C_Flock (Interfaces.C.int (Fd), Lock_Exclusive + Lock_No_Wait) = 0 then
                  return Domain;  --  the descriptor stays open: the lock lives with us
               end if;
               GNAT.OS_Lib.Close (Fd);
            end if;
         end;
      end loop;
      return Start + 1;
   end Free_Domain_Id;

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
            Id : constant String := Integer'Image (Free_Domain_Id);
         begin
            Env.Set ("ROS_DOMAIN_ID", Id (Id'First + 1 .. Id'Last));
         end;
      end if;
   end Keep_DDS_On_Loopback;

   function Run is new AUnit.Run.Test_Runner_With_Status (All_Suites.Suite);
   Reporter : AUnit.Reporter.Text.Text_Reporter;
   Filter   : aliased AUnit.Test_Filters.Name_Filter;
   Options  : AUnit.Options.AUnit_Options := AUnit.Options.Default_Options;
   use type AUnit.Status;
begin
   Keep_DDS_On_Loopback;
   if Ada.Command_Line.Argument_Count > 1 then
      Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error,
                            "usage: test_driver [start of the test names to run]");
      Ada.Text_IO.Flush (Ada.Text_IO.Standard_Error);
      GNAT.OS_Lib.OS_Exit (2);
   elsif Ada.Command_Line.Argument_Count = 1 then
      Filter.Set_Name (Ada.Command_Line.Argument (1));
      Options.Filter := Filter'Unchecked_Access;
   end if;
   declare
      Passed : constant Boolean := Run (Reporter, Options) = AUnit.Success;
   begin
      --  Ends the process here: a test that failed before stopping the
      --  tasks it started (team agents, executors) would otherwise keep the
      --  driver alive after its report, until CI's timeout.
      Ada.Text_IO.Flush (Ada.Text_IO.Standard_Output);
      Ada.Text_IO.Flush (Ada.Text_IO.Standard_Error);
      GNAT.OS_Lib.OS_Exit (if Passed then 0 else 1);
   end;
end Test_Driver;
