with Ada.Directories;
with Ada.Text_IO;
with AUnit.Assertions;
with Suite_Support; use Suite_Support;

package body Sancta.Logging.Tests is

   use AUnit.Assertions;

   procedure Levels_And_File (Unused : in out Fixture) is
      Name   : constant String := "out/test/logging.txt";
      Before : Counts;
      F      : Ada.Text_IO.File_Type;
   begin
      Ada.Directories.Create_Path ("out/test");
      if Ada.Directories.Exists (Name) then
         Ada.Directories.Delete_File (Name);
      end if;
      Set_Console (False);
      Open_File (Name);
      Set_Level ("quiet", Error);
      Set_Level ("chatty", Debug);
      Before := Printed;
      Log ("quiet", Warning, "not printed");
      Log ("quiet", Error, "printed 1");
      Log ("chatty", Debug, "printed 2");
      Log ("other", Debug, "not printed either (default info)");
      Log ("other", Info, "printed 3");
      Close_File;
      Set_Console (True);
      Assert (Printed (Error) = Before (Error) + 1, "errors");
      Assert (Printed (Debug) = Before (Debug) + 1, "debug");
      Assert (Printed (Warning) = Before (Warning), "warnings filtered");
      Assert (Last_Message = "printed 3", Last_Message);
      Assert (Enabled ("chatty", Debug) and then not Enabled ("quiet", Warning), "Enabled");
      Ada.Text_IO.Open (F, Ada.Text_IO.In_File, Name);
      declare
         L1 : constant String := Ada.Text_IO.Get_Line (F);
         L2 : constant String := Ada.Text_IO.Get_Line (F);
         L3 : constant String := Ada.Text_IO.Get_Line (F);
      begin
         Assert (Ada.Text_IO.End_Of_File (F), "three lines");
         Ada.Text_IO.Close (F);
         Assert (Contains (L1, " ERROR [quiet] printed 1"), L1);
         Assert (Contains (L2, " DEBUG [chatty] printed 2"), L2);
         Assert (Contains (L3, " INFO  [other] printed 3"), L3);
      end;
   end Levels_And_File;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("sancta logging: sections, levels, file",
                                      Levels_And_File'Access));
      return Result;
   end Suite;

end Sancta.Logging.Tests;
