with AUnit.Assertions; use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;
with ROSIDL.Static.Unbounded_Sequences.Invariant_Checks;

package body ROSIDL.Static.Sequence_Contract_Tests is

   use type Int32;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;
   package Caller is new AUnit.Test_Caller (Fixture);

   package Int32_Sequences is new ROSIDL.Static.Unbounded_Sequences (Int32, Int32_Array, 0);
   package Checks is new Int32_Sequences.Invariant_Checks (Sample => Int32_Array'[7, 8]);

   procedure Invariant (Unused : in out Fixture) is
      use Int32_Sequences;
      S : Sequence := To_Sequence ([1, 2, 3]);
   begin
      S.Append (4);
      S.Set_Length (2);
      S.Set_Length (9);
      S.Clear;
      S.Append (5);
      Assert (S.Length = 1 and then S.Element (0) = 5, "operations keep the rule");

      Assert (Checks.Unindexed_Storage_Refused, "storage not indexed from 0 went unnoticed");
      Assert (Checks.Length_Beyond_Storage_Refused,
              "a length beyond the storage went unnoticed");
   end Invariant;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create
        ("static: unbounded sequence invariant (storage from 0, length within it)",
         Invariant'Access));
      return Result;
   end Suite;

end ROSIDL.Static.Sequence_Contract_Tests;
