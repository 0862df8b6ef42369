pragma Validity_Checks (Off);
with Ada.Unchecked_Conversion;
pragma Warnings (Off, "*internal GNAT unit*");
pragma Warnings (Off, "*non-portable and version-dependent*");
with Ada.Strings.Unbounded.Aux;
--  Get_String: the characters of an Unbounded_String in place (GNAT's
--  documented access for layered utilities; To_String would copy them to
--  the secondary stack on every message).
pragma Warnings (On, "*internal GNAT unit*");
pragma Warnings (On, "*non-portable and version-dependent*");
with Interfaces;
with System;
with ROSIDL.Wide_Text_Builders;

package body ROSIDL.Static.Impl.Wire is

   pragma Unsuppress (Index_Check);
   pragma Unsuppress (Length_Check);
   --  The writing procedures rely on them: a buffer too small stops the
   --  write pass at its end (Constraint_Error), never past it.

   use Interfaces;
   use type System.Bit_Order;

   Little : constant Boolean := System.Default_Bit_Order = System.Low_Order_First;

   function To_UInt64 is new Ada.Unchecked_Conversion (Int64, Unsigned_64);

   function Offset_Image (N : Stream_Element_Offset) return String is
      Img : constant String := N'Image;
   begin
      return Img (Img'First + 1 .. Img'Last);
   end Offset_Image;

   procedure Add (Pos : in out Stream_Element_Offset; Align, Bytes : Stream_Element_Offset) is
   begin
      Pos := Pos + (-Pos) mod Align + Bytes;
   end Add;

   procedure Add_String (Pos : in out Stream_Element_Offset; Length : Natural) is
   begin
      Add (Pos, 4, 5 + Stream_Element_Offset (Length));
   end Add_String;

   procedure Add_WString (Pos : in out Stream_Element_Offset; Length : Natural) is
   begin
      Add (Pos, 4, 4 + 4 * Stream_Element_Offset (Length));
   end Add_WString;

   procedure Pad (B : in out Stream_Element_Array; C : in out Cursor;
                  Align : Stream_Element_Offset) is
      N : constant Stream_Element_Offset := (C.Origin - C.Pos) mod Align;
   begin
      for I in 0 .. N - 1 loop
         B (C.Pos + I) := 0;
      end loop;
      C.Pos := C.Pos + N;
   end Pad;

   function Byte_Swap (V : Unsigned_32) return Unsigned_32 is
     (Shift_Left (V, 24) or Shift_Left (V and 16#FF00#, 8)
      or Shift_Right (V and 16#FF_0000#, 8) or Shift_Right (V, 24))
     with Inline;

   subtype Raw_U32 is Stream_Element_Array (1 .. 4);
   function To_Raw is new Ada.Unchecked_Conversion (Unsigned_32, Raw_U32);

   procedure Put_U32 (B : in out Stream_Element_Array; C : in out Cursor; V : Unsigned_32)
     with Inline
   is
   begin
      Pad (B, C, 4);
      B (C.Pos .. C.Pos + 3) := To_Raw (if C.Swap then Byte_Swap (V) else V);
      C.Pos := C.Pos + 4;
   end Put_U32;

   procedure Put_Count (B : in out Stream_Element_Array; C : in out Cursor; Count : Natural) is
   begin
      Put_U32 (B, C, Unsigned_32 (Count));
   end Put_Count;

   procedure Put_Characters
     (B : in out Stream_Element_Array; C : in out Cursor; Text : String) with Inline is
      N : constant Stream_Element_Offset := Text'Length;
   begin
      Put_U32 (B, C, Unsigned_32 (Text'Length + 1));
      if N > 0 then
         declare
            Src : Stream_Element_Array (1 .. N) with Import, Address => Text'Address;
         begin
            B (C.Pos .. C.Pos + N - 1) := Src;
         end;
      end if;
      B (C.Pos + N) := 0;
      C.Pos := C.Pos + N + 1;
   end Put_Characters;

   procedure Put_String (B : in out Stream_Element_Array; C : in out Cursor; Text : String) is
   begin
      Put_Characters (B, C, Text);
   end Put_String;

   procedure Put_String
     (B    : in out Stream_Element_Array;
      C    : in out Cursor;
      Text : Ada.Strings.Unbounded.Unbounded_String)
   is
      Chars  : Ada.Strings.Unbounded.Aux.Big_String_Access;
      Length : Natural;
   begin
      Ada.Strings.Unbounded.Aux.Get_String (Text, Chars, Length);
      Put_Characters (B, C, Chars (1 .. Length));
   end Put_String;

   procedure Put_WString
     (B : in out Stream_Element_Array; C : in out Cursor; Text : Wide_Wide_String) is
   begin
      Put_U32 (B, C, Unsigned_32 (Text'Length));
      for Ch of Text loop
         Put_U32 (B, C, Wide_Wide_Character'Pos (Ch));
      end loop;
   end Put_WString;

   procedure Fail (B : Stream_Element_Array; At_Pos : Stream_Element_Offset; What, Problem : String)
   is
   begin
      raise Decode_Error with What & ": " & Problem & " at byte offset "
        & Offset_Image (At_Pos - B'First);
   end Fail;

   procedure Skip_Pad (C : in out Cursor; Align : Stream_Element_Offset) is
   begin
      C.Pos := C.Pos + (C.Origin - C.Pos) mod Align;
   end Skip_Pad;

   procedure Get_U32
     (B : Stream_Element_Array; C : in out Cursor; V : out Unsigned_32; What : String)
   is
      Wire_Little : constant Boolean := Little /= C.Swap;
   begin
      Skip_Pad (C, 4);
      if Remaining (B, C) < 4 then
         Fail (B, C.Pos, What, "truncated: needs 4 bytes,"
               & Long_Long_Integer'Max (Remaining (B, C), 0)'Image & " remain");
      end if;
      V := 0;
      for I in 0 .. 3 loop
         V := V or Shift_Left
           (Unsigned_32 (B (C.Pos + (if Wire_Little then Stream_Element_Offset (I)
                                     else Stream_Element_Offset (3 - I)))), 8 * I);
      end loop;
      C.Pos := C.Pos + 4;
   end Get_U32;

   function Get_Count
     (B        : Stream_Element_Array;
      C        : in out Cursor;
      Min_Size : Positive;
      Bound    : Natural;
      What     : String) return Natural
   is
      Wire : Unsigned_32;
   begin
      Get_U32 (B, C, Wire, What & " (sequence count)");
      if Bound > 0 and then Wire > Unsigned_32 (Bound) then
         Fail (B, C.Pos - 4, What, "sequence count" & Wire'Image
               & " exceeds the bound" & Bound'Image);
      end if;
      if Long_Long_Integer (Wire) * Long_Long_Integer (Min_Size)
        > Long_Long_Integer'Max (Remaining (B, C), 0)
      then
         Fail (B, C.Pos - 4, What, "sequence count" & Wire'Image & " cannot fit in the"
               & Long_Long_Integer'Max (Remaining (B, C), 0)'Image & " remaining bytes");
      end if;
      return Natural (Wire);
   end Get_Count;

   function Get_String_Span
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      What  : String) return String_Span
   is
      L : Unsigned_32;
   begin
      Get_U32 (B, C, L, What & " (string length)");
      if L = 0 then
         Fail (B, C.Pos - 4, What, "string length 0 (no room for its NUL)");
      end if;
      if Long_Long_Integer (L) > Remaining (B, C) then
         Fail (B, C.Pos - 4, What, "string length" & L'Image & " exceeds the"
               & Long_Long_Integer'Max (Remaining (B, C), 0)'Image & " remaining bytes");
      end if;
      if Bound > 0 and then L - 1 > Unsigned_32 (Bound) then
         Fail (B, C.Pos - 4, What, "string of" & Unsigned_32'Image (L - 1)
               & " characters exceeds its bound" & Bound'Image);
      end if;
      return Span : constant String_Span := (First => C.Pos, Length => Natural (L) - 1) do
         if B (Span.First + Stream_Element_Offset (Span.Length)) /= 0 then
            Fail (B, Span.First + Stream_Element_Offset (Span.Length), What,
                  "string not terminated by a NUL");
         end if;
         C.Pos := C.Pos + Stream_Element_Offset (L);
      end return;
   end Get_String_Span;

   function Text (B : Stream_Element_Array; Span : String_Span) return String is
      Result : String (1 .. Span.Length) with Import, Address => B (Span.First)'Address;
   begin
      return Result;
   end Text;

   procedure Get_String
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      Into  : in out Ada.Strings.Unbounded.Unbounded_String;
      What  : String)
   is
      Span : constant String_Span := Get_String_Span (B, C, Bound, What);
   begin
      if Span.Length = 0 then
         Ada.Strings.Unbounded.Set_Unbounded_String (Into, "");
      else
         declare
            Chars : String (1 .. Span.Length) with Import, Address => B (Span.First)'Address;
         begin
            Ada.Strings.Unbounded.Set_Unbounded_String (Into, Chars);
         end;
      end if;
   end Get_String;

   procedure Get_WString
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      Into  : out Ada.Strings.Wide_Wide_Unbounded.Unbounded_Wide_Wide_String;
      What  : String)
   is
      L    : Unsigned_32;
      Text : Wide_Text_Builders.Builder;
   begin
      Get_U32 (B, C, L, What & " (wstring length)");
      if Long_Long_Integer (L) * 4 > Remaining (B, C) then
         Fail (B, C.Pos - 4, What, "wstring length" & L'Image & " exceeds the"
               & Long_Long_Integer'Max (Remaining (B, C), 0)'Image & " remaining bytes");
      end if;
      if Bound > 0 and then L > Unsigned_32 (Bound) then
         Fail (B, C.Pos - 4, What, "wstring of" & L'Image
               & " characters exceeds its bound" & Bound'Image);
      end if;
      for Unused in 1 .. L loop
         declare
            Code : Unsigned_32;
         begin
            Get_U32 (B, C, Code, What);
            if Code > 16#7FFF_FFFF# then
               Fail (B, C.Pos - 4, What, "wstring character" & Code'Image & " out of range");
            end if;
            Wide_Text_Builders.Append (Text, Wide_Wide_Character'Val (Code));
         end;
      end loop;
      Wide_Text_Builders.Take (Text, Into);
   end Get_WString;

   function Get_WString
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      What  : String) return Wide_Wide_String
   is
      Result : Ada.Strings.Wide_Wide_Unbounded.Unbounded_Wide_Wide_String;
   begin
      Get_WString (B, C, Bound, Result, What);
      return Ada.Strings.Wide_Wide_Unbounded.To_Wide_Wide_String (Result);
   end Get_WString;

   procedure Put_Request_Header
     (B : in out Stream_Element_Array; C : in out Cursor; GUID : UInt64; Sequence : Int64)
   is
      Wire_Little : constant Boolean := Little /= C.Swap;
      procedure Put_U64 (V : Unsigned_64) is
      begin
         for I in 0 .. 7 loop
            B (C.Pos + (if Wire_Little then Stream_Element_Offset (I)
                        else Stream_Element_Offset (7 - I))) :=
              Stream_Element (Shift_Right (V, 8 * I) and 16#FF#);
         end loop;
         C.Pos := C.Pos + 8;
      end Put_U64;
   begin
      Put_U64 (GUID);
      Put_U64 (To_UInt64 (Sequence));
   end Put_Request_Header;

end ROSIDL.Static.Impl.Wire;
