--  Test-only: sequences broken against their Type_Invariant (a generic
--  child sees the representation; the breaking is done in the body, where
--  no invariant check applies), then handed to an operation.
generic
   Sample : Element_Array;
   --  At least two elements.
package ROSIDL.Static.Unbounded_Sequences.Invariant_Checks is

   function Unindexed_Storage_Refused return Boolean;
   --  A sequence whose storage starts at index 5: Clear raises
   --  Assertion_Error.

   function Length_Beyond_Storage_Refused return Boolean;
   --  A sequence of length 3 over 2 stored elements: Set_Length (3), which
   --  changes nothing, raises Assertion_Error.

end ROSIDL.Static.Unbounded_Sequences.Invariant_Checks;
