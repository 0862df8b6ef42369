--  Tests of RCL.Logging: the console format.
with AUnit.Test_Suites;

package RCL.Logging.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Logging.Tests;
