pragma Validity_Checks (Off);
--  Floats may be NaN or infinite (ROS 2 data, definitions).
package body ROSIDL.Static.Impl.Codecs is

   pragma Unsuppress (Index_Check);
   pragma Unsuppress (Length_Check);
   --  Writing relies on them (see ROSIDL.Static.Impl.Wire).

   use type Ada.Streams.Stream_Element_Offset;
   use type Ada.Streams.Stream_Element;

   package body Bool_Codec is

      procedure Put (B : in out Bytes; C : in out Wire.Cursor; V : Boolean) is
      begin
         B (C.Pos) := (if V then 1 else 0);
         C.Pos := C.Pos + 1;
      end Put;

      procedure Get
        (B : Bytes; C : in out Wire.Cursor; V : out Boolean; What : String) is
      begin
         if C.Pos > B'Last then
            Wire.Fail (B, C.Pos, What, "truncated: needs 1 bytes, 0 remain");
         end if;
         V := B (C.Pos) /= 0;
         C.Pos := C.Pos + 1;
      end Get;

      procedure Put_Array
        (B : in out Bytes; C : in out Wire.Cursor; Items : Bool_Array) is
      begin
         for V of Items loop
            Put (B, C, V);
         end loop;
      end Put_Array;

      procedure Get_Array
        (B : Bytes; C : in out Wire.Cursor; Items : out Bool_Array; What : String) is
      begin
         if Wire.Remaining (B, C) < Long_Long_Integer (Items'Length) then
            Wire.Fail (B, C.Pos, What, "truncated: needs" & Items'Length'Image & " bytes,"
                  & Long_Long_Integer'Max (Wire.Remaining (B, C), 0)'Image & " remain");
         end if;
         for V of Items loop
            V := B (C.Pos) /= 0;
            C.Pos := C.Pos + 1;
         end loop;
      end Get_Array;

   end Bool_Codec;

end ROSIDL.Static.Impl.Codecs;
