with Ada.Characters.Conversions;
with Ada.Characters.Handling;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with Interfaces;

package body ROSIDL.Dynamic.Images is

   use Ada.Strings.Fixed;
   use type Interfaces.Unsigned_64;
   use type Interfaces.Unsigned_32;
   use type Interfaces.Unsigned_8;
   use type Interfaces.IEEE_Float_64;

   package F64_IO is new Ada.Text_IO.Float_IO (Float64);

   function Trimmed (S : String) return String is (Trim (S, Ada.Strings.Both));

   function Spaces (N : Natural) return String is (Ada.Strings.Fixed."*" (N, ' '));

   function Finite_Image (X : Float64) return String is
      Buf  : String (1 .. 40);
      Text : Unbounded_String;
   begin
      if X = 0.0 then
         return "0.0";
      end if;
      for D in 1 .. 17 loop
         F64_IO.Put (Buf, X, Aft => D - 1, Exp => 3);
         exit when Float64'Value (Buf) = X;
      end loop;
      declare
         S        : constant String := Trimmed (Buf);
         E_Pos    : constant Natural := Index (S, "E");
         Exponent : constant Integer := Integer'Value (S (E_Pos + 1 .. S'Last));
         Negative : constant Boolean := S (S'First) = '-';
         Digits_S : Unbounded_String;
      begin
         for C of S (S'First .. E_Pos - 1) loop
            if C in '0' .. '9' then
               Append (Digits_S, C);
            end if;
         end loop;
         --  Strip trailing zeros (keep one digit).
         while Length (Digits_S) > 1
           and then Element (Digits_S, Length (Digits_S)) = '0'
         loop
            Delete (Digits_S, Length (Digits_S), Length (Digits_S));
         end loop;
         declare
            Dg : constant String := To_String (Digits_S);
         begin
            if Exponent >= -4 and then Exponent < 16 then
               if Exponent >= 0 then
                  if Dg'Length <= Exponent + 1 then
                     Text := To_Unbounded_String
                       (Dg & (Exponent + 1 - Dg'Length) * '0' & ".0");
                  else
                     Text := To_Unbounded_String
                       (Dg (Dg'First .. Dg'First + Exponent) & "."
                        & Dg (Dg'First + Exponent + 1 .. Dg'Last));
                  end if;
               else
                  Text := To_Unbounded_String
                    ("0." & (-Exponent - 1) * '0' & Dg);
               end if;
            else
               declare
                  Exp_Img : constant String := Trimmed (Integer'Image (abs Exponent));
               begin
                  Text := To_Unbounded_String
                    (Dg (Dg'First .. Dg'First)
                     & "." & (if Dg'Length > 1 then Dg (Dg'First + 1 .. Dg'Last)
                              else "0")
                     & "e" & (if Exponent < 0 then "-" else "+")
                     & (if Exp_Img'Length < 2 then "0" else "") & Exp_Img);
               end;
            end if;
            return (if Negative then "-" else "") & To_String (Text);
         end;
      end;
   end Finite_Image;

   function Bits_Image (Bits : Interfaces.Unsigned_64) return String is
      Exp  : constant Interfaces.Unsigned_64 :=
        Interfaces.Shift_Right (Bits, 52) and 16#7FF#;
      Frac : constant Interfaces.Unsigned_64 := Bits and (2**52 - 1);
      Neg  : constant Boolean := Interfaces.Shift_Right (Bits, 63) = 1;
   begin
      if Exp = 16#7FF# then
         return (if Frac /= 0 then ".nan" elsif Neg then "-.inf" else ".inf");
      elsif Exp = 0 and then Frac = 0 then
         return (if Neg then "-0.0" else "0.0");
      end if;
      declare
         V : Float64 with Import, Address => Bits'Address;
      begin
         return Finite_Image (V);
      end;
   end Bits_Image;

   function Float_Image (X : Float64) return String is
      Bits : Interfaces.Unsigned_64 with Import, Address => X'Address;
   begin
      return Bits_Image (Bits);
   end Float_Image;

   function Float32_Image (A : System.Address) return String is
      Bits : Interfaces.Unsigned_32 with Import, Address => A;
      Exp  : constant Interfaces.Unsigned_32 :=
        Interfaces.Shift_Right (Bits, 23) and 16#FF#;
      Frac : constant Interfaces.Unsigned_32 := Bits and (2**23 - 1);
      Neg  : constant Boolean := Interfaces.Shift_Right (Bits, 31) = 1;
   begin
      if Exp = 16#FF# then
         return (if Frac /= 0 then ".nan" elsif Neg then "-.inf" else ".inf");
      end if;
      declare
         V : Float32 with Import, Address => A;
      begin
         return Finite_Image (Float64 (V));
      end;
   end Float32_Image;

   function Float64_Image (A : System.Address) return String is
      Bits : Interfaces.Unsigned_64 with Import, Address => A;
   begin
      return Bits_Image (Bits);
   end Float64_Image;

   Hex : constant String := "0123456789abcdef";

   function Looks_Special (S : String) return Boolean is
      L : constant String := Ada.Characters.Handling.To_Lower (S);
   begin
      return L in "true" | "false" | "yes" | "no" | "on" | "off" | "y" | "n"
        | "null" | "~" | ".nan" | ".inf" | "-.inf" | "+.inf";
   end Looks_Special;

   function Is_Number (S : String) return Boolean is
      Seen_Digit : Boolean := False;
   begin
      for C of S loop
         case C is
            when '0' .. '9' => Seen_Digit := True;
            when '.' | '-' | '+' | 'e' | 'E' | '_' | 'x' | 'o' | 'b' => null;
            when others => return False;
         end case;
      end loop;
      return Seen_Digit;
   end Is_Number;

   function Yaml_String (S : String) return String is
      Printable : constant Boolean :=
        (for all C of S => C in ' ' .. '~');
   begin
      if not Printable then
         declare
            R : Unbounded_String := To_Unbounded_String ("""");
         begin
            for C of S loop
               case C is
                  when '"'  => Append (R, "\""");
                  when '\'  => Append (R, "\\");
                  when ASCII.NUL => Append (R, "\0");
                  when ASCII.HT => Append (R, "\t");
                  when ASCII.LF => Append (R, "\n");
                  when ASCII.CR => Append (R, "\r");
                  when ' ' .. '!' | '#' .. '[' | ']' .. '~' => Append (R, C);
                  when others =>
                     Append (R, "\x" & Hex (Character'Pos (C) / 16 + 1)
                             & Hex (Character'Pos (C) mod 16 + 1));
               end case;
            end loop;
            return To_String (R) & """";
         end;
      end if;
      if S = ""
        or else S (S'First) in ' ' | '-' | '?' | ':' | ',' | '[' | ']' | '{' | '}'
          | '#' | '&' | '*' | '!' | '|' | '>' | ''' | '"' | '%' | '@' | '`'
        or else S (S'Last) = ' ' or else S (S'Last) = ':'
        or else Index (S, ": ") > 0 or else Index (S, " #") > 0
        or else Looks_Special (S) or else Is_Number (S)
      then
         declare
            R : Unbounded_String := To_Unbounded_String ("'");
         begin
            for C of S loop
               Append (R, (if C = ''' then "''" else [C]));
            end loop;
            return To_String (R) & "'";
         end;
      end if;
      return S;
   end Yaml_String;

   function Int_Image (V : Long_Long_Integer) return String is
     (Trimmed (V'Image));

   function Primitive_Image
     (Cell : Field_Cell; Index : Positive) return String
   is
      A : constant System.Address := Element_Address (Cell, Index);
   begin
      case Primitive_Kind'(Cell_Type (Cell).Kind) is
         when Bool_Kind =>
            declare
               B : UInt8 with Import, Address => A;
            begin
               return (if B /= 0 then "true" else "false");
            end;
         when Byte_Kind =>
            declare
               B : UInt8 with Import, Address => A;
            begin
               return Yaml_String ([Character'Val (B)]);
            end;
         when Char_Kind | UInt8_Kind =>
            declare
               B : UInt8 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when Int8_Kind =>
            declare
               B : Int8 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when Int16_Kind =>
            declare
               B : Int16 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when UInt16_Kind =>
            declare
               B : UInt16 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when Int32_Kind =>
            declare
               B : Int32 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when UInt32_Kind =>
            declare
               B : UInt32 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when Int64_Kind =>
            declare
               B : Int64 with Import, Address => A;
            begin
               return Int_Image (Long_Long_Integer (B));
            end;
         when UInt64_Kind =>
            declare
               B : UInt64 with Import, Address => A;
            begin
               return Trimmed (B'Image);
            end;
         when Float32_Kind =>
            return Float32_Image (A);
         when Float64_Kind =>
            return Float64_Image (A);
      end case;
   end Primitive_Image;

   function Render (Root : not null Node_Access; Truncate : Natural) return String is
      Out_Text : Unbounded_String;

      function Cut (S : String) return String is
        (if Truncate > 0 and then S'Length > Truncate
         then S (S'First .. S'First + Truncate - 1) & "..." else S);

      function Scalar_Image (Cell : Field_Cell; Index : Positive) return String is
      begin
         case Cell_Type (Cell).Kind is
            when Primitive_Kind =>
               return Primitive_Image (Cell, Index);
            when String_Kind =>
               return Yaml_String (Cut (To_String (Cell.Texts (Index))));
            when WString_Kind =>
               return Yaml_String
                 (Cut (Ada.Characters.Conversions.To_String
                    (To_Wide_Wide_String (Cell.WTexts (Index)), '?')));
            when Message_Kind =>
               raise Program_Error;
         end case;
      end Scalar_Image;

      procedure Put_Fields (N : Node_Access; Indent : Natural; Lead : String);
      --  Lead replaces the indentation of the first line ("- " of a list).

      procedure Put_Fields (N : Node_Access; Indent : Natural; Lead : String) is
         First : Boolean := True;

         function Prefix return String is
         begin
            if First then
               First := False;
               return Lead;
            end if;
            return Spaces (Indent);
         end Prefix;
      begin
         for Cell of N.Cells loop
            declare
               T    : constant Field_Type := Cell_Type (Cell);
               Name : constant String := To_String (N.Def.Fields (Cell.Field).Name);
               P    : constant String := Prefix;
            begin
               if T.Collection = Single then
                  if T.Kind = Message_Kind then
                     Append (Out_Text, P & Name & ":" & ASCII.LF);
                     Put_Fields (Cell.Nodes (1), Indent + 2, Spaces (Indent + 2));
                  else
                     Append (Out_Text, P & Name & ": " & Scalar_Image (Cell, 1)
                             & ASCII.LF);
                  end if;
               elsif Cell.Count = 0 then
                  Append (Out_Text, P & Name & ": []" & ASCII.LF);
               else
                  Append (Out_Text, P & Name & ":" & ASCII.LF);
                  declare
                     Shown : constant Natural :=
                       (if Truncate > 0 then Natural'Min (Truncate, Cell.Count)
                        else Cell.Count);
                  begin
                     for I in 1 .. Shown loop
                        if T.Kind = Message_Kind then
                           Put_Fields (Cell.Nodes (I), Indent + 2,
                                       Spaces (Indent) & "- ");
                        else
                           Append (Out_Text, Spaces (Indent) & "- "
                                   & Scalar_Image (Cell, I) & ASCII.LF);
                        end if;
                     end loop;
                     if Shown < Cell.Count then
                        Append (Out_Text, Spaces (Indent) & "- '...'" & ASCII.LF);
                     end if;
                  end;
               end if;
            end;
         end loop;
      end Put_Fields;

   begin
      Put_Fields (Root, 0, "");
      return To_String (Out_Text);
   end Render;

end ROSIDL.Dynamic.Images;
