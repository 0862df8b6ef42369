with Ada.Characters.Latin_1;
with Ada.Containers.Hashed_Sets;
with Ada.Strings.Unbounded.Hash;
with Ada.Directories;
with Ada.Streams.Stream_IO;
with Ada.Strings.Fixed;
with Ada.Unchecked_Deallocation;
with RCL.Names;

package body RCL.YAML is

   package L1 renames Ada.Characters.Latin_1;

   package Key_Sets is new Ada.Containers.Hashed_Sets
     (Unbounded_String, Ada.Strings.Unbounded.Hash, Equivalent_Elements => "=");
   --  The keys of the mapping being parsed: duplicates found in constant time (a
   --  mapping of many keys must not cost the square of their number).

   function Img (N : Natural) return String is
      S : constant String := N'Image;
   begin
      return S (S'First + 1 .. S'Last);
   end Img;

   --------------
   -- Classify --
   --------------

   function Classify (Text : String) return Scalar_Kind is
      S     : String renames Text;
      First : Positive := S'First;

      function All_In (From : Positive; Set : String) return Boolean is
        (From <= S'Last
         and then (for all I in From .. S'Last => Ada.Strings.Fixed.Index (Set, [S (I)]) > 0));

      function Is_Float return Boolean is
         I          : Positive := First;
         Digits_Seen : Boolean := False;
         Dot_Or_Exp : Boolean := False;
      begin
         while I <= S'Last and then S (I) in '0' .. '9' loop
            Digits_Seen := True;
            I := I + 1;
         end loop;
         if I <= S'Last and then S (I) = '.' then
            Dot_Or_Exp := True;
            I := I + 1;
            while I <= S'Last and then S (I) in '0' .. '9' loop
               Digits_Seen := True;
               I := I + 1;
            end loop;
         end if;
         if not Digits_Seen then
            return False;
         end if;
         if I <= S'Last and then S (I) in 'e' | 'E' then
            Dot_Or_Exp := True;
            I := I + 1;
            if I <= S'Last and then S (I) in '+' | '-' then
               I := I + 1;
            end if;
            if I > S'Last then
               return False;
            end if;
            while I <= S'Last and then S (I) in '0' .. '9' loop
               I := I + 1;
            end loop;
         end if;
         return I > S'Last and Dot_Or_Exp;
      end Is_Float;
   begin
      if S = "" or else S = "~" or else S = "null" or else S = "Null" or else S = "NULL" then
         return Null_Scalar;
      elsif S = "true" or else S = "True" or else S = "TRUE" or else S = "false"
        or else S = "False" or else S = "FALSE"
      then
         return Bool_Scalar;
      end if;
      if S (First) in '+' | '-' then
         First := First + 1;
      end if;
      if First > S'Last then
         return String_Scalar;
      end if;
      declare
         Rest : constant String := S (First .. S'Last);
      begin
         if Rest = ".inf" or else Rest = ".Inf" or else Rest = ".INF"
           or else ((Rest = ".nan" or else Rest = ".NaN" or else Rest = ".NAN")
                    and then First = S'First)
         then
            return Float_Scalar;
         end if;
      end;
      if All_In (First, "0123456789") then
         return Int_Scalar;
      elsif First + 2 <= S'Last and then S (First) = '0' and then S (First + 1) in 'x' | 'o'
        and then All_In (First + 2, (if S (First + 1) = 'x' then "0123456789abcdefABCDEF"
                                     else "01234567"))
      then
         return Int_Scalar;
      elsif Is_Float then
         return Float_Scalar;
      end if;
      return String_Scalar;
   end Classify;

   -------------------
   -- Integer_Value --
   -------------------

   function Integer_Value (Text : String) return Long_Long_Integer is
      S : String renames Text;
   begin
      if Classify (S) /= Int_Scalar then
         raise Constraint_Error with "not an integer";
      end if;
      declare
         Neg   : constant Boolean := S (S'First) = '-';
         First : constant Positive := S'First + (if S (S'First) in '+' | '-' then 1 else 0);
         Base  : Long_Long_Integer := 10;
         Start : Positive := First;
         V     : Long_Long_Integer := 0;
      begin
         if First + 1 <= S'Last and then S (First) = '0' and then S (First + 1) in 'x' | 'o' then
            Base := (if S (First + 1) = 'x' then 16 else 8);
            Start := First + 2;
         end if;
         for I in Start .. S'Last loop
            V := V * Base - (case S (I) is
                 when '0' .. '9' => Character'Pos (S (I)) - Character'Pos ('0'),
                 when 'a' .. 'f' => Character'Pos (S (I)) - Character'Pos ('a') + 10,
                 when others => Character'Pos (S (I)) - Character'Pos ('A') + 10);
         end loop;
         --  Accumulated negatively so that the most negative value fits.
         return (if Neg then V else -V);
      end;
   end Integer_Value;

   -----------------
   -- Float_Value --
   -----------------

   function Float_Value (Text : String) return Long_Float is
      S    : String renames Text;
      Zero : constant Long_Float := Long_Float'Value ("0.0");
      --  Not static: the divisions below make IEEE infinities and NaN.
   begin
      case Classify (S) is
         when Int_Scalar =>
            return Long_Float (Integer_Value (S));
         when Float_Scalar =>
            null;
         when others =>
            raise Constraint_Error with "not a number";
      end case;
      if S in ".inf" | ".Inf" | ".INF" | "+.inf" | "+.Inf" | "+.INF" then
         return 1.0 / Zero;
      elsif S in "-.inf" | "-.Inf" | "-.INF" then
         return -1.0 / Zero;
      elsif S in ".nan" | ".NaN" | ".NAN" then
         return Zero / Zero;
      end if;
      declare
         --  Ada's 'Value needs digits on both sides of the point.
         T : String (1 .. 2 * S'Length + 4);
         L : Natural := 0;
         Seen_Point : Boolean := False;
         procedure Put (C : Character) is
         begin
            L := L + 1;
            T (L) := C;
         end Put;
      begin
         for I in S'Range loop
            if S (I) = '.' then
               if L = 0 or else T (L) not in '0' .. '9' then
                  Put ('0');
               end if;
               Put ('.');
               Seen_Point := True;
               if I = S'Last or else S (I + 1) not in '0' .. '9' then
                  Put ('0');
               end if;
            elsif S (I) in 'e' | 'E' and then not Seen_Point then
               Put ('.');
               Put ('0');
               Put ('e');
               Seen_Point := True;
            else
               Put (S (I));
            end if;
         end loop;
         return Long_Float'Value (T (1 .. L));
      end;
   end Float_Value;

   -----------
   -- Parse --
   -----------

   function Parse_Text (T : String; Source : String) return Document
     with Pre => T'First = 1;
   --  Parse, for a text indexed from 1 (no copy: a large file would not fit on the stack).

   type String_Access is access String;
   procedure Free is new Ada.Unchecked_Deallocation (String, String_Access);

   function Parse (Text : String; Source : String := "<input>") return Document is
      Copy : String_Access;
   begin
      if Text'First = 1 then
         return Parse_Text (Text, Source);
      end if;
      Copy := new String (1 .. Text'Length);
      Copy.all := Text;
      return Result : constant Document := Parse_Text (Copy.all, Source) do
         Free (Copy);
      end return;
   exception
      when others =>
         Free (Copy);
         raise;
   end Parse;

   function Parse_Text (T : String; Source : String) return Document is
      Pos        : Positive := 1;
      Line       : Positive := 1;
      Line_Start : Positive := 1;
      D          : Document;
      Depth      : Natural := 0;
      --  Of the collection being parsed (Enter / Leave).

      function Col return Positive is (Pos - Line_Start + 1);
      function EOF return Boolean is (Pos > T'Last);
      function Cur return Character is (if Pos > T'Last then L1.LF else T (Pos));
      function Peek (K : Natural) return Character is
        (if Pos + K > T'Last then L1.LF else T (Pos + K));
      function Blank_After (K : Natural) return Boolean is
        (Peek (K) in ' ' | L1.LF | L1.HT | L1.CR);

      procedure Fail (Message : String; L : Positive; C : Positive) is
      begin
         raise Parse_Error with Source & ":" & Img (L) & ":" & Img (C) & ": " & Message;
      end Fail;

      procedure Fail (Message : String) is
      begin
         Fail (Message, Line, Col);
      end Fail;

      procedure Enter is
      begin
         Depth := Depth + 1;
         if Depth > Max_Depth then
            Fail ("collections nested deeper than" & Natural'Image (Max_Depth));
         end if;
      end Enter;

      procedure Leave is
      begin
         Depth := Depth - 1;
      end Leave;

      procedure Advance is
      begin
         if T (Pos) = L1.LF then
            Line := Line + 1;
            Line_Start := Pos + 1;
         end if;
         Pos := Pos + 1;
      end Advance;

      procedure Skip_Inline is
      begin
         while not EOF and then Cur in ' ' | L1.HT | L1.CR loop
            Advance;
         end loop;
      end Skip_Inline;

      function At_Line_End return Boolean is (EOF or else Cur = L1.LF or else Cur = '#');
      --  After Skip_Inline.

      procedure Skip_To_Content is
         --  Past blanks, comments and line ends, to the next content.
         Start_Line : constant Positive := Line;
      begin
         loop
            Skip_Inline;
            exit when EOF;
            if Cur = '#' then
               while not EOF and then Cur /= L1.LF loop
                  Advance;
               end loop;
            end if;
            exit when EOF;
            if Cur = L1.LF then
               Advance;
            else
               exit;
            end if;
         end loop;
         if not EOF and then Line /= Start_Line then
            for I in Line_Start .. Pos - 1 loop
               if T (I) = L1.HT then
                  Fail ("tab character in indentation (use spaces)", Line, I - Line_Start + 1);
               end if;
            end loop;
         end if;
      end Skip_To_Content;

      function New_Node
        (Kind : Node_Kind; L, C : Positive; Text : String := ""; Quoted : Boolean := False)
         return Positive is
      begin
         D.Nodes.Append (Node_Record'(Kind => Kind, Text => To_Unbounded_String (Text),
                                      Quoted => Quoted, Line => L, Column => C,
                                      others => <>));
         return D.Nodes.Last_Index;
      end New_Node;

      procedure Check_Unsupported is
      begin
         case Cur is
            when '&' | '*' => Fail ("anchors and aliases are not supported");
            when '!' => Fail ("tags are not supported");
            when '|' | '>' => Fail ("block scalars (| and >) are not supported");
            when '?' =>
               if Blank_After (1) then
                  Fail ("complex keys are not supported");
               end if;
            when '@' | '`' => Fail ("'" & Cur & "' cannot start a plain scalar");
            when others => null;
         end case;
      end Check_Unsupported;

      --  Quoted scalars ---------------------------------------------------

      procedure Put_UTF_8 (Into : in out Unbounded_String; Code : Natural) is
         function Ch (V : Natural) return Character is (Character'Val (V));
      begin
         if Code < 16#80# then
            Append (Into, Ch (Code));
         elsif Code < 16#800# then
            Append (Into, Ch (16#C0# + Code / 64));
            Append (Into, Ch (16#80# + Code mod 64));
         elsif Code < 16#10000# then
            Append (Into, Ch (16#E0# + Code / 4096));
            Append (Into, Ch (16#80# + Code / 64 mod 64));
            Append (Into, Ch (16#80# + Code mod 64));
         else
            Append (Into, Ch (16#F0# + Code / 262_144));
            Append (Into, Ch (16#80# + Code / 4096 mod 64));
            Append (Into, Ch (16#80# + Code / 64 mod 64));
            Append (Into, Ch (16#80# + Code mod 64));
         end if;
      end Put_UTF_8;

      function Quoted_Scalar return Positive is
         Q      : constant Character := Cur;
         L      : constant Positive := Line;
         C      : constant Positive := Col;
         Result : Unbounded_String;
      begin
         Advance;
         loop
            if EOF or else Cur = L1.LF then
               Fail ("unterminated " & (if Q = '"' then "double" else "single")
                     & "-quoted string (quoted strings must end on their line)", L, C);
            end if;
            if Cur = Q then
               if Q = ''' and then Peek (1) = ''' then
                  Append (Result, ''');
                  Advance;
                  Advance;
               else
                  Advance;
                  exit;
               end if;
            elsif Q = '"' and then Cur = '\' then
               declare
                  E_Col : constant Positive := Col;
                  E     : constant Character := Peek (1);
                  Width : Natural := 0;
               begin
                  if Pos + 1 > T'Last or else E = L1.LF then
                     Fail ("unterminated double-quoted string (a '\' ends its line)", L, C);
                  end if;
                  Advance;
                  Advance;
                  case E is
                     when 'n' => Append (Result, L1.LF);
                     when 't' => Append (Result, L1.HT);
                     when 'r' => Append (Result, L1.CR);
                     when '0' => Append (Result, L1.NUL);
                     when '"' | '\' | '/' | ' ' => Append (Result, E);
                     when 'x' => Width := 2;
                     when 'u' => Width := 4;
                     when 'U' => Width := 8;
                     when others =>
                        Fail ("unknown escape sequence \" & E, Line, E_Col);
                  end case;
                  if Width > 0 then
                     declare
                        Code : Natural := 0;
                     begin
                        for I in 1 .. Width loop
                           if Cur not in '0' .. '9' | 'a' .. 'f' | 'A' .. 'F' then
                              Fail ("\" & E & " needs" & Width'Image & " hex digits", Line, E_Col);
                           end if;
                           Code := Code * 16 + (case Cur is
                              when '0' .. '9' => Character'Pos (Cur) - Character'Pos ('0'),
                              when 'a' .. 'f' => Character'Pos (Cur) - Character'Pos ('a') + 10,
                              when others => Character'Pos (Cur) - Character'Pos ('A') + 10);
                           Advance;
                        end loop;
                        if Code > 16#10FFFF# then
                           Fail ("escape beyond Unicode", Line, E_Col);
                        end if;
                        Put_UTF_8 (Result, Code);
                     end;
                  end if;
               end;
            else
               Append (Result, Cur);
               Advance;
            end if;
         end loop;
         return New_Node (Scalar, L, C, To_String (Result), Quoted => True);
      end Quoted_Scalar;

      procedure Expect_Line_End (What : String) is
      begin
         Skip_Inline;
         if not At_Line_End then
            Fail ("unexpected text after " & What);
         end if;
      end Expect_Line_End;

      --  Plain scalars ----------------------------------------------------

      type Plain_Context is (Block, Flow, Flow_Key);
      --  Where a plain scalar stands: it ends at the line end in a block; in
      --  a flow collection also at ',', a bracket or brace, and at ": " (at
      --  any ':' in a mapping's key).

      function Plain_Scalar (Context : Plain_Context) return Positive is
         L     : constant Positive := Line;
         C     : constant Positive := Col;
         Start : constant Positive := Pos;
         Last  : Natural := Pos - 1;

         function Ends_Here return Boolean is
           (Cur = L1.LF
            or else (Cur = '#' and then Pos > Start and then T (Pos - 1) in ' ' | L1.HT)
            or else (Context /= Block
                     and then (Cur in ',' | ']' | '}' | '[' | '{'
                               or else (Cur = ':'
                                        and then (Blank_After (1) or Context = Flow_Key)))));
      begin
         Check_Unsupported;
         while not EOF and then not Ends_Here loop
            if Context = Block and then Cur = ':' and then Blank_After (1) then
               Fail ("a mapping cannot start on the line of its key (put it on its own line"
                     & " or use {...})");
            end if;
            if Cur not in ' ' | L1.HT | L1.CR then
               Last := Pos;
            end if;
            Advance;
         end loop;
         if Last < Start then
            Fail ("expected a value", L, C);
         end if;
         return New_Node (Scalar, L, C, T (Start .. Last));
      end Plain_Scalar;

      --  Flow collections -----------------------------------------------

      procedure Skip_Flow_Space is
      begin
         loop
            while not EOF and then Cur in ' ' | L1.HT | L1.CR | L1.LF loop
               Advance;
            end loop;
            exit when EOF or else Cur /= '#';
            while not EOF and then Cur /= L1.LF loop
               Advance;
            end loop;
         end loop;
      end Skip_Flow_Space;

      function Flow_Node return Positive;

      function Flow_Item (In_Map_Key : Boolean := False) return Positive is
      begin
         Skip_Flow_Space;
         if EOF then
            Fail ("unexpected end of input in a flow collection");
         end if;
         if Cur in '[' | '{' then
            return Flow_Node;
         elsif Cur in '"' | ''' then
            return Quoted_Scalar;
         else
            return Plain_Scalar (if In_Map_Key then Flow_Key else Flow);
         end if;
      end Flow_Item;

      function Flow_Node return Positive is
         L     : constant Positive := Line;
         C     : constant Positive := Col;
         Open  : constant Character := Cur;
         Close : constant Character := (if Open = '[' then ']' else '}');
         N     : constant Positive := New_Node ((if Open = '[' then Sequence else Mapping), L, C);
         Seen  : Key_Sets.Set;
      begin
         Enter;
         Advance;
         loop
            Skip_Flow_Space;
            if EOF then
               Fail ("'" & Open & "' is never closed", L, C);
            end if;
            exit when Cur = Close;
            if Open = '[' then
               declare
                  Item : constant Positive := Flow_Item;
               begin
                  D.Nodes (N).Children.Append (Item);
               end;
            else
               declare
                  K_Line : constant Positive := Line;
                  K_Col  : constant Positive := Col;
                  K      : constant Positive := Flow_Item (In_Map_Key => True);
                  Key    : constant String := To_String (D.Nodes (K).Text);
                  V      : Positive;
               begin
                  if D.Nodes (K).Kind /= Scalar then
                     Fail ("mapping keys must be scalars", K_Line, K_Col);
                  end if;
                  if Seen.Contains (To_Unbounded_String (Key)) then
                     Fail ("duplicate key """ & Key & """", K_Line, K_Col);
                  end if;
                  Skip_Flow_Space;
                  if Cur /= ':' then
                     Fail ("expected ':' after key """ & Key & """");
                  end if;
                  Advance;
                  Skip_Flow_Space;
                  if Cur in ',' | '}' then
                     V := New_Node (Null_Value, Line, Col);
                  else
                     V := Flow_Item;
                  end if;
                  Seen.Insert (To_Unbounded_String (Key));
                  D.Nodes (N).Keys.Append (To_Unbounded_String (Key));
                  D.Nodes (N).Key_At.Append (Position'(K_Line, K_Col));
                  D.Nodes (N).Children.Append (V);
               end;
            end if;
            Skip_Flow_Space;
            if Cur = ',' then
               Advance;
            elsif Cur /= Close then
               if EOF then
                  Fail ("'" & Open & "' is never closed", L, C);
               end if;
               Fail ("expected ',' or '" & Close & "', found '" & Cur & "'");
            end if;
         end loop;
         Advance;  --  Close.
         Leave;
         return N;
      end Flow_Node;

      --  Block collections ------------------------------------------------

      function At_Document_Marker return Boolean is
        (Col = 1 and then ((Cur = '-' and then Peek (1) = '-' and then Peek (2) = '-')
                           or else (Cur = '.' and then Peek (1) = '.' and then Peek (2) = '.'))
         and then Blank_After (3));

      function Is_Key_Here return Boolean is
         I : Positive := Pos;
      begin
         if Cur in '"' | ''' then
            I := I + 1;
            while I <= T'Last and then T (I) /= T (Pos) and then T (I) /= L1.LF loop
               I := I + (if T (Pos) = '"' and then T (I) = '\' then 2 else 1);
            end loop;
            I := I + 1;
            while I <= T'Last and then T (I) in ' ' | L1.HT loop
               I := I + 1;
            end loop;
            return I <= T'Last and then T (I) = ':'
              and then (I = T'Last or else T (I + 1) in ' ' | L1.LF | L1.CR | L1.HT);
         end if;
         if Cur in '[' | '{' then
            return False;
         end if;
         while I <= T'Last and then T (I) /= L1.LF loop
            exit when T (I) = '#' and then I > Pos and then T (I - 1) in ' ' | L1.HT;
            if T (I) = ':'
              and then (I = T'Last or else T (I + 1) in ' ' | L1.LF | L1.CR | L1.HT)
            then
               return True;
            end if;
            I := I + 1;
         end loop;
         return False;
      end Is_Key_Here;

      function Parse_Node return Positive;
      function Block_Sequence (C : Positive) return Positive;

      function Inline_Value return Positive is
         N : Positive;
      begin
         Check_Unsupported;
         if Cur in '[' | '{' then
            N := Flow_Node;
            Expect_Line_End ("a flow collection");
         elsif Cur in '"' | ''' then
            N := Quoted_Scalar;
            Expect_Line_End ("a quoted string");
         elsif Cur = '-' and then Blank_After (1) then
            Fail ("a sequence cannot start on the line of its key (put it on its own line"
                  & " or use [...])");
         else
            N := Plain_Scalar (Block);
         end if;
         return N;
      end Inline_Value;

      function Block_Mapping (C : Positive) return Positive is
         M    : constant Positive := New_Node (Mapping, Line, C);
         Seen : Key_Sets.Set;
      begin
         loop
            declare
               K_Line : constant Positive := Line;
               K_Col  : constant Positive := Col;
               Key    : Unbounded_String;
               V      : Positive;
            begin
               if Cur = '-' and then Blank_After (1) then
                  Fail ("expected a 'key: value' of the mapping at column" & C'Image
                        & ", found a sequence item");
               end if;
               if not Is_Key_Here then
                  Fail ("expected 'key: value' (the mapping at column" & C'Image
                        & " continues here)");
               end if;
               if Cur in '"' | ''' then
                  declare
                     K : constant Positive := Quoted_Scalar;
                  begin
                     Key := D.Nodes (K).Text;
                  end;
                  Skip_Inline;
               else
                  declare
                     Start : constant Positive := Pos;
                     Last  : Natural := Pos - 1;
                  begin
                     while not (Cur = ':' and then Blank_After (1)) loop
                        if Cur not in ' ' | L1.HT then
                           Last := Pos;
                        end if;
                        Advance;
                     end loop;
                     Key := To_Unbounded_String (T (Start .. Last));
                  end;
               end if;
               if Seen.Contains (Key) then
                  Fail ("duplicate key """ & To_String (Key) & """", K_Line, K_Col);
               end if;
               Advance;  --  ':'
               Skip_Inline;
               if At_Line_End then
                  Skip_To_Content;
                  if EOF then
                     V := New_Node (Null_Value, K_Line, K_Col);
                  elsif Col > C then
                     V := Parse_Node;
                  elsif Col = C and then Cur = '-' and then Blank_After (1) then
                     V := Block_Sequence (C);
                  else
                     V := New_Node (Null_Value, K_Line, K_Col);
                  end if;
               else
                  V := Inline_Value;
               end if;
               Seen.Insert (Key);
               D.Nodes (M).Keys.Append (Key);
               D.Nodes (M).Key_At.Append (Position'(K_Line, K_Col));
               D.Nodes (M).Children.Append (V);
            end;
            Skip_To_Content;
            exit when EOF or else Col < C or else At_Document_Marker;
            if Col > C then
               Fail ("bad indentation: this line is deeper than the mapping at column"
                     & C'Image & " it would continue");
            end if;
         end loop;
         return M;
      end Block_Mapping;

      function Block_Sequence (C : Positive) return Positive is
         S : constant Positive := New_Node (Sequence, Line, C);
      begin
         loop
            declare
               V : Positive;
               L : constant Positive := Line;
            begin
               Advance;  --  '-'
               Skip_Inline;
               if At_Line_End then
                  Skip_To_Content;
                  if not EOF and then Col > C then
                     V := Parse_Node;
                  else
                     V := New_Node (Null_Value, L, C);
                  end if;
               else
                  V := Parse_Node;
               end if;
               D.Nodes (S).Children.Append (V);
            end;
            Skip_To_Content;
            exit when EOF or else Col < C;
            if Col = C and then Cur = '-' and then Blank_After (1) then
               null;
            elsif Col = C then
               exit;  --  The enclosing mapping continues.
            else
               Fail ("bad indentation: expected a '- ' item at column" & C'Image);
            end if;
         end loop;
         return S;
      end Block_Sequence;

      function Parse_Node return Positive is
         C : constant Positive := Col;
         N : Positive;
      begin
         Check_Unsupported;
         Enter;
         if Cur = '-' and then Blank_After (1) then
            N := Block_Sequence (C);
         elsif Cur in '[' | '{' then
            N := Flow_Node;
            Expect_Line_End ("a flow collection");
         elsif Is_Key_Here then
            N := Block_Mapping (C);
         elsif Cur in '"' | ''' then
            N := Quoted_Scalar;
            Expect_Line_End ("a quoted string");
         else
            N := Plain_Scalar (Block);
         end if;
         Leave;
         return N;
      end Parse_Node;

   begin
      D.Source := To_Unbounded_String (Source);
      Skip_To_Content;
      if not EOF and then Cur = '-' and then Peek (1) = '-' and then Peek (2) = '-'
        and then Blank_After (3)
      then
         Advance;
         Advance;
         Advance;
         Skip_To_Content;
      end if;
      if EOF then
         D.Root := New_Node (Null_Value, Line, 1);
         return D;
      end if;
      D.Root := Parse_Node;
      Skip_To_Content;
      if not EOF then
         if At_Document_Marker then
            Fail ("only one document is supported");
         end if;
         Fail ("unexpected content (check the indentation)");
      end if;
      return D;
   end Parse_Text;

   ----------------
   -- Parse_File --
   ----------------

   function Shown (Path : String) return String is
     (RCL.Names.Shortened (Path, Longest => 80, Tail => 57));
   --  Path as messages quote it: its middle left out past 80 characters
   --  (the end, with the file name, kept), so that "PATH:LINE:COL: reason"
   --  keeps its reason within GNAT's 200 characters of exception message.

   function Parse_File (Path : String) return Document is
      use type Ada.Directories.File_Kind;
      Text : String_Access;
   begin
      if not Ada.Directories.Exists (Path) then
         raise Parse_Error with Shown (Path) & ": no such file";
      elsif Ada.Directories.Kind (Path) /= Ada.Directories.Ordinary_File then
         raise Parse_Error with Shown (Path) & ": not a regular file";
      end if;
      declare
         F : Ada.Streams.Stream_IO.File_Type;
      begin
         Ada.Streams.Stream_IO.Open (F, Ada.Streams.Stream_IO.In_File, Path);
         Text := new String (1 .. Natural (Ada.Streams.Stream_IO.Size (F)));
         --  On the heap: a large file must not overflow the stack.
         String'Read (Ada.Streams.Stream_IO.Stream (F), Text.all);
         Ada.Streams.Stream_IO.Close (F);
      exception
         when others =>
            if Ada.Streams.Stream_IO.Is_Open (F) then
               Ada.Streams.Stream_IO.Close (F);
            end if;
            Free (Text);
            raise Parse_Error with Shown (Path) & ": cannot be read";
      end;
      return Result : constant Document := Parse_Text (Text.all, Shown (Path)) do
         Free (Text);
      end return;
   exception
      when others =>
         Free (Text);
         raise;
   end Parse_File;

   ---------------
   -- Accessors --
   ---------------

   function Root (This : Document) return Node is (This.Root);
   function Kind (This : Document; N : Node) return Node_Kind is (This.Nodes (N).Kind);
   function Text (This : Document; N : Node) return String is
     (To_String (This.Nodes (N).Text));
   function Quoted (This : Document; N : Node) return Boolean is (This.Nodes (N).Quoted);

   function Scalar_Type (This : Document; N : Node) return Scalar_Kind is
     (if This.Nodes (N).Kind = Null_Value then Null_Scalar
      elsif This.Nodes (N).Quoted then String_Scalar
      else Classify (To_String (This.Nodes (N).Text)));

   function Length (This : Document; N : Node) return Natural is
     (Natural (This.Nodes (N).Children.Length));
   function Item (This : Document; N : Node; I : Positive) return Node is
     (This.Nodes (N).Children (I));
   function Key (This : Document; N : Node; I : Positive) return String is
     (To_String (This.Nodes (N).Keys (I)));

   function Key_Where (This : Document; N : Node; I : Positive) return String is
     (To_String (This.Source) & ":" & Img (This.Nodes (N).Key_At (I).Line) & ":"
      & Img (This.Nodes (N).Key_At (I).Column));

   function Find (This : Document; N : Node; Key : String) return Natural is
   begin
      if This.Nodes (N).Kind /= Mapping then
         return 0;
      end if;
      for I in 1 .. Length (This, N) loop
         if To_String (This.Nodes (N).Keys (I)) = Key then
            return This.Nodes (N).Children (I);
         end if;
      end loop;
      return 0;
   end Find;

   function Where (This : Document; N : Node) return String is
     (To_String (This.Source) & ":" & Img (This.Nodes (N).Line) & ":"
      & Img (This.Nodes (N).Column));

   function Image (This : Document; N : Node) return String is
      R : Unbounded_String;
   begin
      case This.Nodes (N).Kind is
         when Null_Value =>
            return "null";
         when Scalar =>
            if This.Nodes (N).Quoted then
               return "'" & Text (This, N) & "'";
            end if;
            return Text (This, N);
         when Sequence | Mapping =>
            Append (R, (if This.Nodes (N).Kind = Sequence then "[" else "{"));
            for I in 1 .. Length (This, N) loop
               if I > 1 then
                  Append (R, ", ");
               end if;
               if This.Nodes (N).Kind = Mapping then
                  Append (R, Key (This, N, I) & ": ");
               end if;
               Append (R, Image (This, Item (This, N, I)));
            end loop;
            Append (R, (if This.Nodes (N).Kind = Sequence then "]" else "}"));
            return To_String (R);
      end case;
   end Image;

end RCL.YAML;
