--  Tests of RCL.Names: node name / namespace validation, topic expansion.
with AUnit.Test_Suites;

package RCL.Names.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Names.Tests;
