--  Tests of RCL.Parameters: values from YAML, declaration with overrides,
--  validation (type, read-only, callback reasons), atomic sets, parameter
--  files and their errors.
with AUnit.Test_Suites;

package RCL.Parameters.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Parameters.Tests;
