with Ada.Assertions;
with AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body Contract_Test_Support is

   procedure Assert_Caught (What : String) is
   begin
      Break_The_Rule;
      AUnit.Assertions.Assert (False, What & " went unnoticed");
   exception
      when Ada.Assertions.Assertion_Error =>
         null;
   end Assert_Caught;

   package body One_Test_Suite is

      type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

      package Caller is new AUnit.Test_Caller (Fixture);

      procedure Run_Test (Unused : in out Fixture) is
      begin
         Run;
      end Run_Test;

      function Suite return AUnit.Test_Suites.Access_Test_Suite is
         Result : constant AUnit.Test_Suites.Access_Test_Suite :=
           new AUnit.Test_Suites.Test_Suite;
      begin
         Result.Add_Test (Caller.Create (Name, Run_Test'Access));
         return Result;
      end Suite;

   end One_Test_Suite;

end Contract_Test_Support;
