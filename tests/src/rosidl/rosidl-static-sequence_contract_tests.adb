with AUnit.Assertions; use AUnit.Assertions;
with Contract_Test_Support;
with ROSIDL.Static.Unbounded_Sequences.Invariant_Checks;

package body ROSIDL.Static.Sequence_Contract_Tests is

   use type Int32;

   package Int32_Sequences is new ROSIDL.Static.Unbounded_Sequences (Int32, Int32_Array, 0);
   package Checks is new Int32_Sequences.Invariant_Checks (Sample => Int32_Array'[7, 8]);

   procedure Invariant is
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

   package Invariant_Test is new Contract_Test_Support.One_Test_Suite
     ("static: unbounded sequence invariant (storage from 0, length within it)", Invariant);

   function Suite return AUnit.Test_Suites.Access_Test_Suite renames Invariant_Test.Suite;

end ROSIDL.Static.Sequence_Contract_Tests;
