--  The list of every AUnit suite of the repository (one line per area).
with AUnit.Test_Suites;

package All_Suites is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end All_Suites;
