--  Tests of RCL.Nodes with the DDS layer, in process: raw publish and
--  subscribe, message info, several nodes, callback exceptions, QoS
--  mismatch, timers driven by the executors, DDS errors as exceptions.
with AUnit.Test_Suites;

package RCL.Nodes.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Nodes.Tests;
