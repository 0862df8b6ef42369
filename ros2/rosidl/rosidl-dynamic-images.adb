with Ada.Strings.UTF_Encoding.Wide_Wide_Strings;
with Ada.Strings.Fixed;
with Ada.Numerics.Big_Numbers.Big_Integers;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Unchecked_Conversion;
with Interfaces;
with ROSIDL.YAML_Strings;

package body ROSIDL.Dynamic.Images is

   use Ada.Strings.Fixed;
   use ROSIDL.YAML_Strings;
   use type Interfaces.Unsigned_64;
   use type Interfaces.Unsigned_32;
   use type Interfaces.Unsigned_8;
   use type Interfaces.IEEE_Float_64;

   function To_Float is new Ada.Unchecked_Conversion (Interfaces.Unsigned_64, Float64);
   function To_Bits is new Ada.Unchecked_Conversion (Float64, Interfaces.Unsigned_64);

   function Trimmed (S : String) return String is (Trim (S, Ada.Strings.Both));

   function Spaces (N : Natural) return String is (Ada.Strings.Fixed."*" (N, ' '));

   --  The shortest decimal digits that read back as the float64 of Bits
   --  (finite, non-zero), and the decimal exponent of the first digit: what
   --  Python's repr prints. Exact arithmetic: X = M * 2**E, and a candidate
   --  Q * 10**J reads back as X when it lies inside X's rounding interval
   --  (boundaries included when M is even: round half to even).
   procedure Shortest_Digits
     (Bits : Interfaces.Unsigned_64; Digits_Out : out Unbounded_String;
      Exponent : out Integer)
   is
      use Ada.Numerics.Big_Numbers.Big_Integers;

      Biased   : constant Integer :=
        Integer (Interfaces.Shift_Right (Bits, 52) and 16#7FF#);
      package Conversions is new Unsigned_Conversions (Interfaces.Unsigned_64);
      Fraction : constant Big_Integer := Conversions.To_Big_Integer (Bits and (2**52 - 1));
      Two      : constant Big_Integer := 2;
      M        : constant Big_Integer :=
        (if Biased = 0 then Fraction else Fraction + Two ** 52);
      E        : constant Integer := (if Biased = 0 then Integer'(-1074) else Biased - 1075);
      Even     : constant Boolean := M mod 2 = 0;
      --  X, and the interval boundaries, times 4, in units of 2**(E - 2).
      P        : constant Integer := E - 2;
      X4       : constant Big_Integer := 4 * M;
      Hi4      : constant Big_Integer := 4 * M + 2;
      Lo4      : constant Big_Integer :=
        (if Fraction = 0 and then Biased > 1 then 4 * M - 1 else 4 * M - 2);
      Two_P    : constant Big_Integer := 2 ** Natural (abs P);

      --  Compares Q * 10**J with V4 * 2**P: -1, 0 or 1.
      function Compare (Q : Big_Integer; J : Integer; V4 : Big_Integer) return Integer
      is
         Left  : Big_Integer := Q;
         Right : Big_Integer := V4;
      begin
         if J >= 0 then
            Left := Left * 10 ** Natural (J);
         else
            Right := Right * 10 ** Natural (-J);
         end if;
         if P >= 0 then
            Right := Right * Two_P;
         else
            Left := Left * Two_P;
         end if;
         return (if Left < Right then -1 elsif Left > Right then 1 else 0);
      end Compare;

      Approx : constant Long_Float := Long_Float (To_Float (Bits));
      K      : Integer := Integer (Long_Float'Floor
        (Ada.Numerics.Long_Elementary_Functions.Log (abs Approx, 10.0)));
   begin
      --  10**K <= X < 10**(K + 1), exactly.
      while Compare (1, K, X4) > 0 loop
         K := K - 1;
      end loop;
      while Compare (1, K + 1, X4) <= 0 loop
         K := K + 1;
      end loop;
      for D in 1 .. 17 loop
         declare
            J : constant Integer := K - D + 1;
            A : Big_Integer := X4;
            B : Big_Integer := 1;
            Q : Big_Integer;
            Low, High : Integer;
         begin
            --  Q = round (X / 10**J) = round (A / B), half to even.
            if P >= 0 then
               A := A * Two_P;
            else
               B := B * Two_P;
            end if;
            if J >= 0 then
               B := B * 10 ** Natural (J);
            else
               A := A * 10 ** Natural (-J);
            end if;
            --  Half to even, as a correctly rounded conversion does.
            Q := A / B;
            if 2 * (A mod B) > B or else (2 * (A mod B) = B and then Q mod 2 = 1) then
               Q := Q + 1;
            end if;
            Low := Compare (Q, J, Lo4);
            High := Compare (Q, J, Hi4);
            if (Low > 0 or else (Even and then Low = 0))
              and then (High < 0 or else (Even and then High = 0))
            then
               declare
                  Image : constant String := To_String (Q);
                  Text  : constant String := Trimmed (Image);
               begin
                  --  Rounding may carry to D + 1 digits (9.99 -> 10.0).
                  Exponent := K + (Text'Length - D);
                  Digits_Out := To_Unbounded_String (Text);
                  while Length (Digits_Out) > 1
                    and then Element (Digits_Out, Length (Digits_Out)) = '0'
                  loop
                     Delete (Digits_Out, Length (Digits_Out), Length (Digits_Out));
                  end loop;
                  return;
               end;
            end if;
         end;
      end loop;
      raise Program_Error with "no 17-digit decimal reads back";
   end Shortest_Digits;

   function Finite_Image (Bits : Interfaces.Unsigned_64) return String is
      Text     : Unbounded_String;
      Digits_S : Unbounded_String;
      Exponent : Integer;
      Negative : constant Boolean := Interfaces.Shift_Right (Bits, 63) = 1;
   begin
      Shortest_Digits (Bits, Digits_S, Exponent);
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
      return Finite_Image (Bits);
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
         return Bits_Image (To_Bits (Float64 (V)));
      end;
   end Float32_Image;

   function Float64_Image (A : System.Address) return String is
      Bits : Interfaces.Unsigned_64 with Import, Address => A;
   begin
      return Bits_Image (Bits);
   end Float64_Image;

   --  PyYAML's implicit resolvers (YAML 1.1): a plain scalar that would
   --  read back as a bool, null, int, float, timestamp, merge or value key
   --  must be quoted.

   function Is_Digit (C : Character) return Boolean is (C in '0' .. '9');

   function Resolves_To_Bool (S : String) return Boolean is
     (S in "yes" | "Yes" | "YES" | "no" | "No" | "NO" | "true" | "True" | "TRUE"
         | "false" | "False" | "FALSE" | "on" | "On" | "ON" | "off" | "Off" | "OFF");

   function Resolves_To_Null (S : String) return Boolean is
     (S in "" | "~" | "null" | "Null" | "NULL");

   type Character_Test is access function (C : Character) return Boolean;

   --  Position after the run of characters of S from P on that satisfy OK.
   function Skip (S : String; P : Positive; OK : Character_Test) return Positive is
      Q : Positive := P;
   begin
      while Q <= S'Last and then OK (S (Q)) loop
         Q := Q + 1;
      end loop;
      return Q;
   end Skip;

   function Digit_Or_Underscore (C : Character) return Boolean is
     (C in '0' .. '9' | '_');
   function Binary (C : Character) return Boolean is (C in '0' | '1' | '_');
   function Octal (C : Character) return Boolean is (C in '0' .. '7' | '_');
   function Hexadecimal (C : Character) return Boolean is
     (C in '0' .. '9' | 'a' .. 'f' | 'A' .. 'F' | '_');

   --  (:[0-5]?[0-9])+ from P; returns the position after it, or P.
   function Sexagesimal (S : String; P : Positive) return Positive is
      Q : Positive := P;
   begin
      while Q < S'Last and then S (Q) = ':' and then Is_Digit (S (Q + 1)) loop
         if Q + 2 <= S'Last and then S (Q + 1) in '0' .. '5'
           and then Is_Digit (S (Q + 2))
         then
            Q := Q + 3;
         else
            Q := Q + 2;
         end if;
      end loop;
      return Q;
   end Sexagesimal;

   function Resolves_To_Int (S : String) return Boolean is
      P : Positive := S'First;
   begin
      if S'Length > 0 and then S (P) in '-' | '+' then
         P := P + 1;
      end if;
      if P > S'Last or else not Is_Digit (S (P)) then
         return False;
      end if;
      if S (P) = '0' then
         if P = S'Last then
            return True;
         elsif S (P + 1) = 'b' then
            return P + 2 <= S'Last and then Skip (S, P + 2, Binary'Access) > S'Last;
         elsif S (P + 1) = 'x' then
            return P + 2 <= S'Last
              and then Skip (S, P + 2, Hexadecimal'Access) > S'Last;
         else
            return Skip (S, P + 1, Octal'Access) > S'Last;
         end if;
      end if;
      P := Skip (S, P + 1, Digit_Or_Underscore'Access);
      return P > S'Last or else (S (P) = ':' and then Sexagesimal (S, P) > S'Last);
   end Resolves_To_Int;

   --  ([eE][-+][0-9]+)? then the end of S, from P.
   function Exponent_Then_End (S : String; P : Positive) return Boolean is
   begin
      if P > S'Last then
         return True;
      end if;
      return P + 2 <= S'Last and then S (P) in 'e' | 'E' and then S (P + 1) in '-' | '+'
        and then (for all C of S (P + 2 .. S'Last) => Is_Digit (C));
   end Exponent_Then_End;

   function Resolves_To_Float (S : String) return Boolean is
      P : Positive := S'First;
   begin
      if S in ".nan" | ".NaN" | ".NAN" then
         return True;
      end if;
      if S'Length > 1 and then S (P) = '.' and then Is_Digit (S (P + 1)) then
         return Exponent_Then_End (S, Skip (S, P + 1, Digit_Or_Underscore'Access));
      end if;
      if S'Length > 0 and then S (P) in '-' | '+' then
         P := P + 1;
      end if;
      if S (P .. S'Last) in ".inf" | ".Inf" | ".INF" then
         return True;
      end if;
      if P > S'Last or else not Is_Digit (S (P)) then
         return False;
      end if;
      P := Skip (S, P, Digit_Or_Underscore'Access);
      if P <= S'Last and then S (P) = ':' then
         P := Sexagesimal (S, P);
         return P <= S'Last and then S (P) = '.'
           and then Skip (S, P + 1, Digit_Or_Underscore'Access) > S'Last;
      end if;
      return P <= S'Last and then S (P) = '.'
        and then Exponent_Then_End (S, Skip (S, P + 1, Digit_Or_Underscore'Access));
   end Resolves_To_Float;

   function Resolves_To_Timestamp (S : String) return Boolean is
      --  yyyy-mm-dd exactly, or yyyy-m?m-d?d followed by a time (approximated
      --  as: then T, t, space or tab and some digit).
      P : Positive;
   begin
      if S'Length < 8 or else not (for all C of S (S'First .. S'First + 3) => Is_Digit (C))
        or else S (S'First + 4) /= '-'
      then
         return False;
      end if;
      if S'Length = 10 and then Is_Digit (S (S'First + 5))
        and then Is_Digit (S (S'First + 6)) and then S (S'First + 7) = '-'
        and then Is_Digit (S (S'First + 8)) and then Is_Digit (S (S'First + 9))
      then
         return True;
      end if;
      P := S'First + 5;
      for Part in 1 .. 2 loop
         if P > S'Last or else not Is_Digit (S (P)) then
            return False;
         end if;
         P := P + 1;
         if P <= S'Last and then Is_Digit (S (P)) then
            P := P + 1;
         end if;
         if Part = 1 then
            if P > S'Last or else S (P) /= '-' then
               return False;
            end if;
            P := P + 1;
         end if;
      end loop;
      return P < S'Last and then S (P) in 'T' | 't' | ' ' | ASCII.HT
        and then (for some C of S (P + 1 .. S'Last) => Is_Digit (C));
   end Resolves_To_Timestamp;

   function Resolves_Otherwise (S : String) return Boolean is
     (Resolves_To_Null (S) or else Resolves_To_Bool (S) or else Resolves_To_Int (S)
      or else Resolves_To_Float (S) or else Resolves_To_Timestamp (S)
      or else S = "<<" or else S = "=");

   function Yaml_String (S : String) return String is
      --  As PyYAML (allow_unicode, unbounded width, as ros2 topic echo uses)
      --  writes a string: plain when it can, single-quoted when a plain
      --  scalar would read back as something else or starts or ends with a
      --  space, double-quoted with escapes when it holds characters YAML
      --  cannot show as they are (Needs_Double_Quotes, Double_Quoted).

      function Followed_By_Space (I : Positive) return Boolean is
        (I = S'Last or else S (I + 1) in ' ' | ASCII.HT | ASCII.LF | ASCII.CR);

      Indicator : Boolean := False;
   begin
      if Needs_Double_Quotes (S) then
         return Double_Quoted (S);
      end if;
      for I in S'Range loop
         if I = S'First then
            Indicator := S (I) in '#' | ',' | '[' | ']' | '{' | '}' | '&' | '*' | '!'
              | '|' | '>' | ''' | '"' | '%' | '@' | '`'
              or else (S (I) in '?' | ':' | '-' and then Followed_By_Space (I));
         else
            Indicator := Indicator
              or else (S (I) = ':' and then Followed_By_Space (I))
              or else (S (I) = '#' and then S (I - 1) = ' ');
         end if;
      end loop;
      if Indicator or else Resolves_Otherwise (S)
        or else S (S'First) = ' ' or else S (S'Last) = ' '
        or else (S'Length >= 3 and then S (S'First .. S'First + 2) in "---" | "..."
                 and then Followed_By_Space (S'First + 2))
      then
         return Single_Quoted (S);
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
         when Byte_Kind | Char_Kind =>
            declare
               B : UInt8 with Import, Address => A;
            begin
               --  rclpy gives a byte as a 1-byte bytes object (turned into
               --  the character of that code by ros2 topic echo) and a char
               --  as a 1-character str: both show as that character.
               return Yaml_String
                 (Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Encode
                    ([Wide_Wide_Character'Val (B)]));
            end;
         when UInt8_Kind =>
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

      --  S (UTF-8) cut after Truncate characters, with "...", as ros2
      --  topic echo cuts the decoded text.
      function Cut (S : String) return String is
         Count : Natural := 0;
      begin
         if Truncate = 0 then
            return S;
         end if;
         for I in S'Range loop
            if S (I) not in Character'Val (16#80#) .. Character'Val (16#BF#) then
               --  The first byte of a character.
               if Count = Truncate then
                  return S (S'First .. I - 1) & "...";
               end if;
               Count := Count + 1;
            end if;
         end loop;
         return S;
      end Cut;

      function Scalar_Image (Cell : Field_Cell; Index : Positive) return String is
      begin
         case Cell_Type (Cell).Kind is
            when Primitive_Kind =>
               return Primitive_Image (Cell, Index);
            when String_Kind =>
               return Yaml_String (Cut (To_String (Cell.Extra.Texts (Index))));
            when WString_Kind =>
               declare
                  --  A wstring from the wire may hold code points UTF-8 cannot
                  --  encode (surrogates, beyond U+10FFFF): shown as U+FFFD.
                  W : Wide_Wide_String := To_Wide_Wide_String (Cell.Extra.WTexts (Index));
               begin
                  for C of W loop
                     if Wide_Wide_Character'Pos (C) in 16#D800# .. 16#DFFF#
                       or else Wide_Wide_Character'Pos (C) > 16#10_FFFF#
                     then
                        C := Wide_Wide_Character'Val (16#FFFD#);
                     end if;
                  end loop;
                  return Yaml_String
                    (Cut (Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Encode (W)));
               end;
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
                     Put_Fields (Cell.Extra.Nodes (1), Indent + 2, Spaces (Indent + 2));
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
                           Put_Fields (Cell.Extra.Nodes (I), Indent + 2,
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
