with Ada.Strings.UTF_Encoding.Wide_Wide_Strings;
with Ada.Unchecked_Conversion;
with Ada.Unchecked_Deallocation;
with ROSIDL.Dynamic.Images;
with Interfaces;
with System.Address_To_Access_Conversions;
with System.Storage_Elements;

package body ROSIDL.Dynamic is

   use System.Storage_Elements;
   use type System.Address;
   use type Text_Vectors.Vector;
   use type Wide_Text_Vectors.Vector;

   procedure Free_Words is new Ada.Unchecked_Deallocation
     (Word_Array, Word_Access);
   procedure Free_Node is new Ada.Unchecked_Deallocation (Node, Node_Access);
   procedure Free_Extra is new Ada.Unchecked_Deallocation (Cell_Extra, Extra_Access);

   --  Access types used to designate elements inside Word_Array storage;
   --  they alias the words, so strict aliasing is off for them.

   type Bool_Access is access all Bool;
   type UInt8_Access is access all UInt8;
   type Int8_Access is access all Int8;
   type Int16_Access is access all Int16;
   type UInt16_Access is access all UInt16;
   type Int32_Access is access all Int32;
   type UInt32_Access is access all UInt32;
   type Int64_Access is access all Int64;
   type UInt64_Access is access all UInt64;
   type Float32_Access is access all Float32;
   type Float64_Access is access all Float64;
   pragma No_Strict_Aliasing (Bool_Access);
   pragma No_Strict_Aliasing (UInt8_Access);
   pragma No_Strict_Aliasing (Int8_Access);
   pragma No_Strict_Aliasing (Int16_Access);
   pragma No_Strict_Aliasing (UInt16_Access);
   pragma No_Strict_Aliasing (Int32_Access);
   pragma No_Strict_Aliasing (UInt32_Access);
   pragma No_Strict_Aliasing (Int64_Access);
   pragma No_Strict_Aliasing (UInt64_Access);
   pragma No_Strict_Aliasing (Float32_Access);
   pragma No_Strict_Aliasing (Float64_Access);

   function To_Bool is new Ada.Unchecked_Conversion (System.Address, Bool_Access);
   function To_UInt8 is new Ada.Unchecked_Conversion (System.Address, UInt8_Access);
   function To_Int8 is new Ada.Unchecked_Conversion (System.Address, Int8_Access);
   function To_Int16 is new Ada.Unchecked_Conversion (System.Address, Int16_Access);
   function To_UInt16 is new Ada.Unchecked_Conversion
     (System.Address, UInt16_Access);
   function To_Int32 is new Ada.Unchecked_Conversion (System.Address, Int32_Access);
   function To_UInt32 is new Ada.Unchecked_Conversion
     (System.Address, UInt32_Access);
   function To_Int64 is new Ada.Unchecked_Conversion (System.Address, Int64_Access);
   function To_UInt64 is new Ada.Unchecked_Conversion
     (System.Address, UInt64_Access);
   function To_Float32 is new Ada.Unchecked_Conversion
     (System.Address, Float32_Access);
   function To_Float64 is new Ada.Unchecked_Conversion
     (System.Address, Float64_Access);

   ---------------------------------------------------------------------
   -- Names and errors --
   ---------------------------------------------------------------------

   function Field_Name (Cell : Field_Cell) return String is
     (To_String (Cell.Owner.Def.Fields (Cell.Field).Name));

   function Owner_Name (Cell : Field_Cell) return String is
     (Full_Name (Cell.Owner.Def.all));

   function Trimmed (N : Integer) return String is
      S : constant String := N'Image;
   begin
      return (if S (S'First) = ' ' then S (S'First + 1 .. S'Last) else S);
   end Trimmed;

   function Ref_Name (This : Field_Ref'Class) return String is
     (Field_Name (This.Cell.all)
      & (if This.Index > 0 and then Cell_Type (This.Cell.all).Collection /= Single
         then "[" & Trimmed (This.Index - 1) & "]" else ""));

   procedure Raise_Field_Error (Cell : Field_Cell; Name, Text : String)
     with No_Return
   is
   begin
      raise Field_Error with Owner_Name (Cell) & " field """ & Name & """: " & Text
        & "; valid fields: " & Field_Names (Cell.Owner.Def.all);
   end Raise_Field_Error;

   ---------------------------------------------------------------------
   -- Storage --
   ---------------------------------------------------------------------

   function Element_Size (T : Field_Type) return Natural is
     (if T.Kind in Primitive_Kind then Primitive_Size (T.Kind) else 0);

   function New_Words (Bytes : Natural) return Word_Access is
     (if Bytes = 0 then null
      else new Word_Array'(0 .. (Bytes - 1) / 8 => 0));

   function Element_Address
     (Cell : Field_Cell; Index : Positive) return System.Address is
   begin
      return Cell.Prims.all'Address
        + Storage_Offset ((Index - 1) * Element_Size (Cell_Type (Cell)));
   end Element_Address;

   procedure Set_Count (Cell : in out Field_Cell; Count : Natural) is
      T : constant Field_Type := Cell_Type (Cell);
   begin
      case T.Kind is
         when Primitive_Kind =>
            declare
               Size      : constant Natural := Element_Size (T);
               New_Bytes : constant Natural := Count * Size;
               Old_Bytes : constant Natural := Cell.Count * Size;
               Fresh     : Word_Access := New_Words (New_Bytes);
               Keep      : constant Natural := Natural'Min (Old_Bytes, New_Bytes);
            begin
               if Keep > 0 then
                  declare
                     Src : Storage_Array (1 .. Storage_Offset (Keep))
                       with Import, Address => Cell.Prims.all'Address;
                     Dst : Storage_Array (1 .. Storage_Offset (Keep))
                       with Import, Address => Fresh.all'Address;
                  begin
                     Dst := Src;
                  end;
               end if;
               Free_Words (Cell.Prims);
               Cell.Prims := Fresh;
               Fresh := null;
            end;
         when String_Kind =>
            Cell.Extra.Texts.Set_Length (Ada.Containers.Count_Type (Count));
         when WString_Kind =>
            Cell.Extra.WTexts.Set_Length (Ada.Containers.Count_Type (Count));
         when Message_Kind =>
            while Natural (Cell.Extra.Nodes.Length) > Count loop
               declare
                  Last : Node_Access := Cell.Extra.Nodes.Last_Element;
               begin
                  Free (Last);
                  Cell.Extra.Nodes.Delete_Last;
               end;
            end loop;
            while Natural (Cell.Extra.Nodes.Length) < Count loop
               Cell.Extra.Nodes.Append (New_Node (T.Nested));
            end loop;
      end case;
      Cell.Count := Count;
   end Set_Count;

   --  Default values (already validated by the parser).

   function Float_Text (S : String) return String is
      --  Ada's 'Value wants digits on both sides of the point.
      R : Unbounded_String;
   begin
      for I in S'Range loop
         if S (I) = '.'
           and then (I = S'First or else S (I - 1) not in '0' .. '9')
         then
            Append (R, "0.");
         elsif S (I) = '.'
           and then (I = S'Last or else S (I + 1) not in '0' .. '9')
         then
            Append (R, ".0");
         else
            Append (R, S (I));
         end if;
      end loop;
      return To_String (R);
   end Float_Text;

   function Is_Integer_Text (S : String) return Boolean is
     (for all C of S => C in '0' .. '9' | '-' | '+');

   function Is_NaN_Text (S : String) return Boolean is
     (S = "nan" or else S = "+nan" or else S = "-nan");

   function Is_Non_Finite_Text (S : String) return Boolean is
     (Is_NaN_Text (S) or else S = "inf" or else S = "+inf" or else S = "-inf");
   --  The parser's normalised nan and infinities. Such values cannot flow
   --  through Ada code built with validity checks (-gnatVa): they are
   --  stored as IEEE bits, read with Is_NaN / Image.

   function To_Float64 (S : String) return Float64 is
      T : constant String := Float_Text (S);
   begin
      if Is_Non_Finite_Text (T) then
         raise Constraint_Error with "not a finite number";
      elsif Is_Integer_Text (T) then
         return Float64 (Long_Long_Integer'Value (T));
      else
         return Float64'Value (T);
      end if;
   end To_Float64;

   function From_UTF_8 (Text : String) return Wide_Wide_String is
     (Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode (Text));
   --  Interface files are UTF-8 (as rosidl reads them): wstring texts are
   --  decoded, not taken byte by byte as Latin-1.

   Encoding_Error : exception renames Ada.Strings.UTF_Encoding.Encoding_Error;

   procedure Set_Primitive_Text
     (Cell : Field_Cell; Index : Positive; Text : String)
   is
      A : constant System.Address := Element_Address (Cell, Index);
   begin
      case Primitive_Kind'(Cell_Type (Cell).Kind) is
         when Bool_Kind =>
            To_Bool (A).all := Text = "true" or else Text = "1";
         when Byte_Kind | Char_Kind | UInt8_Kind =>
            To_UInt8 (A).all := UInt8'Value (Text);
         when Int8_Kind   => To_Int8 (A).all := Int8'Value (Text);
         when Int16_Kind  => To_Int16 (A).all := Int16'Value (Text);
         when UInt16_Kind => To_UInt16 (A).all := UInt16'Value (Text);
         when Int32_Kind  => To_Int32 (A).all := Int32'Value (Text);
         when UInt32_Kind => To_UInt32 (A).all := UInt32'Value (Text);
         when Int64_Kind  => To_Int64 (A).all := Int64'Value (Text);
         when UInt64_Kind => To_UInt64 (A).all := UInt64'Value (Text);
         when Float32_Kind =>
            if Is_NaN_Text (Text) then
               To_UInt32 (A).all := 16#7FC0_0000#;  --  Quiet NaN.
            elsif Is_Non_Finite_Text (Text) then
               To_UInt32 (A).all := (if Text = "-inf" then 16#FF80_0000# else 16#7F80_0000#);
            else
               To_Float32 (A).all := Float32 (To_Float64 (Text));
            end if;
         when Float64_Kind =>
            if Is_NaN_Text (Text) then
               To_UInt64 (A).all := 16#7FF8_0000_0000_0000#;
            elsif Is_Non_Finite_Text (Text) then
               To_UInt64 (A).all :=
                 (if Text = "-inf" then 16#FFF0_0000_0000_0000# else 16#7FF0_0000_0000_0000#);
            else
               To_Float64 (A).all := To_Float64 (Text);
            end if;
      end case;
   end Set_Primitive_Text;

   function New_Node (Def : not null Message_Access) return Node_Access is
      N : constant Node_Access :=
        new Node (Field_Count => Natural (Def.Fields.Length));
   begin
      N.Def := Def;
      for I in N.Cells'Range loop
         declare
            F    : Field renames Def.Fields (I);
            Cell : Field_Cell renames N.Cells (I);
            D    : constant Natural := Natural (F.Default.Length);
         begin
            Cell.Owner := N;
            Cell.Field := I;
            Cell.Of_Type := F.Of_Type;
            if F.Of_Type.Kind not in Primitive_Kind then
               Cell.Extra := new Cell_Extra;
            end if;
            Set_Count
              (Cell,
               (case F.Of_Type.Collection is
                   when Single      => 1,
                   when Fixed_Array => F.Of_Type.Size,
                   when others      => D));
            for E in 1 .. Natural'Min (D, Cell.Count) loop
               declare
                  Text : constant String := F.Default (E);
               begin
                  case F.Of_Type.Kind is
                     when Primitive_Kind =>
                        Set_Primitive_Text (Cell, E, Text);
                     when String_Kind =>
                        Cell.Extra.Texts (E) := To_Unbounded_String (Text);
                     when WString_Kind =>
                        Cell.Extra.WTexts (E) :=
                          To_Unbounded_Wide_Wide_String (From_UTF_8 (Text));
                     when Message_Kind =>
                        null;
                  end case;
               end;
            end loop;
         end;
      end loop;
      return N;
   end New_Node;

   procedure Free (N : in out Node_Access) is
   begin
      if N = null then
         return;
      end if;
      for Cell of N.Cells loop
         Free_Words (Cell.Prims);
         if Cell.Extra /= null then
            for Child of Cell.Extra.Nodes loop
               Free (Child);
            end loop;
            Free_Extra (Cell.Extra);
         end if;
      end loop;
      Free_Node (N);
   end Free;

   function Copy (N : Node_Access) return Node_Access is
   begin
      if N = null then
         return null;
      end if;
      declare
         R : constant Node_Access := new Node (N.Field_Count);
      begin
         R.Def := N.Def;
         for I in N.Cells'Range loop
            declare
               S : Field_Cell renames N.Cells (I);
               D : Field_Cell renames R.Cells (I);
            begin
               D.Owner := R;
               D.Field := I;
               D.Of_Type := S.Of_Type;
               D.Count := S.Count;
               if S.Prims /= null then
                  D.Prims := new Word_Array'(S.Prims.all);
               end if;
               if S.Extra /= null then
                  D.Extra := new Cell_Extra'(Texts  => S.Extra.Texts,
                                             WTexts => S.Extra.WTexts,
                                             Nodes  => <>);
                  for Child of S.Extra.Nodes loop
                     D.Extra.Nodes.Append (Copy (Child));
                  end loop;
               end if;
            end;
         end loop;
         return R;
      end;
   end Copy;

   function Equal (L, R : Node_Access) return Boolean is
   begin
      if L = null or else R = null then
         return L = R;
      end if;
      if L.Def /= R.Def then
         return False;
      end if;
      for I in L.Cells'Range loop
         declare
            A     : Field_Cell renames L.Cells (I);
            B     : Field_Cell renames R.Cells (I);
            Bytes : constant Natural := A.Count * Element_Size (Cell_Type (A));
         begin
            if A.Count /= B.Count then
               return False;
            end if;
            if Bytes > 0 then
               declare
                  SA : Storage_Array (1 .. Storage_Offset (Bytes))
                    with Import, Address => A.Prims.all'Address;
                  SB : Storage_Array (1 .. Storage_Offset (Bytes))
                    with Import, Address => B.Prims.all'Address;
               begin
                  if SA /= SB then
                     return False;
                  end if;
               end;
            end if;
            if A.Extra /= null then
               if A.Extra.Texts /= B.Extra.Texts or else A.Extra.WTexts /= B.Extra.WTexts
               then
                  return False;
               end if;
               for J in 1 .. Natural (A.Extra.Nodes.Length) loop
                  if not Equal (A.Extra.Nodes (J), B.Extra.Nodes (J)) then
                     return False;
                  end if;
               end loop;
            end if;
         end;
      end loop;
      return True;
   end Equal;

   ---------------------------------------------------------------------
   -- Message --
   ---------------------------------------------------------------------

   function Init (Support : Message_Support) return Message is
   begin
      return (Ada.Finalization.Controlled with
              Root => New_Node (Definition (Support)));
   end Init;

   function Is_Initialised (This : Message) return Boolean is
     (This.Root /= null);

   function Support (This : Message) return Message_Support is
     (To_Support (This.Root.Def));

   function Definition (This : Message) return Message_Access is
     (This.Root.Def);

   function Type_Name (This : Message) return String is
     (if This.Root = null then "(uninitialised message)"
      else Full_Name (This.Root.Def.all));

   overriding function "=" (Left, Right : Message) return Boolean is
     (Equal (Left.Root, Right.Root));

   overriding procedure Adjust (This : in out Message) is
   begin
      if This.Root /= null then
         if This.Root.Referenced then
            This.Root := Copy (This.Root);
         else
            System.Atomic_Counters.Increment (This.Root.Shares);
         end if;
      end if;
   end Adjust;

   overriding procedure Finalize (This : in out Message) is
   begin
      if This.Root /= null then
         if System.Atomic_Counters.Decrement (This.Root.Shares) then
            Free (This.Root);
         end if;
         This.Root := null;
      end if;
   end Finalize;

   package Message_Pointers is new System.Address_To_Access_Conversions (Message);

   --  Taking a private copy of a shared root is serialised, so that tasks
   --  reading one message object at the same time (each handing out
   --  references) do not both replace its root. The common case (an
   --  unshared root) takes no lock.
   protected Unsharing is
      procedure Unshare (This : Message'Class; Keep_Contents : Boolean);
   end Unsharing;

   protected body Unsharing is
      procedure Unshare (This : Message'Class; Keep_Contents : Boolean) is
         Old : Node_Access := This.Root;
      begin
         if System.Atomic_Counters.Is_One (Old.Shares) then
            return;  --  another task got there first
         end if;
         declare
            Mine : constant Node_Access :=
              (if Keep_Contents then Copy (Old) else New_Node (Old.Def));
         begin
            --  This is a variable even when seen as a constant (a Message
            --  is a by-reference type): only its root pointer changes.
            Message_Pointers.To_Pointer (This'Address).Root := Mine;
            if System.Atomic_Counters.Decrement (Old.Shares) then
               Free (Old);
            end if;
         end;
      end Unshare;
   end Unsharing;

   procedure Make_Unique
     (This : Message'Class; Referenced : Boolean; Keep_Contents : Boolean := True) is
   begin
      if This.Root = null then
         return;
      end if;
      if not System.Atomic_Counters.Is_One (This.Root.Shares) then
         Unsharing.Unshare (This, Keep_Contents);
      end if;
      if Referenced then
         This.Root.Referenced := True;
      end if;
   end Make_Unique;

   function Find
     (N : Node_Access; Name : String; Context : String) return Positive
   is
   begin
      if N = null then
         raise Field_Error with "field """ & Name & """ of an uninitialised "
           & "message (use ROSIDL.Dynamic.Init)";
      end if;
      declare
         I : constant Natural := Field_Index (N.Def.all, Name);
      begin
         if I = 0 then
            raise Field_Error with Full_Name (N.Def.all) & Context
              & " has no field """ & Name & """; valid fields: "
              & Field_Names (N.Def.all);
         end if;
         return I;
      end;
   end Find;

   function Reference (This : Message'Class; Name : String) return Field_Ref is
      I : constant Positive := Find (This.Root, Name, "");
   begin
      Make_Unique (This, Referenced => True);
      return (Cell => This.Root.Cells (I)'Access, Index => 0);
   end Reference;

   --  The element a reference to a single value designates.
   function Single_Index (This : Field_Ref'Class; Requested : String) return Positive is
      T : constant Field_Type := Cell_Type (This.Cell.all);
   begin
      if This.Index > 0 then
         return This.Index;
      elsif T.Collection = Single then
         return 1;
      else
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "is " & Image (T) & ", an array: requested a single " & Requested
            & " (use As_Array or a bulk accessor)");
      end if;
   end Single_Index;

   function Nested_Node (This : Field_Ref'Class; Requested : String) return Node_Access is
      T : constant Field_Type := Cell_Type (This.Cell.all);
   begin
      if T.Kind /= Message_Kind then
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "expected " & Image (T) & ", requested " & Requested);
      end if;
      return This.Cell.Extra.Nodes.Element (Single_Index (This, Requested));
   end Nested_Node;

   function Field_Reference (This : Field_Ref; Name : String) return Field_Ref is
      N : constant Node_Access := Nested_Node (This, "a nested message");
      I : constant Natural := (if N = null then 0 else Field_Index (N.Def.all, Name));
      --  The error context (Ref_Name) is only built when the look-up fails:
      --  this is on the hot path of every nested field access.
   begin
      return (Cell  => N.Cells (if I /= 0 then I
                                else Find (N, Name, " (in field """ & Ref_Name (This)
                                                    & """)"))'Access,
              Index => 0);
   end Field_Reference;

   function Name (This : Field_Ref) return String is (Ref_Name (This));

   function Field_Type_Of (This : Field_Ref) return Field_Type is
     (Cell_Type (This.Cell.all));

   function Is_Collection (This : Field_Ref) return Boolean is
     (This.Index = 0 and then Cell_Type (This.Cell.all).Collection /= Single);

   --  The address of the single primitive of kind Kind This designates.
   function Scalar_Address (This : Field_Ref'Class; Kind : Primitive_Kind; Requested : String := "")
      return System.Address
   is
      T : constant Field_Type := Cell_Type (This.Cell.all);

      function Req return String is
        (if Requested = "" then Type_Name (Kind) else Requested);
      --  Only for error texts: every scalar accessor passes here.
   begin
      if T.Kind /= Kind then
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "expected " & Image (T) & ", requested " & Req);
      end if;
      return Element_Address
        (This.Cell.all,
         (if This.Index > 0 then This.Index
          elsif T.Collection = Single then 1
          else Single_Index (This, Req)));
   end Scalar_Address;

   function As_Bool (This : Field_Ref) return Bool_Ref is
     ((Element => To_Bool (Scalar_Address (This, Bool_Kind))));
   function As_Byte (This : Field_Ref) return UInt8_Ref is
     ((Element => To_UInt8 (Scalar_Address (This, Byte_Kind))));
   function As_Char (This : Field_Ref) return UInt8_Ref is
     ((Element => To_UInt8 (Scalar_Address (This, Char_Kind))));
   function As_UInt8 (This : Field_Ref) return UInt8_Ref is
     ((Element => To_UInt8 (Scalar_Address (This, UInt8_Kind))));
   function As_Int8 (This : Field_Ref) return Int8_Ref is
     ((Element => To_Int8 (Scalar_Address (This, Int8_Kind))));
   function As_Int16 (This : Field_Ref) return Int16_Ref is
     ((Element => To_Int16 (Scalar_Address (This, Int16_Kind))));
   function As_UInt16 (This : Field_Ref) return UInt16_Ref is
     ((Element => To_UInt16 (Scalar_Address (This, UInt16_Kind))));
   function As_Int32 (This : Field_Ref) return Int32_Ref is
     ((Element => To_Int32 (Scalar_Address (This, Int32_Kind))));
   function As_UInt32 (This : Field_Ref) return UInt32_Ref is
     ((Element => To_UInt32 (Scalar_Address (This, UInt32_Kind))));
   function As_Int64 (This : Field_Ref) return Int64_Ref is
     ((Element => To_Int64 (Scalar_Address (This, Int64_Kind))));
   function As_UInt64 (This : Field_Ref) return UInt64_Ref is
     ((Element => To_UInt64 (Scalar_Address (This, UInt64_Kind))));
   function As_Float32 (This : Field_Ref) return Float32_Ref is
     ((Element => To_Float32 (Scalar_Address (This, Float32_Kind))));
   function As_Float64 (This : Field_Ref) return Float64_Ref is
     ((Element => To_Float64 (Scalar_Address (This, Float64_Kind))));

   function Is_NaN (This : Field_Ref) return Boolean is
      use type Interfaces.Unsigned_32;
      use type Interfaces.Unsigned_64;
      T : constant Field_Type := Cell_Type (This.Cell.all);
   begin
      if T.Kind = Float32_Kind then
         declare
            Bits : constant Interfaces.Unsigned_32 :=
              To_UInt32 (Scalar_Address (This, Float32_Kind, "float")).all;
         begin
            return (Bits and 16#7F80_0000#) = 16#7F80_0000#
              and then (Bits and 16#007F_FFFF#) /= 0;
         end;
      else
         declare
            Bits : constant Interfaces.Unsigned_64 :=
              To_UInt64 (Scalar_Address (This, Float64_Kind, "float")).all;
         begin
            return (Bits and 16#7FF0_0000_0000_0000#) = 16#7FF0_0000_0000_0000#
              and then (Bits and 16#000F_FFFF_FFFF_FFFF#) /= 0;
         end;
      end if;
   end Is_NaN;

   function Text_Index
     (This : Field_Ref'Class; Kind : Text_Kind; Requested : String) return Positive
   is
      T : constant Field_Type := Cell_Type (This.Cell.all);
   begin
      if T.Kind /= Kind then
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "expected " & Image (T) & ", requested " & Requested);
      end if;
      return Single_Index (This, Requested);
   end Text_Index;

   procedure Set_String (This : Field_Ref; Value : String) is
   begin
      This.Cell.Extra.Texts (Text_Index (This, String_Kind, "string")) :=
        To_Unbounded_String (Value);
   end Set_String;

   function Get_String (This : Field_Ref) return String is
     (To_String (This.Cell.Extra.Texts (Text_Index (This, String_Kind, "string"))));

   procedure Set_WString (This : Field_Ref; Value : Wide_Wide_String) is
   begin
      This.Cell.Extra.WTexts (Text_Index (This, WString_Kind, "wstring")) :=
        To_Unbounded_Wide_Wide_String (Value);
   end Set_WString;

   function Get_WString (This : Field_Ref) return Wide_Wide_String is
     (To_Wide_Wide_String
        (This.Cell.Extra.WTexts (Text_Index (This, WString_Kind, "wstring"))));

   function To_Message (This : Field_Ref'Class) return Message is
     (Ada.Finalization.Controlled with
      Root => Copy (Nested_Node (This, "a nested message")));

   procedure Set_Message (This : Field_Ref; Value : Message'Class) is
      Target : constant Positive :=
        Single_Index (This, "a nested message");
      Old    : Node_Access := Nested_Node (This, "a nested message");
   begin
      if Value.Root = null or else Value.Root.Def /= Old.Def then
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "expected " & Full_Name (Old.Def.all) & ", given "
            & Type_Name (Value));
      end if;
      Free (Old);
      This.Cell.Extra.Nodes (Target) := Copy (Value.Root);
   end Set_Message;

   ---------------------------------------------------------------------
   -- Arrays --
   ---------------------------------------------------------------------

   function As_Array (This : Field_Ref'Class) return Array_Ref is
   begin
      if not Is_Collection (This) then
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "expected " & Image (Cell_Type (This.Cell.all))
            & ", requested an array");
      end if;
      return (Cell => This.Cell);
   end As_Array;

   function As_Array (This : Field_Ref'Class; Index : Positive) return Field_Ref is
     (Element (As_Array (This), Index));

   function Length (This : Array_Ref) return Natural is (This.Cell.Count);

   function Capacity (This : Array_Ref) return Natural is
      T : constant Field_Type := Cell_Type (This.Cell.all);
   begin
      return (if T.Collection = Unbounded_Sequence then Natural'Last else T.Size);
   end Capacity;

   procedure Check_Length (Cell : Field_Cell; Length : Natural) is
      T : constant Field_Type := Cell_Type (Cell);
   begin
      case T.Collection is
         when Fixed_Array =>
            if Length /= T.Size then
               Raise_Field_Error
                 (Cell, Field_Name (Cell),
                  "is the fixed array " & Image (T) & ": cannot hold"
                  & Length'Image & " elements");
            end if;
         when Bounded_Sequence =>
            if Length > T.Size then
               Raise_Field_Error
                 (Cell, Field_Name (Cell),
                  "is the bounded sequence " & Image (T) & ": cannot hold"
                  & Length'Image & " elements");
            end if;
         when Unbounded_Sequence | Single =>
            null;
      end case;
   end Check_Length;

   procedure Resize (This : Array_Ref; Length : Natural) is
   begin
      Check_Length (This.Cell.all, Length);
      if Length /= This.Cell.Count then
         Set_Count (This.Cell.all, Length);
      end if;
   end Resize;

   function Element (This : Array_Ref'Class; Index : Positive) return Field_Ref is
   begin
      if Index > This.Cell.Count then
         Raise_Field_Error
           (This.Cell.all, Field_Name (This.Cell.all),
            "index" & Index'Image & " out of range 1 .."
            & This.Cell.Count'Image);
      end if;
      return (Cell => This.Cell, Index => Index);
   end Element;

   function Matrix_Element
     (N : Node_Access; Indices : Index_Array) return Field_Ref
   is
      Layout_I : constant Natural := Field_Index (N.Def.all, "layout");
      Data_I   : constant Natural := Field_Index (N.Def.all, "data");
   begin
      if Layout_I = 0 or else Data_I = 0
        or else N.Def.Fields (Layout_I).Of_Type.Kind /= Message_Kind
        or else N.Def.Fields (Data_I).Of_Type.Collection = Single
      then
         raise Field_Error with Full_Name (N.Def.all)
           & " is not a MultiArray (layout, data); As_Matrix needs one; fields: "
           & Field_Names (N.Def.all);
      end if;
      declare
         Layout : constant Node_Access := N.Cells (Layout_I).Extra.Nodes (1);
         Dims   : Field_Cell renames
           Layout.Cells (Field_Index (Layout.Def.all, "dim"));
         Offset : constant UInt32 := To_UInt32
           (Element_Address
              (Layout.Cells (Field_Index (Layout.Def.all, "data_offset")), 1)).all;
         Data   : Field_Cell renames N.Cells (Data_I);
         Pos    : Long_Long_Integer := Long_Long_Integer (Offset);

         function Dim_Value (D : Positive; Name : String) return Long_Long_Integer is
            Dim : constant Node_Access := Dims.Extra.Nodes (D);
         begin
            return Long_Long_Integer
              (To_UInt32 (Element_Address
                 (Dim.Cells (Field_Index (Dim.Def.all, Name)), 1)).all);
         end Dim_Value;
      begin
         if Indices'Length /= Dims.Count then
            Raise_Field_Error
              (Data, "data",
               "matrix index has" & Indices'Length'Image
               & " indices, layout has" & Dims.Count'Image & " dimensions");
         end if;
         for K in Indices'Range loop
            declare
               D : constant Positive := K - Indices'First + 1;
            begin
               if Long_Long_Integer (Indices (K)) > Dim_Value (D, "size") then
                  Raise_Field_Error
                    (Data, "data",
                     "matrix index" & Indices (K)'Image & " exceeds the size"
                     & Dim_Value (D, "size")'Image & " of dimension" & D'Image);
               end if;
               Pos := Pos + Long_Long_Integer (Indices (K) - 1)
                 * (if D < Dims.Count then Dim_Value (D + 1, "stride") else 1);
            end;
         end loop;
         if Pos >= Long_Long_Integer (Data.Count) then
            Raise_Field_Error
              (Data, "data",
               "matrix element at offset" & Pos'Image & " beyond the"
               & Data.Count'Image & " elements of data");
         end if;
         return (Cell => Data'Access, Index => Natural (Pos) + 1);
      end;
   end Matrix_Element;

   function As_Matrix (This : Field_Ref; Indices : Index_Array) return Field_Ref is
     (Matrix_Element (Nested_Node (This, "a MultiArray"), Indices));

   function As_Matrix
     (This : Message'Class; Indices : Index_Array) return Field_Ref is
   begin
      if This.Root = null then
         raise Field_Error with "As_Matrix on an uninitialised message";
      end if;
      Make_Unique (This, Referenced => True);
      return Matrix_Element (This.Root, Indices);
   end As_Matrix;

   ---------------------------------------------------------------------
   -- Bulk access --
   ---------------------------------------------------------------------

   procedure Check_Bulk (This : Field_Ref'Class; Kinds : String; OK : Boolean) is
   begin
      if not OK or else not Is_Collection (This) then
         Raise_Field_Error
           (This.Cell.all, Ref_Name (This),
            "expected " & Image (Cell_Type (This.Cell.all)) & ", requested "
            & Kinds & " array");
      end if;
   end Check_Bulk;

   type Kind_Set is array (Element_Kind) of Boolean;

   generic
      type Item is private;
      type Item_Array is array (Positive range <>) of Item;
      Kinds   : String;
      Allowed : Kind_Set;
   package Bulk is
      procedure Set (This : Field_Ref; Values : Item_Array);
      function Get (This : Field_Ref) return Item_Array;
   end Bulk;

   package body Bulk is
      procedure Set (This : Field_Ref; Values : Item_Array) is
      begin
         Check_Bulk (This, Kinds, Allowed (Cell_Type (This.Cell.all).Kind));
         Check_Length (This.Cell.all, Values'Length);
         if This.Cell.Count /= Values'Length then
            Free_Words (This.Cell.Prims);
            This.Cell.Count := 0;
            Set_Count (This.Cell.all, Values'Length);
         end if;
         if Values'Length > 0 then
            declare
               Dst : Item_Array (1 .. Values'Length)
                 with Import, Address => This.Cell.Prims.all'Address;
            begin
               Dst := Values;
            end;
         end if;
      end Set;

      function Get (This : Field_Ref) return Item_Array is
      begin
         Check_Bulk (This, Kinds, Allowed (Cell_Type (This.Cell.all).Kind));
         if This.Cell.Count = 0 then
            return [];
         end if;
         declare
            Src : Item_Array (1 .. This.Cell.Count)
              with Import, Address => This.Cell.Prims.all'Address;
         begin
            return Src;
         end;
      end Get;
   end Bulk;

   package Bool_Bulk is new Bulk
     (Bool, Bool_Array, "a bool", [Bool_Kind => True, others => False]);
   package UInt8_Bulk is new Bulk
     (UInt8, UInt8_Array, "a uint8/byte/char",
      [Byte_Kind | Char_Kind | UInt8_Kind => True, others => False]);
   package Int8_Bulk is new Bulk
     (Int8, Int8_Array, "an int8",
      [Int8_Kind => True, others => False]);
   package Int16_Bulk is new Bulk
     (Int16, Int16_Array, "an int16",
      [Int16_Kind => True, others => False]);
   package UInt16_Bulk is new Bulk
     (UInt16, UInt16_Array, "a uint16",
      [UInt16_Kind => True, others => False]);
   package Int32_Bulk is new Bulk
     (Int32, Int32_Array, "an int32",
      [Int32_Kind => True, others => False]);
   package UInt32_Bulk is new Bulk
     (UInt32, UInt32_Array, "a uint32",
      [UInt32_Kind => True, others => False]);
   package Int64_Bulk is new Bulk
     (Int64, Int64_Array, "an int64",
      [Int64_Kind => True, others => False]);
   package UInt64_Bulk is new Bulk
     (UInt64, UInt64_Array, "a uint64",
      [UInt64_Kind => True, others => False]);
   package Float32_Bulk is new Bulk
     (Float32, Float32_Array, "a float32",
      [Float32_Kind => True, others => False]);
   package Float64_Bulk is new Bulk
     (Float64, Float64_Array, "a float64",
      [Float64_Kind => True, others => False]);

   procedure Set_Bool_Array (This : Field_Ref; Values : Bool_Array)
     renames Bool_Bulk.Set;
   procedure Set_UInt8_Array (This : Field_Ref; Values : UInt8_Array)
     renames UInt8_Bulk.Set;
   procedure Set_Int8_Array (This : Field_Ref; Values : Int8_Array)
     renames Int8_Bulk.Set;
   procedure Set_Int16_Array (This : Field_Ref; Values : Int16_Array)
     renames Int16_Bulk.Set;
   procedure Set_UInt16_Array (This : Field_Ref; Values : UInt16_Array)
     renames UInt16_Bulk.Set;
   procedure Set_Int32_Array (This : Field_Ref; Values : Int32_Array)
     renames Int32_Bulk.Set;
   procedure Set_UInt32_Array (This : Field_Ref; Values : UInt32_Array)
     renames UInt32_Bulk.Set;
   procedure Set_Int64_Array (This : Field_Ref; Values : Int64_Array)
     renames Int64_Bulk.Set;
   procedure Set_UInt64_Array (This : Field_Ref; Values : UInt64_Array)
     renames UInt64_Bulk.Set;
   procedure Set_Float32_Array (This : Field_Ref; Values : Float32_Array)
     renames Float32_Bulk.Set;
   procedure Set_Float64_Array (This : Field_Ref; Values : Float64_Array)
     renames Float64_Bulk.Set;

   function Get_Bool_Array (This : Field_Ref) return Bool_Array
     renames Bool_Bulk.Get;
   function Get_UInt8_Array (This : Field_Ref) return UInt8_Array
     renames UInt8_Bulk.Get;
   function Get_Int8_Array (This : Field_Ref) return Int8_Array
     renames Int8_Bulk.Get;
   function Get_Int16_Array (This : Field_Ref) return Int16_Array
     renames Int16_Bulk.Get;
   function Get_UInt16_Array (This : Field_Ref) return UInt16_Array
     renames UInt16_Bulk.Get;
   function Get_Int32_Array (This : Field_Ref) return Int32_Array
     renames Int32_Bulk.Get;
   function Get_UInt32_Array (This : Field_Ref) return UInt32_Array
     renames UInt32_Bulk.Get;
   function Get_Int64_Array (This : Field_Ref) return Int64_Array
     renames Int64_Bulk.Get;
   function Get_UInt64_Array (This : Field_Ref) return UInt64_Array
     renames UInt64_Bulk.Get;
   function Get_Float32_Array (This : Field_Ref) return Float32_Array
     renames Float32_Bulk.Get;
   function Get_Float64_Array (This : Field_Ref) return Float64_Array
     renames Float64_Bulk.Get;

   ---------------------------------------------------------------------
   -- Constants and image --
   ---------------------------------------------------------------------

   function Constant_Value (This : Message; Name : String) return String is
      Names : Unbounded_String;
   begin
      if This.Root = null then
         raise Field_Error with "constant """ & Name
           & """ of an uninitialised message";
      end if;
      for C of This.Root.Def.Constants loop
         if C.Name = Name then
            return To_String (C.Value);
         end if;
         Append (Names, (if Length (Names) > 0 then ", " else "") & C.Name);
      end loop;
      raise Field_Error with Full_Name (This.Root.Def.all)
        & " has no constant """ & Name & """; valid constants: "
        & (if Length (Names) = 0 then "(none)" else To_String (Names));
   end Constant_Value;

   function Constant_Int64 (This : Message; Name : String) return Int64 is
      V : constant String := Constant_Value (This, Name);
   begin
      return Int64'Value (V);
   exception
      when Constraint_Error =>
         raise Field_Error with Type_Name (This) & " constant """ & Name
           & """ = " & V & " is not an int64";
   end Constant_Int64;

   function Constant_Float64 (This : Message; Name : String) return Float64 is
      V : constant String := Constant_Value (This, Name);
   begin
      if Is_Non_Finite_Text (V) then
         raise Field_Error with Type_Name (This) & " constant """ & Name
           & """ is " & V & ", not a finite number (Constant_Value gives its text)";
      end if;
      return To_Float64 (V);
   exception
      when Constraint_Error =>
         raise Field_Error with Type_Name (This) & " constant """ & Name
           & """ = " & V & " is not a number";
   end Constant_Float64;

   function Constant_WString (This : Message; Name : String) return Wide_Wide_String is
      V : constant String := Constant_Value (This, Name);
   begin
      return From_UTF_8 (V);
   exception
      when Encoding_Error =>
         raise Field_Error with Type_Name (This) & " constant """ & Name
           & """ is not valid UTF-8";
   end Constant_WString;

   function Image (This : Message; Truncate_Length : Natural := 0) return String
   is
   begin
      if This.Root = null then
         return "(uninitialised message)" & ASCII.LF;
      end if;
      return Images.Render (This.Root, Truncate_Length);
   end Image;

end ROSIDL.Dynamic;
