--  Unbounded sequences (ROS 2 "T[]") of generated messages: a growable
--  array indexed from 0, with value semantics (assignment copies the
--  elements). Storage is kept when the length shrinks, so that decoding
--  into the same message again allocates only when a sequence grows
--  beyond what it held before.
--  Example:
--     Scan.Ranges.Set_Length (720);
--     Scan.Ranges (0) := 1.5;
--     Scan.Ranges.Append (2.0);            --  Length = 721
--     Put_Line (Scan.Ranges.Length'Image);
with Ada.Finalization;
with ROSIDL.Static.Storage;

generic
   type Element_Type is private;
   type Element_Array is array (Natural range <>) of aliased Element_Type;
   Default : Element_Type;
   --  The value of new elements (Set_Length, Append of a default).
   with function "=" (Left, Right : Element_Type) return Boolean is <>;
package ROSIDL.Static.Unbounded_Sequences is

   Message_Pool : ROSIDL.Static.Storage.Forwarding_Pool
     renames ROSIDL.Static.Storage.Message_Pool;

   type Sequence is new Ada.Finalization.Controlled with private
     with Constant_Indexing => Constant_Reference,
          Variable_Indexing => Reference;
   --  Its storage is indexed from 0 and holds its Length elements (a
   --  Type_Invariant; see Storage).

   Empty : constant Sequence;

   function Length (S : Sequence) return Natural;

   procedure Set_Length (S : in out Sequence; Length : Natural);
   --  New elements (beyond the old length) are Default.

   procedure Append (S : in out Sequence; Item : Element_Type);

   procedure Clear (S : in out Sequence);
   --  Length 0; the storage is kept.

   function To_Sequence (Items : Element_Array) return Sequence
     with Post => Length (To_Sequence'Result) = Items'Length;
   --  To_Sequence ([1.0, 2.0]): elements 0 and 1.

   function To_Array (S : Sequence) return Element_Array
     with Post => To_Array'Result'First = 0
                  and then To_Array'Result'Length = Length (S);

   function Element (S : Sequence; Index : Natural) return Element_Type
     with Pre => Index < Length (S);

   type Constant_Reference_Type (Item : not null access constant Element_Type) is
     null record with Implicit_Dereference => Item;
   type Reference_Type (Item : not null access Element_Type) is
     null record with Implicit_Dereference => Item;

   function Constant_Reference
     (S : aliased Sequence; Index : Natural) return Constant_Reference_Type
     with Pre => Index < Length (S);
   function Reference
     (S : aliased in out Sequence; Index : Natural) return Reference_Type
     with Pre => Index < Length (S);

   overriding function "=" (Left, Right : Sequence) return Boolean;
   --  Same length and equal elements (the storage kept does not count).

   --  For generated code (see ROSIDL.Static.Impl): elements 0 ..
   --  Length (S) - 1 of Storage (S).all are the sequence's; null when
   --  nothing was ever stored.
   type Element_Array_Access is access Element_Array
     with Storage_Pool => Message_Pool;
   --  From the pool the allocating task selected (ROSIDL.Static.Storage).
   function Storage (S : Sequence) return Element_Array_Access with Inline;

   overriding procedure Adjust (S : in out Sequence);
   overriding procedure Finalize (S : in out Sequence);

private

   type Sequence is new Ada.Finalization.Controlled with record
      Items  : Element_Array_Access;
      Length : Natural := 0;
   end record
     with Type_Invariant =>
       --  What Storage promises the generated codecs: the elements are
       --  Items (0 .. Length - 1).
       (if Sequence.Items = null then Sequence.Length = 0
        else Sequence.Items'First = 0 and then Sequence.Length <= Sequence.Items'Length);

   Empty : constant Sequence := (Ada.Finalization.Controlled with null, 0);

   function Length (S : Sequence) return Natural is (S.Length);
   function Storage (S : Sequence) return Element_Array_Access is (S.Items);

end ROSIDL.Static.Unbounded_Sequences;
