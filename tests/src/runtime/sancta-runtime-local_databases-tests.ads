--  Tests of the local database: typed values, concurrent writers and
--  listeners (nothing lost), atomic Update, recursion detection, failing
--  listeners.
with AUnit.Test_Suites;

package Sancta.Runtime.Local_Databases.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Runtime.Local_Databases.Tests;
