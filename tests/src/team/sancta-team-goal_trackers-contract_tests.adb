with Ada.Strings.Unbounded;
with AUnit.Assertions;   use AUnit.Assertions;
with Contract_Test_Support;

package body Sancta.Team.Goal_Trackers.Contract_Tests is

   procedure Invariant is
      T : Goal_Tracker;
      A : Action;

      procedure Decide_Idle_Holding_A_Task is
      begin
         T.Task_Id := Ada.Strings.Unbounded.To_Unbounded_String ("t1");
         A := T.Decide (False, (0.0, 0.0), "", (1.0, 0.0), 0.3);
      end Decide_Idle_Holding_A_Task;

      procedure Idle_Holding_A_Task is new
        Contract_Test_Support.Assert_Caught (Decide_Idle_Holding_A_Task);
   begin
      A := T.Decide (True, (5.0, 0.0), "t1", (0.0, 0.0), 0.3);
      Assert (A = New_Goal and then T.Current = Going, "goal sent");
      A := T.Decide (False, (0.0, 0.0), "", (1.0, 0.0), 0.3);
      Assert (A = Go_Idle and then Ada.Strings.Unbounded.Length (T.Task_Id) = 0,
              "idle: the task is forgotten");

      Idle_Holding_A_Task ("an idle tracker holding a task");
   end Invariant;

   package Invariant_Test is new Contract_Test_Support.One_Test_Suite
     ("team: goal tracker invariant (only a goer holds a task)", Invariant);

   function Suite return AUnit.Test_Suites.Access_Test_Suite renames Invariant_Test.Suite;

end Sancta.Team.Goal_Trackers.Contract_Tests;
