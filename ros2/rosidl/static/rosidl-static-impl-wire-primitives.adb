pragma Validity_Checks (Off);
with Ada.Unchecked_Conversion;

package body ROSIDL.Static.Impl.Wire.Primitives is

   pragma Unsuppress (Index_Check);
   pragma Unsuppress (Length_Check);
   --  Writing relies on them (see ROSIDL.Static.Impl.Wire).

   subtype Raw is Stream_Element_Array (1 .. Size);
   function To_Raw is new Ada.Unchecked_Conversion (T, Raw);
   function From_Raw is new Ada.Unchecked_Conversion (Raw, T);

   procedure Reverse_Bytes (R : in out Raw) with Inline is
      Tmp : Stream_Element;
   begin
      for I in 1 .. Size / 2 loop
         Tmp := R (I);
         R (I) := R (Size + 1 - I);
         R (Size + 1 - I) := Tmp;
      end loop;
   end Reverse_Bytes;

   procedure Put (B : in out Stream_Element_Array; C : in out Cursor; V : T) is
      R : Raw := To_Raw (V);
   begin
      if Size > 1 then
         Pad (B, C, Size);
         if C.Swap then
            Reverse_Bytes (R);
         end if;
      end if;
      B (C.Pos .. C.Pos + Size - 1) := R;
      C.Pos := C.Pos + Size;
   end Put;

   procedure Truncated
     (B : Stream_Element_Array; C : Cursor; Needed : Long_Long_Integer; What : String)
     with No_Return is
   begin
      Fail (B, C.Pos, What, "truncated: needs" & Needed'Image & " bytes,"
            & Long_Long_Integer'Max (Remaining (B, C), 0)'Image & " remain");
   end Truncated;

   procedure Get (B : Stream_Element_Array; C : in out Cursor; V : out T; What : String) is
   begin
      if Size > 1 then
         Skip_Pad (C, Size);
      end if;
      if Remaining (B, C) < Long_Long_Integer (Size) then
         Truncated (B, C, Long_Long_Integer (Size), What);
      end if;
      declare
         R : Raw := B (C.Pos .. C.Pos + Size - 1);
      begin
         if Size > 1 and then C.Swap then
            Reverse_Bytes (R);
         end if;
         V := From_Raw (R);
      end;
      C.Pos := C.Pos + Size;
   end Get;

   procedure Put_Array (B : in out Stream_Element_Array; C : in out Cursor; Items : T_Array) is
      N : constant Stream_Element_Offset := Items'Length * Size;
   begin
      if Items'Length = 0 then
         return;
      end if;
      Pad (B, C, Size);
      if Size = 1 or else not C.Swap then
         declare
            Src : Stream_Element_Array (1 .. N) with Import, Address => Items'Address;
         begin
            B (C.Pos .. C.Pos + N - 1) := Src;
         end;
         C.Pos := C.Pos + N;
      else
         for V of Items loop
            declare
               R : Raw := To_Raw (V);
            begin
               Reverse_Bytes (R);
               B (C.Pos .. C.Pos + Size - 1) := R;
               C.Pos := C.Pos + Size;
            end;
         end loop;
      end if;
   end Put_Array;

   procedure Get_Array
     (B : Stream_Element_Array; C : in out Cursor; Items : out T_Array; What : String)
   is
      N : constant Stream_Element_Offset := Items'Length * Size;
   begin
      if Items'Length = 0 then
         return;
      end if;
      Skip_Pad (C, Size);
      if Remaining (B, C) < Long_Long_Integer (N) then
         Truncated (B, C, Long_Long_Integer (N), What);
      end if;
      if Size = 1 or else not C.Swap then
         declare
            Dst : Stream_Element_Array (1 .. N) with Import, Address => Items'Address;
         begin
            Dst := B (C.Pos .. C.Pos + N - 1);
         end;
         C.Pos := C.Pos + N;
      else
         for V of Items loop
            declare
               R : Raw := B (C.Pos .. C.Pos + Size - 1);
            begin
               Reverse_Bytes (R);
               V := From_Raw (R);
               C.Pos := C.Pos + Size;
            end;
         end loop;
      end if;
   end Get_Array;

end ROSIDL.Static.Impl.Wire.Primitives;
