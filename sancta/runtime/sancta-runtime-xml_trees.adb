with Ada.Containers.Indefinite_Vectors;
with Ada.Directories;
with Ada.Text_IO;
with Ada.Exceptions;
with Input_Sources.File;
with Sax.Exceptions;
with Sax.Locators;
with Sax.Readers;
with Sax.Symbols;
with Sax.Utils;
with Unicode.CES;

package body Sancta.Runtime.XML_Trees is

   function Trim (N : Natural) return String is
      S : constant String := N'Image;
   begin
      return S (S'First + 1 .. S'Last);
   end Trim;

   function Image (Where : Position) return String is
     (To_String (Where.File) & ":" & Trim (Where.Line) & ":" & Trim (Where.Column));

   package Line_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   type Builder is new Sax.Readers.Sax_Reader with record
      File   : Unbounded_String;
      Lines  : Line_Vectors.Vector;
      --  The file's text, to find where start tags begin.
      Result : Tree;
      Stack  : Element_Vectors.Vector;
      Error_Where : Position;
      Error_Text  : Unbounded_String;
   end record;

   overriding procedure Start_Element
     (Handler    : in out Builder;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol;
      Atts       : Sax.Readers.Sax_Attribute_List);

   overriding procedure End_Element
     (Handler    : in out Builder;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol);

   overriding procedure Fatal_Error
     (Handler : in out Builder;
      Except  : Sax.Exceptions.Sax_Parse_Exception'Class);

   overriding procedure Start_DTD
     (Handler   : in out Builder;
      Name      : Unicode.CES.Byte_Sequence;
      Public_Id : Unicode.CES.Byte_Sequence := "";
      System_Id : Unicode.CES.Byte_Sequence := "");

   function To_Position (File : Unbounded_String; L : Sax.Locators.Location) return Position is
     ((File => File, Line => L.Line, Column => L.Column));

   function Tag_Start (Handler : Builder; Tag_End : Sax.Locators.Location) return Position is
      --  The parser reports the position just after a start tag's ">"; the
      --  element is reported where its "<" is (no "<" can occur inside a
      --  start tag of a well-formed document).
      Line   : Natural := Tag_End.Line;
      Column : Integer := Tag_End.Column - 1;
   begin
      while Line in 1 .. Natural (Handler.Lines.Length) loop
         declare
            Text : String renames Handler.Lines (Line);
            --  No copy: a one-line file must not cost its length per element.
         begin
            Column := Integer'Min (Column, Text'Length);
            while Column >= 1 loop
               if Text (Text'First + Column - 1) = '<' then
                  return (Handler.File, Line, Column);
               end if;
               Column := Column - 1;
            end loop;
         end;
         Line := Line - 1;
         Column := Integer'Last;
      end loop;
      return To_Position (Handler.File, Tag_End);
   end Tag_Start;

   Parse_Failed : exception;

   overriding procedure Start_DTD
     (Handler   : in out Builder;
      Name      : Unicode.CES.Byte_Sequence;
      Public_Id : Unicode.CES.Byte_Sequence := "";
      System_Id : Unicode.CES.Byte_Sequence := "")
   is
      pragma Unreferenced (Name, Public_Id, System_Id);
   begin
      Handler.Error_Where := To_Position (Handler.File, Handler.Current_Location);
      Handler.Error_Where.Column := Natural'Max (1, Handler.Error_Where.Column);
      Handler.Error_Text := To_Unbounded_String
        ("a DOCTYPE declaration is not allowed (no DTD, no entities)");
      raise Parse_Failed;
   end Start_DTD;

   overriding procedure Start_Element
     (Handler    : in out Builder;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol;
      Atts       : Sax.Readers.Sax_Attribute_List)
   is
      pragma Unreferenced (NS);
      New_Element : Element;
      Id : Element_Id;

      procedure Refuse (Where : Position; Text : String) is
      begin
         Handler.Error_Where := Where;
         Handler.Error_Text := To_Unbounded_String (Text);
         raise Parse_Failed;
      end Refuse;
   begin
      if Natural (Handler.Stack.Length) >= Max_Depth then
         Refuse (Tag_Start (Handler, Handler.Current_Location),
                 "elements nested deeper than" & Natural'Image (Max_Depth));
      elsif Natural (Handler.Result.Elements.Length) >= Max_Elements then
         Refuse (Tag_Start (Handler, Handler.Current_Location),
                 "more than" & Natural'Image (Max_Elements) & " elements");
      end if;
      New_Element.Name := To_Unbounded_String (Sax.Symbols.Get (Local_Name).all);
      New_Element.Where := Tag_Start (Handler, Handler.Current_Location);
      for I in 1 .. Sax.Readers.Get_Length (Atts) loop
         declare
            Name  : constant Unicode.CES.Cst_Byte_Sequence_Access :=
              Sax.Symbols.Get (Sax.Readers.Get_Name (Atts, I).Local);
            Value : constant Unicode.CES.Cst_Byte_Sequence_Access :=
              Sax.Symbols.Get (Sax.Readers.Get_Value (Atts, I));
            Where : constant Position :=
              To_Position (Handler.File, Sax.Readers.Get_Location (Atts, I));
         begin
            if Value'Length > Max_Attribute_Size then
               Refuse (Where, "attribute " & Name.all & " of" & Value'Length'Image
                       & " bytes exceeds the limit of" & Natural'Image (Max_Attribute_Size));
            elsif (for some A of New_Element.Attributes => A.Name = Name.all) then
               Refuse (Where, "attribute " & Name.all & " given twice");
            end if;
            New_Element.Attributes.Append
              (Attribute'(Name  => To_Unbounded_String (Name.all),
                          Value => To_Unbounded_String (Value.all),
                          Where => Where));
         end;
      end loop;
      Handler.Result.Elements.Append (New_Element);
      Id := Handler.Result.Elements.Last_Index;
      if not Handler.Stack.Is_Empty then
         Handler.Result.Elements (Handler.Stack.Last_Element).Children.Append (Id);
      end if;
      Handler.Stack.Append (Id);
   end Start_Element;

   overriding procedure End_Element
     (Handler    : in out Builder;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol)
   is
      pragma Unreferenced (NS, Local_Name);
   begin
      Handler.Stack.Delete_Last;
   end End_Element;

   function Strip_Location (Text : String) return String is
      --  XML/Ada starts its messages with "[file]:line:column: ": drop it,
      --  the diagnostic carries the position already.
      I : Natural := Text'First;
      Colons : Natural := 0;
   begin
      while I <= Text'Last and then Text (I) /= ' ' loop
         if Text (I) = ':' then
            Colons := Colons + 1;
         end if;
         I := I + 1;
      end loop;
      if Colons >= 3 and then I > Text'First and then Text (I - 1) = ':' then
         return Text (I + 1 .. Text'Last);
      end if;
      return Text;
   end Strip_Location;

   overriding procedure Fatal_Error
     (Handler : in out Builder;
      Except  : Sax.Exceptions.Sax_Parse_Exception'Class) is
   begin
      Handler.Error_Where := To_Position (Handler.File, Sax.Exceptions.Get_Location (Except));
      Handler.Error_Where.Column := Natural'Max (1, Handler.Error_Where.Column);
      Handler.Error_Where.Line := Natural'Max (1, Handler.Error_Where.Line);
      Handler.Error_Text :=
        To_Unbounded_String (Strip_Location (Sax.Exceptions.Get_Message (Except)));
      raise Parse_Failed;
   end Fatal_Error;

   procedure Load (File : String; Result : out Tree; Error : out Load_Error) is
      Input   : Input_Sources.File.File_Input;
      Handler : Builder;
      Opened  : Boolean := False;

      procedure Fail (Where : Position; Text : String) is
      begin
         Error := (Failed => True, Where => Where, Text => To_Unbounded_String (Text));
      end Fail;

      Start : constant Position := (To_Unbounded_String (File), 1, 1);
   begin
      Error := (Failed => False, Where => Start, Text => Null_Unbounded_String);
      Result := (Elements => Element_Stores.Empty_Vector);
      if not Ada.Directories.Exists (File) then
         Fail (Start, "cannot open: no such file");
         return;
      elsif Ada.Directories."/=" (Ada.Directories.Kind (File), Ada.Directories.Ordinary_File)
      then
         Fail (Start, "cannot read: not a regular file");
         return;
      end if;
      if Ada.Directories.">" (Ada.Directories.Size (File), Max_File_Size) then
         Fail (Start, "file of" & Ada.Directories.File_Size'Image (Ada.Directories.Size (File))
               & " bytes exceeds the limit of" & Natural'Image (Max_File_Size));
         return;
      end if;
      Handler.File := To_Unbounded_String (File);
      declare
         F : Ada.Text_IO.File_Type;
      begin
         Ada.Text_IO.Open (F, Ada.Text_IO.In_File, File);
         while not Ada.Text_IO.End_Of_File (F) loop
            --  In chunks: Text_IO's Get_Line function overflows the stack
            --  on a line of megabytes (a file may be minified XML).
            declare
               Chunk : String (1 .. 4096);
               Last  : Natural;
               Line  : Unbounded_String;
            begin
               loop
                  Ada.Text_IO.Get_Line (F, Chunk, Last);
                  Append (Line, Chunk (1 .. Last));
                  exit when Last < Chunk'Last or else Ada.Text_IO.End_Of_File (F);
               end loop;
               Handler.Lines.Append (To_String (Line));
            end;
         end loop;
         Ada.Text_IO.Close (F);
      exception
         when E : others =>
            if Ada.Text_IO.Is_Open (F) then
               Ada.Text_IO.Close (F);
            end if;
            Fail (Start, "cannot read: " & Ada.Exceptions.Exception_Name (E));
            return;
      end;
      Input_Sources.File.Open (File, Input);
      Opened := True;
      Handler.Set_Feature (Sax.Readers.Namespace_Feature, False);
      Handler.Parse (Input);
      Input_Sources.File.Close (Input);
      if Handler.Result.Elements.Is_Empty then
         Fail (Start, "malformed XML: no root element");
         return;
      end if;
      Result := Handler.Result;
   exception
      when Parse_Failed =>
         Input_Sources.File.Close (Input);
         Fail (Handler.Error_Where, "malformed XML: " & To_String (Handler.Error_Text));
      when E : others =>
         --  XML/Ada's own exceptions (bad encodings, I/O): no position.
         if Opened then
            Input_Sources.File.Close (Input);
         end if;
         Fail (Start, "cannot read: " & Ada.Exceptions.Exception_Name (E) & ": "
               & Strip_Location (Ada.Exceptions.Exception_Message (E)));
   end Load;

   procedure Load (File : String; Result : out Tree) is
      Error : Load_Error;
   begin
      Load (File, Result, Error);
      if Error.Failed then
         raise Configuration_Error with Image (Error.Where) & ": " & To_String (Error.Text);
      end if;
   end Load;

   function Root (This : Tree) return Element_Id is (This.Elements.First_Index);

   function Name (This : Tree; E : Element_Id) return String is
     (To_String (This.Elements (E).Name));

   function Where (This : Tree; E : Element_Id) return Position is (This.Elements (E).Where);

   function Children (This : Tree; E : Element_Id) return Element_Vectors.Vector is
     (This.Elements (E).Children);

   function Attributes (This : Tree; E : Element_Id) return Attribute_Vectors.Vector is
     (This.Elements (E).Attributes);

   function Has_Attribute (This : Tree; E : Element_Id; Name : String) return Boolean is
     (for some A of This.Elements (E).Attributes => A.Name = Name);

   function Attribute_Value (This : Tree; E : Element_Id; Name : String) return String is
   begin
      for A of This.Elements (E).Attributes loop
         if A.Name = Name then
            return To_String (A.Value);
         end if;
      end loop;
      return "";
   end Attribute_Value;

   function Attribute_Where (This : Tree; E : Element_Id; Name : String) return Position is
   begin
      for A of This.Elements (E).Attributes loop
         if A.Name = Name then
            return A.Where;
         end if;
      end loop;
      return This.Elements (E).Where;
   end Attribute_Where;

end Sancta.Runtime.XML_Trees;
