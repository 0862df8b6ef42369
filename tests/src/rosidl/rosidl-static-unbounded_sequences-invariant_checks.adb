with Ada.Assertions;

package body ROSIDL.Static.Unbounded_Sequences.Invariant_Checks is

   --  S's storage becomes Sample (First .. First + 1) indexed from First,
   --  its length Length, with no check.
   procedure Replace_Storage (S : in out Sequence; First, Length : Natural) is
      Stored : constant Element_Array_Access :=
        new Element_Array'(First .. First + 1 => Default);
   begin
      Stored.all := Sample (Sample'First .. Sample'First + 1);
      S.Items := Stored;  --  (the old storage is left to the pool: a test)
      S.Length := Length;
   end Replace_Storage;

   function Unindexed_Storage_Refused return Boolean is
      S : Sequence;
   begin
      Replace_Storage (S, First => 5, Length => 2);
      S.Clear;
      return False;
   exception
      when Ada.Assertions.Assertion_Error =>
         return True;
   end Unindexed_Storage_Refused;

   function Length_Beyond_Storage_Refused return Boolean is
      S : Sequence;
   begin
      Replace_Storage (S, First => 0, Length => 3);
      S.Set_Length (3);
      return False;
   exception
      when Ada.Assertions.Assertion_Error =>
         return True;
   end Length_Beyond_Storage_Refused;

end ROSIDL.Static.Unbounded_Sequences.Invariant_Checks;
