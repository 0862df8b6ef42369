with Harness_Tests;
with Sancta.Allocation.Tests;

package body All_Suites is

   use AUnit.Test_Suites;

   Result : aliased Test_Suite;

   function Suite return Access_Test_Suite is
   begin
      Result.Add_Test (Harness_Tests.Suite);
      Result.Add_Test (Sancta.Allocation.Tests.Suite);
      --  Each area adds its suite here, e.g.
      --  Result.Add_Test (ROSIDL.CDR.Tests.Suite);
      return Result'Access;
   end Suite;

end All_Suites;
