with Ada.Assertions;
with AUnit.Assertions;   use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body Sancta.Robot.GPS_Fusion.Contract_Tests is

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   package Caller is new AUnit.Test_Caller (Fixture);

   procedure Invariant (Unused : in out Fixture) is
      F : Filter;
   begin
      F.Initialize ((0.0, 0.0, 0.0), Variance => 0.5);
      for I in 1 .. 20 loop
         F.Predict ((Real (I), 0.0, 0.0));
         F.Correct ((Stamp => Real (I), Position => (Real (I) + 0.1, 0.05), Std_Dev => 0.3));
      end loop;
      Assert (Variance (F) in 0.0 .. 0.5, "variance kept in 0 .. its start:" & Variance (F)'Image);
      F.Correct ((Stamp => 21.0, Position => (20.0, 0.0), Std_Dev => 0.0));
      Assert (Variance (F) = 0.0, "an exact fix leaves no variance");

      F.Variance := -1.0;
      begin
         F.Predict ((21.0, 0.0, 0.0));
         Assert (False, "a negative variance went unnoticed");
      exception
         when Ada.Assertions.Assertion_Error =>
            null;
      end;

      F.Initialize ((0.0, 0.0, 0.0));
      F.Gain := 1.5;
      begin
         F.Correct ((Stamp => 1.0, Position => (0.0, 0.0), Std_Dev => 1.0));
         Assert (False, "a heading gain above 1 went unnoticed");
      exception
         when Ada.Assertions.Assertion_Error =>
            null;
      end;
   end Invariant;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("robot: GPS fusion invariant (variance >= 0, gain a share)",
                                      Invariant'Access));
      return Result;
   end Suite;

end Sancta.Robot.GPS_Fusion.Contract_Tests;
