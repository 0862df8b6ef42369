pragma Validity_Checks (Off);
--  Floats may be NaN or infinite (ROS 2 data, definitions).
with Ada.Unchecked_Deallocation;

package body ROSIDL.Static.Unbounded_Sequences is

   procedure Free is new Ada.Unchecked_Deallocation (Element_Array, Element_Array_Access);

   procedure Reserve (S : in out Sequence; Capacity : Natural) is
   begin
      if Capacity > 0 and then (S.Items = null or else S.Items'Length < Capacity) then
         declare
            New_Capacity : constant Natural :=
              (if S.Items = null then Capacity
               else Natural'Max (Capacity, Natural'Min (2 * S.Items'Length, Natural'Last / 2)));
            Bigger : constant Element_Array_Access :=
              new Element_Array'(0 .. New_Capacity - 1 => Default);
         begin
            if S.Items /= null then
               Bigger (0 .. S.Length - 1) := S.Items (0 .. S.Length - 1);
               Free (S.Items);
            end if;
            S.Items := Bigger;
         end;
      end if;
   end Reserve;

   procedure Set_Length (S : in out Sequence; Length : Natural) is
   begin
      if Length > S.Length then
         if S.Items = null or else S.Items'Length < Length then
            if S.Length = 0 then
               --  Exactly what is asked (a decoded sequence, a first use).
               Free (S.Items);
               S.Items := new Element_Array'(0 .. Length - 1 => Default);
            else
               Reserve (S, Length);
            end if;
         end if;
         S.Items (S.Length .. Length - 1) := [others => Default];
      end if;
      S.Length := Length;
   end Set_Length;

   procedure Append (S : in out Sequence; Item : Element_Type) is
   begin
      Reserve (S, S.Length + 1);
      S.Items (S.Length) := Item;
      S.Length := S.Length + 1;
   end Append;

   procedure Clear (S : in out Sequence) is
   begin
      S.Length := 0;
   end Clear;

   function To_Sequence (Items : Element_Array) return Sequence is
   begin
      return S : Sequence do
         if Items'Length > 0 then
            S.Items := new Element_Array'(0 .. Items'Length - 1 => Default);
            S.Items.all := Items;
            S.Length := Items'Length;
         end if;
      end return;
   end To_Sequence;

   function To_Array (S : Sequence) return Element_Array is
   begin
      if S.Length = 0 then
         return Result : Element_Array (0 .. -1);
      end if;
      return S.Items (0 .. S.Length - 1);
   end To_Array;

   function Element (S : Sequence; Index : Natural) return Element_Type is (S.Items (Index));

   function Constant_Reference
     (S : aliased Sequence; Index : Natural) return Constant_Reference_Type is
     (Item => S.Items (Index)'Access);

   function Reference
     (S : aliased in out Sequence; Index : Natural) return Reference_Type is
     (Item => S.Items (Index)'Access);

   overriding function "=" (Left, Right : Sequence) return Boolean is
     (Left.Length = Right.Length
      and then (for all I in 0 .. Left.Length - 1 => Left.Items (I) = Right.Items (I)));
   --  The used elements, compared with the formal "=".

   overriding procedure Adjust (S : in out Sequence) is
   begin
      if S.Items /= null then
         if S.Length = 0 then
            S.Items := null;
         else
            S.Items := new Element_Array'(S.Items (0 .. S.Length - 1));
         end if;
      end if;
   end Adjust;

   overriding procedure Finalize (S : in out Sequence) is
   begin
      Free (S.Items);
      S.Length := 0;
   end Finalize;

end ROSIDL.Static.Unbounded_Sequences;
