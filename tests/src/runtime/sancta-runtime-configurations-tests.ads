--  Tests of the configuration loader: the corpus of broken files under
--  tests/data/config (each names its expected diagnostic and position in
--  its first line), the paper's Listing 1.1 and the extensions (constants,
--  groups, includes, overrides).
with AUnit.Test_Suites;

package Sancta.Runtime.Configurations.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Runtime.Configurations.Tests;
