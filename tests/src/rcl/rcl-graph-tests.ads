--  Tests of RCL.Graph queries (topic names, types and endpoint counts).
with AUnit.Test_Suites;

package RCL.Graph.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Graph.Tests;
