--  Tests of RCL.YAML (the YAML subset and its positioned errors),
--  RCL.YAML.Messages (dynamic messages from YAML) and RCL.Graph.Queries' pure
--  parts (name mangling, ros_discovery_info decoding).
with AUnit.Test_Suites;

package RCL.YAML.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.YAML.Tests;
