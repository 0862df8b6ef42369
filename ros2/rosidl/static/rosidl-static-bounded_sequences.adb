pragma Validity_Checks (Off);
--  Floats may be NaN or infinite (ROS 2 data, definitions).
package body ROSIDL.Static.Bounded_Sequences is

   overriding function "=" (Left, Right : Sequence) return Boolean is
     (Left.Length = Right.Length
      and then (for all I in 0 .. Left.Length - 1 => Left.Items (I) = Right.Items (I)));
   --  The used elements, compared with the formal "=".

   function To_Sequence (Items : Element_Array) return Sequence is
   begin
      return S : Sequence do
         S.Length := Items'Length;
         S.Items (0 .. Items'Length - 1) := Items;
      end return;
   end To_Sequence;

   procedure Append (S : in out Sequence; Item : Element_Type) is
   begin
      S.Items (S.Length) := Item;
      S.Length := S.Length + 1;
   end Append;

end ROSIDL.Static.Bounded_Sequences;
