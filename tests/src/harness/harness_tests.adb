with AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body Harness_Tests is

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   package Caller is new AUnit.Test_Caller (Fixture);

   procedure Assertions_Are_Enabled (Unused : in out Fixture) is
      Raised : Boolean := False;
   begin
      begin
         pragma Assert (False, "assertions are enabled");
      exception
         when others =>
            Raised := True;
      end;
      AUnit.Assertions.Assert
        (Raised, "pragma Assert must raise: build with -gnata");
   end Assertions_Are_Enabled;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test
        (Caller.Create ("harness: assertions are enabled",
                        Assertions_Are_Enabled'Access));
      return Result;
   end Suite;

end Harness_Tests;
