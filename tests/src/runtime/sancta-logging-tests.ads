--  Tests of the logging facility: per-section thresholds, counts, file.
with AUnit.Test_Suites;

package Sancta.Logging.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Logging.Tests;
