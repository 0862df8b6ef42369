--  Tests of dynamic messages: field access, defaults and constants, nested
--  references, arrays and their limits, matrix views, bulk access, copies,
--  error texts and the ros2 topic echo image.
--  (Not a child of ROSIDL.Dynamic: GNAT 12 ignores the indexing aspects of
--  Message where its full view is visible.)
with AUnit.Test_Suites;

package ROSIDL.Dynamic_Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end ROSIDL.Dynamic_Tests;
