--  For generated code (ROSIDL.Static.Impl): the XCDR1 codec of one
--  primitive type (numbers; bool is ROSIDL.Static.Impl.Codecs.Bool_Codec),
--  single values and arrays. Arrays are copied in one block when the wire's
--  byte order is the machine's.
generic
   type T is private;
   type T_Array is array (Natural range <>) of T;
package ROSIDL.Static.Impl.Wire.Primitives is

   Size : constant Stream_Element_Offset := T'Size / Stream_Element'Size;

   procedure Put (B : in out Stream_Element_Array; C : in out Cursor; V : T) with Inline;
   procedure Get (B : Stream_Element_Array; C : in out Cursor; V : out T; What : String)
     with Inline;
   procedure Put_Array (B : in out Stream_Element_Array; C : in out Cursor; Items : T_Array);
   procedure Get_Array
     (B : Stream_Element_Array; C : in out Cursor; Items : out T_Array; What : String);
   --  Items'Length elements (a fixed array, or a sequence after its count).

end ROSIDL.Static.Impl.Wire.Primitives;
