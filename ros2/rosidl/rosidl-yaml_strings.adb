with Ada.Strings.UTF_Encoding.Wide_Wide_Strings;
with Ada.Strings.Unbounded;

package body ROSIDL.YAML_Strings is

   use Ada.Strings.Unbounded;

   Hex : constant String := "0123456789ABCDEF";

   function Single_Quoted (Text : String) return String is
      R : Unbounded_String := To_Unbounded_String ("'");
   begin
      for C of Text loop
         Append (R, (if C = ''' then "''" else [C]));
      end loop;
      return To_String (R) & "'";
   end Single_Quoted;

   function Double_Quoted (Text : String) return String is
      subtype Code is Natural;
      R : Unbounded_String := To_Unbounded_String ("""");

      function Hex_Digits (C : Code; Width : Positive) return String is
         Result : String (1 .. Width);
         V      : Natural := C;
      begin
         for I in reverse Result'Range loop
            Result (I) := Hex (V mod 16 + 1);
            V := V / 16;
         end loop;
         return Result;
      end Hex_Digits;

      function Escape (C : Code) return String is
        (case C is
            when 16#00# => "0", when 16#07# => "a", when 16#08# => "b", when 16#09# => "t",
            when 16#0A# => "n", when 16#0B# => "v", when 16#0C# => "f", when 16#0D# => "r",
            when 16#1B# => "e", when 16#22# => """", when 16#5C# => "\", when 16#85# => "N",
            when 16#2028# => "L", when 16#2029# => "P",
            when others => "");
      --  PyYAML's named escapes.

      procedure Put (C : Code) is
      begin
         if Escape (C) /= "" then
            Append (R, "\" & Escape (C));
         elsif C in 16#20# .. 16#7E# then
            Append (R, Character'Val (C));
         elsif C in 16#A0# .. 16#D7FF# | 16#E000# .. 16#FEFE# | 16#FF00# .. 16#FFFD# then
            Append (R, Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Encode
                         ([Wide_Wide_Character'Val (C)]));
         elsif C <= 16#FF# then
            Append (R, "\x" & Hex_Digits (C, 2));
         elsif C <= 16#FFFF# then
            Append (R, "\u" & Hex_Digits (C, 4));
         else
            Append (R, "\U" & Hex_Digits (C, 8));
         end if;
      end Put;
   begin
      declare
         Decoded : constant Wide_Wide_String :=
           Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode (Text);
      begin
         for C of Decoded loop
            Put (Wide_Wide_Character'Pos (C));
         end loop;
      end;
      return To_String (R) & """";
   exception
      when Ada.Strings.UTF_Encoding.Encoding_Error =>
         R := To_Unbounded_String ("""");
         for C of Text loop
            Put (Character'Pos (C));
         end loop;
         return To_String (R) & """";
   end Double_Quoted;

   function Needs_Double_Quotes (Text : String) return Boolean is
   begin
      if (for some C of Text => C not in ' ' .. '~' | Character'Val (16#80#) .. Character'Last)
      then
         return True;
      elsif (for all C of Text => C in ' ' .. '~') then
         return False;
      end if;
      declare
         Decoded : constant Wide_Wide_String :=
           Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode (Text);
      begin
         return (for some C of Decoded =>
                   Wide_Wide_Character'Pos (C) not in 16#20# .. 16#7E# | 16#A0# .. 16#D7FF#
                     | 16#E000# .. 16#FEFE#
                     | 16#FF00# .. 16#FFFD# | 16#1_0000# .. 16#10_FFFE#
                   or else Wide_Wide_Character'Pos (C) in 16#2028# .. 16#2029#);
      end;
   exception
      when Ada.Strings.UTF_Encoding.Encoding_Error =>
         return True;
   end Needs_Double_Quotes;

end ROSIDL.YAML_Strings;
