with Ada.Containers.Vectors;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with ROSIDL.Interfaces;
with ROSIDL.Parser.Literals;

package body ROSIDL.Parser is

   use Ada.Strings.Unbounded;
   use ROSIDL.Parser.Literals;

   ---------------------------------------------------------------------------
   --  Names

   function Is_Valid_Package_Name (Name : String) return Boolean is
   begin
      if Name'Length = 0 or else Name (Name'First) not in 'a' .. 'z'
        or else Name (Name'Last) = '_'
      then
         return False;
      end if;
      for I in Name'Range loop
         if Name (I) not in 'a' .. 'z' | '0' .. '9' | '_' then
            return False;
         elsif Name (I) = '_' and then I > Name'First and then Name (I - 1) = '_' then
            return False;
         end if;
      end loop;
      return True;
   end Is_Valid_Package_Name;

   function Is_Valid_Type_Name (Name : String) return Boolean is
     (Name'Length > 0 and then Name (Name'First) in 'A' .. 'Z'
      and then (for all C of Name => C in 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9'));

   function Is_Valid_Constant_Name (Name : String) return Boolean is
   begin
      if Name'Length = 0 or else Name (Name'First) not in 'A' .. 'Z'
        or else Name (Name'Last) = '_'
      then
         return False;
      end if;
      for I in Name'Range loop
         if Name (I) not in 'A' .. 'Z' | '0' .. '9' | '_' then
            return False;
         elsif Name (I) = '_' and then Name (I - 1) = '_' then
            return False;
         end if;
      end loop;
      return True;
   end Is_Valid_Constant_Name;

   Reserved : constant String :=
     "|and|as|assert|async|await|break|class|continue|def|del|elif|else|except|finally|for|"
     & "from|global|if|import|in|is|lambda|nonlocal|not|or|pass|raise|return|try|while|"
     & "with|yield|";
   --  The Python keywords, "|" around each.

   function Is_Reserved_Name (Name : String) return Boolean is
     (Name'Length > 0 and then Ada.Strings.Fixed.Index (Reserved, "|" & Name & "|") > 0);

   ---------------------------------------------------------------------------
   --  Errors

   procedure Fail (File : String; Line, Column : Natural; Expected, Found : String)
     with No_Return;

   procedure Fail (File : String; Line, Column : Natural; Expected, Found : String) is
   begin
      raise Definition_Error with
        Image (Source_Position'(To_Unbounded_String (File), Line, Column))
        & ": expected " & Expected & ", found " & Found;
   end Fail;

   function Quote (S : String) return String is ("'" & S & "'");

   function Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   ---------------------------------------------------------------------------
   --  Lines

   type Line_Record is record
      Text   : Unbounded_String;
      Number : Positive := 1;
   end record;

   package Line_Vectors is new Ada.Containers.Vectors (Positive, Line_Record);

   BOM : constant String :=
     Character'Val (16#EF#) & Character'Val (16#BB#) & Character'Val (16#BF#);
   --  The UTF-8 byte order mark some editors put at the start of a file.

   function Split_Lines (Text : String) return Line_Vectors.Vector is
      --  The lines of Text (LF or CR LF ends), numbered from 1, without a
      --  leading byte order mark.
      Result : Line_Vectors.Vector;
      First  : Positive :=
        (if Text'Length >= 3 and then Text (Text'First .. Text'First + 2) = BOM
         then Text'First + 3 else Text'First);
      Number : Positive := 1;

      procedure Add (Last : Natural) is
         L : Natural := Last;
      begin
         if L >= First and then Text (L) = ASCII.CR then
            L := L - 1;
         end if;
         Result.Append (Line_Record'(To_Unbounded_String (Text (First .. L)), Number));
      end Add;

   begin
      for I in First .. Text'Last loop
         if Text (I) = ASCII.LF then
            Add (I - 1);
            First := I + 1;
            Number := Number + 1;
         end if;
      end loop;
      if First <= Text'Last then
         Add (Text'Last);
      end if;
      return Result;
   end Split_Lines;

   function Is_Separator (L : Line_Record) return Boolean is
     (Trim_Blanks (To_String (L.Text)) = "---");

   ---------------------------------------------------------------------------
   --  Parsing one message

   type Context is record
      File         : Unbounded_String;
      Package_Name : Unbounded_String;
      Name         : Unbounded_String;
      --  The message being parsed ("AddTwoInts_Request" for a part).
      Namespace    : Interface_Kind := Msg;
      Resolve      : Resolver;
   end record;

   function Primitive_Kind_Of (Name : String; Kind : out Element_Kind) return Boolean is
   begin
      for K in Primitive_Kind loop
         if Type_Name (K) = Name then
            Kind := K;
            return True;
         end if;
      end loop;
      if Name = "string" then
         Kind := String_Kind;
         return True;
      elsif Name = "wstring" then
         Kind := WString_Kind;
         return True;
      end if;
      Kind := Bool_Kind;
      return False;
   end Primitive_Kind_Of;

   function Read_Bound (S : String) return Natural is
      --  A decimal number > 0, or 0 when S is not one.
      Value : Natural := 0;
   begin
      if S'Length = 0 or else S'Length > 9 then
         return 0;
      end if;
      for C of S loop
         if C not in '0' .. '9' then
            return 0;
         end if;
         Value := Value * 10 + (Character'Pos (C) - Character'Pos ('0'));
      end loop;
      return Value;
   end Read_Bound;

   function Parse_Type
     (C : Context; Token : String; Line, Column : Positive) return Field_Type
   --  Token starts at Column of Line.
   is
      Result    : Field_Type;
      Base_Last : Natural := Token'Last;

      function Col (I : Positive) return Positive is (Column + (I - Token'First));

   begin
      if Token (Token'Last) = ']' then
         declare
            Open : constant Natural :=
              Ada.Strings.Fixed.Index (Token, "[", Ada.Strings.Backward);
         begin
            if Open = 0 then
               Fail (To_String (C.File), Line, Col (Token'Last),
                     "'[' before ']' in an array type", Quote (Token));
            end if;
            declare
               Inside : constant String := Token (Open + 1 .. Token'Last - 1);
            begin
               if Inside'Length = 0 then
                  Result.Collection := Unbounded_Sequence;
               elsif Inside'Length >= 2 and then Inside (Inside'First .. Inside'First + 1) = "<="
               then
                  Result.Collection := Bounded_Sequence;
                  Result.Size := Read_Bound (Inside (Inside'First + 2 .. Inside'Last));
                  if Result.Size = 0 then
                     Fail (To_String (C.File), Line, Col (Open + 3),
                           "a sequence bound N > 0 after '<='",
                           Quote (Inside (Inside'First + 2 .. Inside'Last)));
                  end if;
               else
                  Result.Collection := Fixed_Array;
                  Result.Size := Read_Bound (Inside);
                  if Result.Size = 0 then
                     Fail (To_String (C.File), Line, Col (Open + 1),
                           "an array size N > 0 (T[N], T[<=N] or T[])",
                           Quote (Inside));
                  end if;
               end if;
            end;
            Base_Last := Open - 1;
         end;
      end if;

      declare
         Base : constant String := Token (Token'First .. Base_Last);
         Kind : Element_Kind;
         Bound_At : constant Natural := Ada.Strings.Fixed.Index (Base, "<=");
         Slash    : constant Natural := Ada.Strings.Fixed.Index (Base, "/");
         Pkg, Name : Unbounded_String;
      begin
         if Base'Length = 0 then
            Fail (To_String (C.File), Line, Column, "an element type before '['",
                  Quote (Token));
         elsif Primitive_Kind_Of (Base, Kind) then
            Result.Kind := Kind;
            return Result;
         elsif Bound_At > 0
           and then Primitive_Kind_Of (Base (Base'First .. Bound_At - 1), Kind)
           and then Kind in Text_Kind
         then
            Result.Kind := Kind;
            Result.String_Bound := Read_Bound (Base (Bound_At + 2 .. Base'Last));
            if Result.String_Bound = 0 then
               Fail (To_String (C.File), Line, Col (Bound_At + 2),
                     "a string bound N > 0 after '<='",
                     Quote (Base (Bound_At + 2 .. Base'Last)));
            end if;
            return Result;
         elsif Base = "Header" then
            Pkg := To_Unbounded_String ("std_msgs");
            Name := To_Unbounded_String ("Header");
         elsif Base in "time" | "duration" then
            --  ROS 1 names kept by ROS 2 for compatibility.
            Pkg := To_Unbounded_String ("builtin_interfaces");
            Name := To_Unbounded_String (if Base = "time" then "Time" else "Duration");
         elsif Slash = 0 then
            Pkg := C.Package_Name;
            Name := To_Unbounded_String (Base);
         elsif Ada.Strings.Fixed.Index (Base (Slash + 1 .. Base'Last), "/") > 0 then
            Fail (To_String (C.File), Line, Column,
                  "a type 'Name' or 'package/Name'", Quote (Base));
         else
            Pkg := To_Unbounded_String (Base (Base'First .. Slash - 1));
            Name := To_Unbounded_String (Base (Slash + 1 .. Base'Last));
            if not Is_Valid_Package_Name (To_String (Pkg)) then
               Fail (To_String (C.File), Line, Column,
                     "a package name ([a-z][a-z0-9_]*, no '__' or trailing '_')",
                     Quote (To_String (Pkg)));
            end if;
         end if;
         if not Is_Valid_Type_Name (To_String (Name)) then
            Fail (To_String (C.File), Line,
                  (if Slash = 0 then Column else Col (Slash + 1)),
                  "a primitive type or a type name ([A-Z][A-Za-z0-9]*)",
                  Quote (To_String (Name)));
         end if;
         if C.Namespace = Msg and then Pkg = C.Package_Name and then Name = C.Name then
            Fail (To_String (C.File), Line, Column,
                  "a type that does not nest the message itself",
                  Quote (To_String (Pkg) & "/" & To_String (Name)));
         end if;
         Result.Kind := Message_Kind;
         Result.Nested := C.Resolve
           (To_String (Pkg), To_String (Name),
            (File => C.File, Line => Line, Column => Column));
         if Result.Nested = null then
            Fail (To_String (C.File), Line, Column, "a message type on the search path",
                  Quote (To_String (Pkg) & "/" & To_String (Name)));
         end if;
         return Result;
      end;
   end Parse_Type;

   procedure Check_Default
     (C      : Context;
      Of_Type : Field_Type;
      Text   : String;
      Line, Column : Positive;
      Into   : out String_Vectors.Vector)
   --  Text (trimmed) starts at Column.
   is
      function Col (I : Positive) return Positive is (Column + (I - Text'First));
   begin
      Into.Clear;
      if Of_Type.Kind = Message_Kind then
         Fail (To_String (C.File), Line, Column,
               "no default value for a field of message type " & Image (Of_Type),
               Quote (Text));
      end if;
      if Of_Type.Collection = Single then
         declare
            R : constant Check_Result :=
              Check_Scalar (Of_Type.Kind, Of_Type.String_Bound, Text);
         begin
            if not R.OK then
               Fail (To_String (C.File), Line, Column, To_String (R.Expected), Quote (Text));
            end if;
            Into.Append (To_String (R.Value));
         end;
         return;
      end if;
      declare
         S : constant Split_Result := Split_Array (Text, Of_Type.Kind in Text_Kind);
         N : constant Natural := Natural (S.Elements.Length);
      begin
         if not S.OK then
            Fail (To_String (C.File), Line, Col (S.Where), To_String (S.Expected),
                  Quote (Text (S.Where .. Text'Last)));
         end if;
         if Of_Type.Collection = Fixed_Array and then N /= Of_Type.Size then
            Fail (To_String (C.File), Line, Column,
                  "an array of exactly " & Image (Of_Type.Size) & " elements for "
                  & Image (Of_Type), Image (N) & " elements");
         elsif Of_Type.Collection = Bounded_Sequence and then N > Of_Type.Size then
            Fail (To_String (C.File), Line, Column,
                  "at most " & Image (Of_Type.Size) & " elements for " & Image (Of_Type),
                  Image (N) & " elements");
         end if;
         for I in 1 .. N loop
            declare
               E : constant Element_Span := S.Elements (I);
               Element : constant String := Text (E.First .. E.Last);
               R : constant Check_Result :=
                 Check_Scalar (Of_Type.Kind, Of_Type.String_Bound, Element);
            begin
               if not R.OK then
                  Fail (To_String (C.File), Line, Col (E.First),
                        To_String (R.Expected) & " (element" & I'Image & ")",
                        Quote (Element));
               end if;
               Into.Append (To_String (R.Value));
            end;
         end loop;
      end;
   end Check_Default;

   function Content_End (L : String) return Natural is
      --  The last character before a comment '#'. A '#' inside a quoted
      --  value does not start a comment; a quote opens a value only after a
      --  blank, '=', '[' or ','.
      I     : Natural := L'First;
      Quote : Character := ' ';
   begin
      while I <= L'Last loop
         if Quote /= ' ' then
            if L (I) = '\' then
               I := I + 1;
            elsif L (I) = Quote then
               Quote := ' ';
            end if;
         elsif L (I) = '#' then
            return I - 1;
         elsif L (I) in ''' | '"'
           and then (I = L'First or else L (I - 1) in ' ' | ASCII.HT | '=' | '[' | ',')
         then
            Quote := L (I);
         end if;
         I := I + 1;
      end loop;
      return L'Last;
   end Content_End;

   type Token (Length : Natural) is record
      Text   : String (1 .. Length);
      Column : Positive;
   end record;
   --  A word of a definition line and the column where it starts (for the
   --  messages); an empty one stands where a word is missing.

   procedure Add_Constant
     (C                       : Context;
      Def                     : in out Message_Definition;
      Line                    : Positive;
      Type_Token, Name, Value : Token)
   --  "<type> <NAME>=<value>"; Value is trimmed (empty when missing).
   is
      File : constant String := To_String (C.File);
      T    : constant Field_Type := Parse_Type (C, Type_Token.Text, Line, Type_Token.Column);
   begin
      if T.Kind = Message_Kind or else T.Collection /= Single or else T.String_Bound /= 0 then
         Fail (File, Line, Type_Token.Column,
               "a primitive, string or wstring type for a constant", Quote (Type_Token.Text));
      elsif Name.Length = 0 then
         Fail (File, Line, Name.Column, "a constant name before '='", "'='");
      elsif not Is_Valid_Constant_Name (Name.Text) then
         Fail (File, Line, Name.Column,
               "a constant name ([A-Z][A-Z0-9_]*, no '__' or trailing '_')", Quote (Name.Text));
      end if;
      for K of Def.Constants loop
         if K.Name = Name.Text then
            Fail (File, Line, Name.Column, "a new constant name",
                  Quote (Name.Text) & " (already defined at line" & K.Position.Line'Image & ")");
         end if;
      end loop;
      if Value.Length = 0 then
         Fail (File, Line, Value.Column, "a constant value after '='", "end of line");
      end if;
      declare
         R : constant Check_Result := Check_Scalar (T.Kind, 0, Value.Text);
      begin
         if not R.OK then
            Fail (File, Line, Value.Column, To_String (R.Expected), Quote (Value.Text));
         end if;
         Def.Constants.Append
           (Constant_Definition'(Name     => To_Unbounded_String (Name.Text),
                                 Kind     => T.Kind,
                                 Value    => R.Value,
                                 Position => (C.File, Line, Name.Column)));
      end;
   end Add_Constant;

   procedure Add_Field
     (C                       : Context;
      Def                     : in out Message_Definition;
      Line                    : Positive;
      Type_Token, Name, Value : Token)
   --  "<type> <name> [<default>]"; Value is trimmed (empty when there is none).
   is
      File : constant String := To_String (C.File);
      F    : Field;
   begin
      F.Of_Type := Parse_Type (C, Type_Token.Text, Line, Type_Token.Column);
      if not Is_Valid_Field_Name (Name.Text) then
         Fail (File, Line, Name.Column,
               "a field name ([a-z][a-z0-9_]*, no '__' or trailing '_')", Quote (Name.Text));
      elsif Is_Reserved_Name (Name.Text) then
         Fail (File, Line, Name.Column, "a field name that is not a reserved word",
               Quote (Name.Text));
      end if;
      for G of Def.Fields loop
         if G.Name = Name.Text then
            Fail (File, Line, Name.Column, "a new field name",
                  Quote (Name.Text) & " (already defined at line" & G.Position.Line'Image & ")");
         end if;
      end loop;
      F.Name := To_Unbounded_String (Name.Text);
      F.Position := (C.File, Line, Name.Column);
      if Value.Length > 0 then
         Check_Default (C, F.Of_Type, Value.Text, Line, Value.Column, F.Default);
      end if;
      Def.Fields.Append (F);
   end Add_Field;

   procedure Parse_Line
     (C    : Context;
      Line : Line_Record;
      Def  : in out Message_Definition)
   --  One line: blank, a comment, a constant or a field. The line is cut in
   --  tokens (type, name, then '=' and a value, or a default value) and
   --  each token's column is kept for the messages.
   is
      Full : constant String := To_String (Line.Text);
      L    : constant String := Full (Full'First .. Content_End (Full));
      Last : Natural := L'Last;
      I    : Positive := L'First;
      N    : constant Positive := Line.Number;

      function Col (J : Positive) return Positive is (J - Full'First + 1);

      function Word (First : Positive; Last : Natural) return Token is
        ((Length => Natural'Max (0, Last - First + 1), Text => L (First .. Last),
          Column => Col (First)));
      --  The word L (First .. Last) (empty when Last < First).

      procedure Skip_Blanks is
      begin
         while I <= Last and then Is_Blank (L (I)) loop
            I := I + 1;
         end loop;
      end Skip_Blanks;

      Type_First, Type_Last, Name_First, Name_Last : Positive;
   begin
      while Last >= L'First and then Is_Blank (L (Last)) loop
         Last := Last - 1;
      end loop;
      Skip_Blanks;
      if I > Last then
         return;  --  blank or comment line
      end if;

      Type_First := I;
      while I <= Last and then not Is_Blank (L (I)) loop
         I := I + 1;
      end loop;
      Type_Last := I - 1;
      if L (Type_First .. Type_Last) = "---" then
         Fail (To_String (C.File), N, Col (Type_First),
               "a field or a constant ('---' only separates .srv and .action parts)",
               "'---'");
      end if;

      Skip_Blanks;
      if I > Last then
         Fail (To_String (C.File), N, Col (I),
               "a field or constant name after the type "
               & Quote (L (Type_First .. Type_Last)), "end of line");
      end if;
      Name_First := I;
      while I <= Last and then not Is_Blank (L (I)) and then L (I) /= '=' loop
         I := I + 1;
      end loop;
      Name_Last := I - 1;
      Skip_Blanks;

      if I <= Last and then L (I) = '=' then
         I := I + 1;
         Skip_Blanks;
         Add_Constant (C, Def, N, Word (Type_First, Type_Last), Word (Name_First, Name_Last),
                       Word (I, Last));
      else
         Add_Field (C, Def, N, Word (Type_First, Type_Last), Word (Name_First, Name_Last),
                    Word (I, Last));
      end if;
   end Parse_Line;

   function Parse_Section
     (C     : Context;
      Lines : Line_Vectors.Vector;
      From  : Positive;
      To    : Natural) return Message_Definition
   is
      Def : Message_Definition;
   begin
      Def.Package_Name := C.Package_Name;
      Def.Name := C.Name;
      Def.Namespace := C.Namespace;
      Def.Position :=
        (File   => C.File,
         Line   => (if From <= To then Lines.Element (From).Number else 1),
         Column => 1);
      for I in From .. To loop
         Parse_Line (C, Lines (I), Def);
      end loop;
      if Def.Fields.Is_Empty then
         Def.Fields.Append
           (Field'(Name     => To_Unbounded_String (Empty_Member_Name),
             Of_Type  => (Kind => UInt8_Kind, others => <>),
             Default  => String_Vectors.Empty_Vector,
             Position => (C.File, 0, 0)));
      end if;
      return Def;
   end Parse_Section;

   function Default_File (Package_Name, Kind, Name, Extension : String) return String is
     (Package_Name & "/" & Kind & "/" & Name & "." & Extension);

   procedure Check_Names (Package_Name, Name, File : String) is
   begin
      if not Is_Valid_Package_Name (Package_Name) then
         Fail (File, 1, 1, "a package name ([a-z][a-z0-9_]*, no '__' or trailing '_')",
               Quote (Package_Name));
      elsif not Is_Valid_Type_Name (Name) then
         Fail (File, 1, 1, "an interface name of the form [A-Z][A-Za-z0-9]*", Quote (Name));
      end if;
   end Check_Names;

   ---------------------------------------------------------------------------

   function Search_Path_Resolver
     (Package_Name, Name : String; Where : Source_Position)
      return Message_Access
   is
      pragma Unreferenced (Where);
   begin
      return ROSIDL.Interfaces.Message (Package_Name, Name);
   exception
      when Unknown_Type =>
         return null;
   end Search_Path_Resolver;

   function Parse_Part
     (Whole  : Context;
      Suffix : String;
      Lines  : Line_Vectors.Vector;
      From   : Positive;
      To     : Natural) return Message_Access
   is
     (new Message_Definition'
        (Parse_Section ((Whole with delta Name => Whole.Name & Suffix), Lines, From, To)));
   --  Lines From .. To of a service or an action (Whole) parsed as its
   --  message NAME & Suffix ("_Request", "_Goal", ...).

   function Parse_Message
     (Package_Name, Name, Text : String;
      File    : String := "";
      Resolve : not null Resolver := Search_Path_Resolver'Access)
      return Message_Access
   is
      File_Name : constant String :=
        (if File = "" then Default_File (Package_Name, "msg", Name, "msg") else File);
      C : constant Context :=
        (File => To_Unbounded_String (File_Name),
         Package_Name => To_Unbounded_String (Package_Name),
         Name => To_Unbounded_String (Name), Namespace => Msg, Resolve => Resolve);
      Lines : constant Line_Vectors.Vector := Split_Lines (Text);
   begin
      Check_Names (Package_Name, Name, File_Name);
      return new Message_Definition'(Parse_Section (C, Lines, 1, Lines.Last_Index));
   end Parse_Message;

   function Parse_Service
     (Package_Name, Name, Text : String;
      File    : String := "";
      Resolve : not null Resolver := Search_Path_Resolver'Access)
      return Service_Access
   is
      File_Name : constant String :=
        (if File = "" then Default_File (Package_Name, "srv", Name, "srv") else File);
      Lines : constant Line_Vectors.Vector := Split_Lines (Text);
      Separator : Natural := 0;

      Whole : constant Context :=
        (File => To_Unbounded_String (File_Name),
         Package_Name => To_Unbounded_String (Package_Name),
         Name => To_Unbounded_String (Name), Namespace => Srv, Resolve => Resolve);
   begin
      Check_Names (Package_Name, Name, File_Name);
      for I in 1 .. Lines.Last_Index loop
         if Is_Separator (Lines (I)) then
            if Separator /= 0 then
               Fail (File_Name, Lines (I).Number, 1,
                     "one line '---' in a service",
                     "a second '---' (the first is at line"
                     & Lines (Separator).Number'Image & ")");
            end if;
            Separator := I;
         end if;
      end loop;
      if Separator = 0 then
         Fail (File_Name, Lines.Last_Index + 1, 1,
               "a line '---' between request and response",
               "end of file");
      end if;
      declare
         Request  : constant Message_Access :=
           Parse_Part (Whole, "_Request", Lines, 1, Separator - 1);
         Response : constant Message_Access :=
           Parse_Part (Whole, "_Response", Lines, Separator + 1, Lines.Last_Index);
      begin
         return new Service_Definition'
           (Package_Name => To_Unbounded_String (Package_Name),
            Name         => To_Unbounded_String (Name),
            Request      => Request,
            Response     => Response);
      end;
   end Parse_Service;

   function Parse_Action
     (Package_Name, Name, Text : String;
      File    : String := "";
      Resolve : not null Resolver := Search_Path_Resolver'Access)
      return Action_Access
   is
      File_Name : constant String :=
        (if File = "" then Default_File (Package_Name, "action", Name, "action") else File);
      Lines : constant Line_Vectors.Vector := Split_Lines (Text);
      Separators : array (1 .. 2) of Natural := [0, 0];
      Count : Natural := 0;
      Origin : constant Source_Position := (To_Unbounded_String (File_Name), 1, 1);

      Whole : constant Context :=
        (File => To_Unbounded_String (File_Name),
         Package_Name => To_Unbounded_String (Package_Name),
         Name => To_Unbounded_String (Name), Namespace => Action, Resolve => Resolve);

      function Needed (Pkg, Type_Name : String) return Message_Access is
         M : constant Message_Access := Resolve (Pkg, Type_Name, Origin);
      begin
         if M = null then
            Fail (File_Name, 1, 1,
                  Pkg & "/msg/" & Type_Name & " on the interface search path (every action"
                  & " needs it)", "none");
         end if;
         return M;
      end Needed;

      function Nested (Field_Name : String; M : Message_Access) return Field is
        ((Name     => To_Unbounded_String (Field_Name),
          Of_Type  => (Kind => Message_Kind, Nested => M, others => <>),
          Default  => String_Vectors.Empty_Vector,
          Position => Origin));

      function Primitive (Field_Name : String; Kind : Primitive_Kind) return Field is
        ((Name     => To_Unbounded_String (Field_Name),
          Of_Type  => (Kind => Kind, others => <>),
          Default  => String_Vectors.Empty_Vector,
          Position => Origin));

      function Derived (Suffix : String; A, B : Field) return Message_Access is
         Def : Message_Definition;
      begin
         Def.Package_Name := To_Unbounded_String (Package_Name);
         Def.Name := To_Unbounded_String (Name & Suffix);
         Def.Namespace := Action;
         Def.Position := Origin;
         Def.Fields.Append (A);
         Def.Fields.Append (B);
         return new Message_Definition'(Def);
      end Derived;

   begin
      Check_Names (Package_Name, Name, File_Name);
      for I in 1 .. Lines.Last_Index loop
         if Is_Separator (Lines (I)) then
            if Count = 2 then
               Fail (File_Name, Lines (I).Number, 1,
                     "two lines '---' in an action (goal, result, feedback)",
                     "a third '---'");
            end if;
            Count := Count + 1;
            Separators (Count) := I;
         end if;
      end loop;
      if Count < 2 then
         Fail (File_Name, Lines.Last_Index + 1, 1,
               "two lines '---' in an action (goal, result, feedback)",
               (if Count = 0 then "none" else "one") & " before the end of file");
      end if;
      declare
         Goal     : constant Message_Access :=
           Parse_Part (Whole, "_Goal", Lines, 1, Separators (1) - 1);
         Result   : constant Message_Access :=
           Parse_Part (Whole, "_Result", Lines, Separators (1) + 1, Separators (2) - 1);
         Feedback : constant Message_Access :=
           Parse_Part (Whole, "_Feedback", Lines, Separators (2) + 1, Lines.Last_Index);
         UUID     : constant Message_Access := Needed ("unique_identifier_msgs", "UUID");
         Time     : constant Message_Access := Needed ("builtin_interfaces", "Time");
         Goal_Id  : constant Field := Nested ("goal_id", UUID);
         Send_Goal : constant Service_Access := new Service_Definition'
           (Package_Name => To_Unbounded_String (Package_Name),
            Name         => To_Unbounded_String (Name & "_SendGoal"),
            Request      => Derived ("_SendGoal_Request", Goal_Id, Nested ("goal", Goal)),
            Response     => Derived ("_SendGoal_Response", Primitive ("accepted", Bool_Kind),
                                     Nested ("stamp", Time)));
         Get_Result_Request : Message_Definition;
         Get_Result : Service_Access;
      begin
         Get_Result_Request.Package_Name := To_Unbounded_String (Package_Name);
         Get_Result_Request.Name := To_Unbounded_String (Name & "_GetResult_Request");
         Get_Result_Request.Namespace := Action;
         Get_Result_Request.Position := Origin;
         Get_Result_Request.Fields.Append (Goal_Id);
         Get_Result := new Service_Definition'
           (Package_Name => To_Unbounded_String (Package_Name),
            Name         => To_Unbounded_String (Name & "_GetResult"),
            Request      => new Message_Definition'(Get_Result_Request),
            Response     => Derived ("_GetResult_Response", Primitive ("status", Int8_Kind),
                                     Nested ("result", Result)));
         return new Action_Definition'
           (Package_Name     => To_Unbounded_String (Package_Name),
            Name             => To_Unbounded_String (Name),
            Goal             => Goal,
            Result           => Result,
            Feedback         => Feedback,
            Send_Goal        => Send_Goal,
            Get_Result       => Get_Result,
            Feedback_Message =>
              Derived ("_FeedbackMessage", Goal_Id, Nested ("feedback", Feedback)));
      end;
   end Parse_Action;

end ROSIDL.Parser;
