with Ada.Characters.Handling;
with Ada.Strings.UTF_Encoding.Wide_Wide_Strings;
with Interfaces;

package body ROSIDL.Parser.Literals is

   use Ada.Characters.Handling;
   use type Interfaces.Unsigned_64;

   subtype U64 is Interfaces.Unsigned_64;

   function Trim_Blanks (S : String) return String is
      First : Positive := S'First;
      Last  : Natural := S'Last;
   begin
      while First <= Last and then Is_Blank (S (First)) loop
         First := First + 1;
      end loop;
      while Last >= First and then Is_Blank (S (Last)) loop
         Last := Last - 1;
      end loop;
      return S (First .. Last);
   end Trim_Blanks;

   function Failure (Expected : String) return Check_Result is
     ((OK => False, Value => Null_Unbounded_String,
       Expected => To_Unbounded_String (Expected)));

   function Success (Value : String) return Check_Result is
     ((OK => True, Value => To_Unbounded_String (Value),
       Expected => Null_Unbounded_String));

   function Image (V : U64) return String is
      S : constant String := V'Image;
   begin
      return S (S'First + 1 .. S'Last);
   end Image;

   ---------------------------------------------------------------------------
   --  Digits with single underscores between them, as Python reads numbers.

   function Digit_Value (C : Character) return Natural is
     (case C is
         when '0' .. '9' => Character'Pos (C) - Character'Pos ('0'),
         when 'a' .. 'f' => Character'Pos (C) - Character'Pos ('a') + 10,
         when 'A' .. 'F' => Character'Pos (C) - Character'Pos ('A') + 10,
         when others     => Natural'Last);

   procedure Read_Digits
     (S         : String;
      Base      : Positive;
      Allow_Lead_Underscore : Boolean;
      Magnitude : out U64;
      Overflow  : out Boolean;
      OK        : out Boolean)
   --  S is a run of digits of Base with single underscores between digits
   --  (and one before the first digit when Allow_Lead_Underscore, as after
   --  a 0x prefix).
   is
      Previous_Underscore : Boolean := not Allow_Lead_Underscore;
      Count               : Natural := 0;
   begin
      Magnitude := 0;
      Overflow := False;
      OK := False;
      if S'Length = 0 then
         return;
      end if;
      for I in S'Range loop
         if S (I) = '_' then
            if Previous_Underscore then
               return;
            end if;
            Previous_Underscore := True;
         elsif Digit_Value (S (I)) < Base then
            Previous_Underscore := False;
            Count := Count + 1;
            declare
               D : constant U64 := U64 (Digit_Value (S (I)));
            begin
               if Magnitude > (U64'Last - D) / U64 (Base) then
                  Overflow := True;
               else
                  Magnitude := Magnitude * U64 (Base) + D;
               end if;
            end;
         else
            return;
         end if;
      end loop;
      OK := Count > 0 and then not Previous_Underscore;
   end Read_Digits;

   ---------------------------------------------------------------------------

   procedure Read_Integer
     (Text      : String;
      Negative  : out Boolean;
      Magnitude : out U64;
      Overflow  : out Boolean;
      OK        : out Boolean)
   is
      First : Positive := Text'First;
   begin
      Negative := False;
      Magnitude := 0;
      Overflow := False;
      OK := False;
      if Text'Length = 0 then
         return;
      end if;
      if Text (First) in '+' | '-' then
         Negative := Text (First) = '-';
         First := First + 1;
      end if;
      if First + 1 <= Text'Last
        and then Text (First) = '0'
        and then To_Lower (Text (First + 1)) in 'x' | 'o' | 'b'
      then
         Read_Digits
           (Text (First + 2 .. Text'Last),
            Base =>
              (case To_Lower (Text (First + 1)) is
                  when 'x'    => 16,
                  when 'o'    => 8,
                  when others => 2),
            Allow_Lead_Underscore => True,
            Magnitude => Magnitude, Overflow => Overflow, OK => OK);
      else
         Read_Digits
           (Text (First .. Text'Last), 10, False, Magnitude, Overflow, OK);
      end if;
   end Read_Integer;

   function Check_Integer (Kind : Integer_Kind; Text : String) return Check_Result is
      Bits     : constant Positive := 8 * Primitive_Size (Kind);
      Signed   : constant Boolean := Kind in Int8_Kind | Int16_Kind | Int32_Kind | Int64_Kind;
      Max_Pos  : constant U64 :=
        (if Signed then 2 ** (Bits - 1) - 1
         elsif Bits = 64 then U64'Last
         else 2 ** Bits - 1);
      Max_Neg  : constant U64 := (if Signed then 2 ** (Bits - 1) else 0);
      Expected : constant String :=
        (if Signed then "an " else "a ") & Type_Name (Kind) & " value in "
        & (if Signed then "-" & Image (Max_Neg) else "0") & " .. " & Image (Max_Pos);
      Negative  : Boolean;
      Magnitude : U64;
      Overflow  : Boolean;
      OK        : Boolean;
   begin
      Read_Integer (Text, Negative, Magnitude, Overflow, OK);
      if not OK or else Overflow then
         return Failure (Expected);
      elsif Negative and then Magnitude > Max_Neg then
         return Failure (Expected);
      elsif not Negative and then Magnitude > Max_Pos then
         return Failure (Expected);
      elsif Negative and then Magnitude /= 0 then
         return Success ("-" & Image (Magnitude));
      else
         return Success (Image (Magnitude));
      end if;
   end Check_Integer;

   ---------------------------------------------------------------------------

   function Check_Float (Kind : Float_Kind; Text : String) return Check_Result is
      Expected : constant String :=
        "a " & Type_Name (Kind)
        & " value (digits, '.', exponent, inf or nan)";
      First    : Positive := Text'First;
      Sign     : Unbounded_String;
      Mantissa : Unbounded_String;
      Fraction : Unbounded_String;
      Exponent : Unbounded_String;
      I        : Positive;

      function Clean (S : String) return String is
         R : Unbounded_String;
      begin
         for C of S loop
            if C /= '_' then
               Append (R, C);
            end if;
         end loop;
         return To_String (R);
      end Clean;

      function Valid_Digits (S : String) return Boolean is
         Magnitude : U64;
         Overflow  : Boolean;
         OK        : Boolean;
      begin
         Read_Digits (S, 10, False, Magnitude, Overflow, OK);
         return OK;
      end Valid_Digits;

   begin
      if Text'Length = 0 then
         return Failure (Expected);
      end if;
      if Text (First) in '+' | '-' then
         if Text (First) = '-' then
            Sign := To_Unbounded_String ("-");
         end if;
         First := First + 1;
      end if;
      declare
         Word : constant String := To_Lower (Text (First .. Text'Last));
      begin
         if Word in "inf" | "infinity" then
            return Success (To_String (Sign) & "inf");
         elsif Word = "nan" then
            return Success ("nan");
         end if;
      end;
      --  digits [. [digits]] | . digits, then [e [sign] digits]
      I := First;
      while I <= Text'Last and then Text (I) in '0' .. '9' | '_' loop
         I := I + 1;
      end loop;
      Mantissa := To_Unbounded_String (Text (First .. I - 1));
      if I <= Text'Last and then Text (I) = '.' then
         declare
            F : constant Positive := I + 1;
         begin
            I := F;
            while I <= Text'Last and then Text (I) in '0' .. '9' | '_' loop
               I := I + 1;
            end loop;
            Fraction := To_Unbounded_String (Text (F .. I - 1));
         end;
      end if;
      if I <= Text'Last and then Text (I) in 'e' | 'E' then
         declare
            F : constant Positive := I + 1;
         begin
            I := F;
            if I <= Text'Last and then Text (I) in '+' | '-' then
               I := I + 1;
            end if;
            if I <= Text'Last then
               Exponent := To_Unbounded_String (Text (F .. Text'Last));
            else
               return Failure (Expected);
            end if;
            declare
               E : constant String := To_String (Exponent);
               D : constant Positive := (if E (E'First) in '+' | '-' then E'First + 1 else E'First);
            begin
               if not Valid_Digits (E (D .. E'Last)) then
                  return Failure (Expected);
               end if;
            end;
            I := Text'Last + 1;
         end;
      end if;
      if I <= Text'Last then
         return Failure (Expected);
      end if;
      if (Length (Mantissa) = 0 and then Length (Fraction) = 0)
        or else (Length (Mantissa) > 0 and then not Valid_Digits (To_String (Mantissa)))
        or else (Length (Fraction) > 0 and then not Valid_Digits (To_String (Fraction)))
      then
         return Failure (Expected);
      end if;
      declare
         Int_Part  : constant String :=
           (if Length (Mantissa) = 0 then "0" else Clean (To_String (Mantissa)));
         Frac_Part : constant String :=
           (if Length (Fraction) = 0 then "0" else Clean (To_String (Fraction)));
         Exp_Raw   : constant String := Clean (To_String (Exponent));
         Exp_Part  : constant String :=
           (if Exp_Raw'Length > 0 and then Exp_Raw (Exp_Raw'First) = '+'
            then Exp_Raw (Exp_Raw'First + 1 .. Exp_Raw'Last) else Exp_Raw);
         Canonical : constant String :=
           To_String (Sign) & Int_Part & "." & Frac_Part
           & (if Exp_Part'Length > 0 then "e" & Exp_Part else "");
      begin
         --  A finite literal must fit the type (Python would give inf).
         declare
            V : constant Long_Float := Long_Float'Value (Canonical);
         begin
            if not V'Valid
              or else (Kind = Float32_Kind and then abs V > Long_Float (Float32'Last))
            then
               return Failure ("a " & Type_Name (Kind) & " value within its range");
            end if;
         end;
         return Success (Canonical);
      exception
         when Constraint_Error =>
            return Failure ("a " & Type_Name (Kind) & " value within its range");
      end;
   end Check_Float;

   ---------------------------------------------------------------------------

   function Character_Count (S : String) return Natural is
      --  UTF-8 code points: every byte that is not a continuation byte.
      N : Natural := 0;
   begin
      for C of S loop
         if Character'Pos (C) not in 16#80# .. 16#BF# then
            N := N + 1;
         end if;
      end loop;
      return N;
   end Character_Count;

   function Is_UTF_8 (S : String) return Boolean is
   begin
      return Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode (S)'Length = Character_Count (S);
   exception
      when Ada.Strings.UTF_Encoding.Encoding_Error =>
         return False;
   end Is_UTF_8;

   function Check_String
     (Kind : Text_Kind; Bound : Natural; Text : String) return Check_Result
   is
      Name   : constant String :=
        (if Kind = String_Kind then "string" else "wstring");
      Result : Unbounded_String;
   begin
      if Text'Length > 0 and then Text (Text'First) in ''' | '"' then
         declare
            Quote : constant Character := Text (Text'First);
            I     : Positive := Text'First + 1;
            Closed : Boolean := False;
         begin
            while I <= Text'Last loop
               if Text (I) = '\' and then I < Text'Last then
                  case Text (I + 1) is
                     when 'n'    => Append (Result, ASCII.LF);
                     when 't'    => Append (Result, ASCII.HT);
                     when 'r'    => Append (Result, ASCII.CR);
                     when 'a'    => Append (Result, ASCII.BEL);
                     when 'b'    => Append (Result, ASCII.BS);
                     when 'f'    => Append (Result, ASCII.FF);
                     when 'v'    => Append (Result, ASCII.VT);
                     when '\' | ''' | '"' => Append (Result, Text (I + 1));
                     when others => Append (Result, Text (I .. I + 1));
                  end case;
                  I := I + 2;
               elsif Text (I) = Quote then
                  if I /= Text'Last then
                     return Failure
                       ("a " & Name & " with its inner " & Quote & " escaped as \" & Quote);
                  end if;
                  Closed := True;
                  I := I + 1;
               else
                  Append (Result, Text (I));
                  I := I + 1;
               end if;
            end loop;
            if not Closed then
               return Failure ("a " & Name & " ending with its opening quote " & Quote);
            end if;
         end;
      else
         Result := To_Unbounded_String (Text);
      end if;
      if Kind = WString_Kind then
         --  A wstring's text becomes characters (UTF-8 decoded): it must be
         --  valid UTF-8.
         if not Is_UTF_8 (To_String (Result)) then
            return Failure ("a " & Name & " in valid UTF-8");
         end if;
      end if;
      if Bound > 0 and then Character_Count (To_String (Result)) > Bound then
         return Failure
           ("a " & Name & " of at most" & Bound'Image & " characters");
      end if;
      return Success (To_String (Result));
   end Check_String;

   ---------------------------------------------------------------------------

   function Check_Scalar
     (Kind         : Element_Kind;
      String_Bound : Natural;
      Text         : String) return Check_Result is
   begin
      case Kind is
         when Bool_Kind =>
            declare
               Word : constant String := To_Lower (Text);
            begin
               if Word in "true" | "1" then
                  return Success ("true");
               elsif Word in "false" | "0" then
                  return Success ("false");
               else
                  return Failure ("a bool value (true, false, 1 or 0)");
               end if;
            end;
         when Byte_Kind | Char_Kind =>
            declare
               R : constant Check_Result := Check_Integer (UInt8_Kind, Text);
            begin
               if R.OK then
                  return R;
               end if;
               return Failure ("a " & Type_Name (Kind) & " value in 0 .. 255");
            end;
         when Integer_Kind =>
            return Check_Integer (Kind, Text);
         when Float_Kind =>
            return Check_Float (Kind, Text);
         when Text_Kind =>
            return Check_String (Kind, String_Bound, Text);
         when Message_Kind =>
            raise Program_Error with "Check_Scalar on a message type";
      end case;
   end Check_Scalar;

   ---------------------------------------------------------------------------

   function Split_Array (Text : String; Quoted : Boolean) return Split_Result is
      Result : Split_Result;
      I      : Natural;
      Last   : Natural;

      function Fail (Expected : String; Where : Natural) return Split_Result is
        ((OK => False, Elements => Span_Vectors.Empty_Vector,
          Expected => To_Unbounded_String (Expected), Where => Where));

      procedure Skip_Blanks is
      begin
         while I <= Last and then Is_Blank (Text (I)) loop
            I := I + 1;
         end loop;
      end Skip_Blanks;

   begin
      if Text'Length < 2 or else Text (Text'First) /= '['
        or else Text (Text'Last) /= ']'
      then
         return Fail ("an array value in brackets [a, b, ...]", Text'First);
      end if;
      I := Text'First + 1;
      Last := Text'Last - 1;
      Skip_Blanks;
      if I > Last then
         return (OK => True, Elements => Span_Vectors.Empty_Vector,
                 Expected => Null_Unbounded_String, Where => 0);
      end if;
      loop
         Skip_Blanks;
         if I > Last or else Text (I) = ',' then
            return Fail ("an array element", (if I > Last then Text'Last else I));
         end if;
         declare
            First : constant Positive := I;
         begin
            if Quoted and then Text (I) in ''' | '"' then
               declare
                  Quote : constant Character := Text (I);
               begin
                  I := I + 1;
                  while I <= Last and then Text (I) /= Quote loop
                     if Text (I) = '\' then
                        I := I + 1;
                     end if;
                     I := I + 1;
                  end loop;
                  if I > Last then
                     return Fail ("a closing quote " & Quote, First);
                  end if;
                  I := I + 1;
               end;
            else
               while I <= Last and then Text (I) /= ',' loop
                  I := I + 1;
               end loop;
            end if;
            declare
               Element : constant String := Trim_Blanks (Text (First .. I - 1));
            begin
               Result.Elements.Append
                 (Element_Span'(First => First, Last => First + Element'Length - 1));
            end;
         end;
         Skip_Blanks;
         exit when I > Last;
         if Text (I) /= ',' then
            return Fail ("',' between array elements", I);
         end if;
         I := I + 1;
      end loop;
      Result.OK := True;
      return Result;
   end Split_Array;

end ROSIDL.Parser.Literals;
