--  Bounded sequences (ROS 2 "T[<=N]") of generated messages: at most
--  Capacity elements held in the record itself (no heap), indexed from 0.
--  Example:
--     use type ROSIDL.Float64;
--     package Joint_Sequences is new ROSIDL.Static.Bounded_Sequences
--       (ROSIDL.Float64, ROSIDL.Static.Float64_Array, Capacity => 6, Default => 0.0);
--     Joints : Joint_Sequences.Sequence := Joint_Sequences.To_Sequence ([1.0, 2.0]);
--     Joints.Items (1) := 2.5;     --  Items (0 .. Length - 1) are used
generic
   type Element_Type is private;
   type Element_Array is array (Natural range <>) of aliased Element_Type;
   Capacity : Positive;
   Default : Element_Type;
   with function "=" (Left, Right : Element_Type) return Boolean is <>;
package ROSIDL.Static.Bounded_Sequences is

   type Sequence is record
      Length : Natural range 0 .. Capacity := 0;
      Items  : Element_Array (0 .. Capacity - 1) := [others => Default];
   end record;

   overriding function "=" (Left, Right : Sequence) return Boolean;
   --  Same length and equal used elements.

   function To_Sequence (Items : Element_Array) return Sequence
     with Pre => Items'Length <= Capacity;

   function To_Array (S : Sequence) return Element_Array is
     (S.Items (0 .. S.Length - 1));

   procedure Append (S : in out Sequence; Item : Element_Type)
     with Pre => S.Length < Capacity;

end ROSIDL.Static.Bounded_Sequences;
