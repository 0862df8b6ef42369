--  What the contract tests share: each is one AUnit test that keeps a type's
--  rule through normal use and then breaks it on purpose (as only a bug in
--  the package could), expecting the contract -- a Type_Invariant, Pre or
--  Post -- to raise Ada.Assertions.Assertion_Error.
--
--     procedure Negative_Variance is begin F.Variance := -1.0; F.Predict (P); end;
--     procedure Check is new Assert_Caught (Negative_Variance);
--     ...  Check ("a negative variance");
--     package Invariant_Test is new One_Test_Suite ("robot: ...", Invariant);
with AUnit.Test_Suites;

package Contract_Test_Support is

   generic
      with procedure Break_The_Rule;
   procedure Assert_Caught (What : String);
   --  Runs Break_The_Rule; the test fails with "WHAT went unnoticed" unless
   --  it raises Ada.Assertions.Assertion_Error.

   generic
      Name : String;
      with procedure Run;
   package One_Test_Suite is
      function Suite return AUnit.Test_Suites.Access_Test_Suite;
      --  A suite of one test, Name, that calls Run.
   end One_Test_Suite;

end Contract_Test_Support;
