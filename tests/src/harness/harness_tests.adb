with AUnit.Assertions;
with Suite_Support; use Suite_Support;

package body Harness_Tests is

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
