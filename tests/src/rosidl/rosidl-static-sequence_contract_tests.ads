--  The consistency rule of ROSIDL.Static.Unbounded_Sequences.Sequence (its
--  Type_Invariant): kept by the operations, an inconsistent sequence
--  refused.
with AUnit.Test_Suites;

package ROSIDL.Static.Sequence_Contract_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end ROSIDL.Static.Sequence_Contract_Tests;
