with Ada.Assertions;
with Ada.Strings.Unbounded;
with AUnit.Assertions;   use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body Sancta.Team.Goal_Trackers.Contract_Tests is

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   package Caller is new AUnit.Test_Caller (Fixture);

   procedure Invariant (Unused : in out Fixture) is
      T : Goal_Tracker;
      A : Action;
   begin
      A := T.Decide (True, (5.0, 0.0), "t1", (0.0, 0.0), 0.3);
      Assert (A = New_Goal and then T.Current = Going, "goal sent");
      A := T.Decide (False, (0.0, 0.0), "", (1.0, 0.0), 0.3);
      Assert (A = Go_Idle and then Ada.Strings.Unbounded.Length (T.Task_Id) = 0,
              "idle: the task is forgotten");

      T.Task_Id := Ada.Strings.Unbounded.To_Unbounded_String ("t1");
      begin
         A := T.Decide (False, (0.0, 0.0), "", (1.0, 0.0), 0.3);
         Assert (False, "an idle tracker holding a task went unnoticed");
      exception
         when Ada.Assertions.Assertion_Error =>
            null;
      end;
   end Invariant;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("team: goal tracker invariant (only a goer holds a task)",
                                      Invariant'Access));
      return Result;
   end Suite;

end Sancta.Team.Goal_Trackers.Contract_Tests;
