with Ada.Unchecked_Deallocation;
with Interfaces;
with ROSIDL.Wide_Text_Builders;

package body ROSIDL.Dynamic.Codec is

   use Interfaces;
   use type System.Bit_Order;

   Native_Little : constant Boolean :=
     System.Default_Bit_Order = System.Low_Order_First;

   Max_Depth : constant := 32;

   Encapsulation_Bytes : constant := 4;

   type Cell_Access is access constant Field_Cell;

   type Frame is record
      Cell  : Cell_Access;
      Index : Natural := 0;
   end record;

   type Frame_Array is array (1 .. Max_Depth) of Frame;

   type State is record
      Frames : Frame_Array;
      Depth  : Natural := 0;
      Swap   : Boolean := False;
      Little : Boolean := Native_Little;
      Pos    : Stream_Element_Offset := 0;
      --  Relative to the origin (the end of the encapsulation header).
      Origin : Stream_Element_Offset := 0;
      --  Index in the buffer of relative position 0.
      Root   : Message_Access;
   end record;

   procedure Push (S : in out State; Cell : Cell_Access; Index : Natural := 0) is
   begin
      S.Depth := S.Depth + 1;
      if S.Depth <= Max_Depth then
         S.Frames (S.Depth) := (Cell, Index);
      end if;
   end Push;

   procedure Pop (S : in out State) is
   begin
      S.Depth := S.Depth - 1;
   end Pop;

   procedure Set_Index (S : in out State; Index : Natural) is
   begin
      if S.Depth in 1 .. Max_Depth then
         S.Frames (S.Depth).Index := Index;
      end if;
   end Set_Index;

   function Trimmed (N : Long_Long_Integer) return String is
      Img : constant String := N'Image;
   begin
      return (if Img (Img'First) = ' ' then Img (Img'First + 1 .. Img'Last) else Img);
   end Trimmed;

   function Path (S : State) return String is
      Result : Unbounded_String;
   begin
      for D in 1 .. Natural'Min (S.Depth, Max_Depth) loop
         declare
            F : constant Frame := S.Frames (D);
            T : constant Field_Type := Cell_Type (F.Cell.all);
         begin
            if D > 1 then
               Append (Result, ".");
            end if;
            Append (Result, F.Cell.Owner.Def.Fields (F.Cell.Field).Name);
            if T.Collection /= Single and then F.Index > 0 then
               Append (Result, "[" & Trimmed (Long_Long_Integer (F.Index - 1)) & "]");
            end if;
         end;
      end loop;
      return (if Length (Result) = 0 then "(message)" else To_String (Result));
   end Path;

   procedure Decode_Failure (S : State; What : String) with No_Return is
   begin
      raise Decode_Error with Full_Name (S.Root.all) & ": " & Path (S) & ": "
        & What & " at byte offset "
        & Trimmed (Long_Long_Integer (S.Pos + Encapsulation_Bytes));
   end Decode_Failure;

   procedure Encode_Failure (S : State; What : String) with No_Return is
   begin
      raise Encode_Error with Full_Name (S.Root.all) & ": " & Path (S) & ": "
        & What;
   end Encode_Failure;

   function Aligned
     (Pos : Stream_Element_Offset; Size : Positive) return Stream_Element_Offset
   is
      A : constant Stream_Element_Offset := Stream_Element_Offset (Size);
   begin
      return (Pos + A - 1) / A * A;
   end Aligned;

   ---------------------------------------------------------------------
   -- Size and bound checks --
   ---------------------------------------------------------------------

   procedure Size_Node (N : Node_Access; S : in out State);

   procedure Check_String_Bound
     (S : in out State; Kind : String; Bound : Natural; Index : Positive; Length : Natural)
   --  Encode_Error at element Index when a Kind ("string", "wstring") of
   --  Length characters exceeds a Bound (0: unbounded).
   is
   begin
      if Bound > 0 and then Length > Bound then
         Set_Index (S, Index);
         Encode_Failure
           (S, Kind & " of" & Length'Image & " characters exceeds its bound" & Bound'Image);
      end if;
   end Check_String_Bound;

   procedure Size_Cell (Cell : Field_Cell; S : in out State) is
      T : constant Field_Type := Cell_Type (Cell);
   begin
      case T.Collection is
         when Single =>
            null;
         when Fixed_Array =>
            if Cell.Count /= T.Size then
               Encode_Failure (S, "holds" & Cell.Count'Image & " elements, "
                               & Image (T) & " needs" & T.Size'Image);
            end if;
         when Bounded_Sequence =>
            if Cell.Count > T.Size then
               Encode_Failure (S, "holds" & Cell.Count'Image & " elements, "
                               & "beyond the bound of " & Image (T));
            end if;
            S.Pos := Aligned (S.Pos, 4) + 4;
         when Unbounded_Sequence =>
            S.Pos := Aligned (S.Pos, 4) + 4;
      end case;
      case T.Kind is
         when Primitive_Kind =>
            if Cell.Count > 0 then
               S.Pos := Aligned (S.Pos, Primitive_Size (T.Kind))
                 + Stream_Element_Offset (Cell.Count * Primitive_Size (T.Kind));
            end if;
         when String_Kind =>
            for I in 1 .. Cell.Count loop
               declare
                  L : constant Natural := Length (Cell.Extra.Texts (I));
               begin
                  Check_String_Bound (S, "string", T.String_Bound, I, L);
                  S.Pos := Aligned (S.Pos, 4) + 4 + Stream_Element_Offset (L + 1);
               end;
            end loop;
         when WString_Kind =>
            for I in 1 .. Cell.Count loop
               declare
                  L : constant Natural := Length (Cell.Extra.WTexts (I));
               begin
                  Check_String_Bound (S, "wstring", T.String_Bound, I, L);
                  S.Pos := Aligned (S.Pos, 4) + 4 + Stream_Element_Offset (4 * L);
               end;
            end loop;
         when Message_Kind =>
            for I in 1 .. Cell.Count loop
               Set_Index (S, I);
               Size_Node (Cell.Extra.Nodes.Element (I), S);
               --  Element, not indexing: no controlled reference object per
               --  nested message (the hot path of every encoding).
            end loop;
      end case;
   end Size_Cell;

   procedure Size_Node (N : Node_Access; S : in out State) is
   begin
      for I in N.Cells'Range loop
         Push (S, N.Cells (I)'Access);
         Size_Cell (N.Cells (I), S);
         Pop (S);
      end loop;
   end Size_Node;

   Encapsulation_Size : constant Stream_Element_Offset := Encapsulation_Bytes;

   function Encoded_Size
     (Msg : Message; With_Header : Boolean) return Stream_Element_Count
   is
      S : State;
   begin
      if Msg.Root = null then
         raise Encode_Error with "encoding an uninitialised message";
      end if;
      S.Root := Msg.Root.Def;
      S.Pos := (if With_Header then 16 else 0);
      Size_Node (Msg.Root, S);
      return Encapsulation_Size + Aligned (S.Pos, 4);
   end Encoded_Size;

   ---------------------------------------------------------------------
   -- Encoding --
   ---------------------------------------------------------------------

   procedure Encode
     (Msg    : Message;
      Header : Optional_Header;
      Order  : CDR.Byte_Order;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset)
   is
      use type CDR.Byte_Order;
      Little : constant Boolean := Order = CDR.Little_Endian;
      Size   : constant Stream_Element_Count := Encoded_Size (Msg, Header.Present);
      S      : State;

      procedure Pad_To (Align : Positive) is
         New_Pos : constant Stream_Element_Offset := Aligned (S.Pos, Align);
      begin
         for P in S.Pos .. New_Pos - 1 loop
            Buffer (S.Origin + P) := 0;
         end loop;
         S.Pos := New_Pos;
      end Pad_To;

      procedure Put_Unsigned (Value : Unsigned_64; Size : Positive) is
         V : Unsigned_64 := Value;
      begin
         Pad_To (Size);
         for I in 0 .. Stream_Element_Offset (Size) - 1 loop
            if Little then
               Buffer (S.Origin + S.Pos + I) := Stream_Element (V and 16#FF#);
            else
               Buffer (S.Origin + S.Pos + Stream_Element_Offset (Size) - 1 - I) :=
                 Stream_Element (V and 16#FF#);
            end if;
            V := Shift_Right (V, 8);
         end loop;
         S.Pos := S.Pos + Stream_Element_Offset (Size);
      end Put_Unsigned;

      procedure Put_Block (Address : System.Address; Count, Size : Natural) is
         Bytes : constant Stream_Element_Offset := Stream_Element_Offset (Count * Size);
         First : Stream_Element_Offset;
      begin
         if Count = 0 then
            return;
         end if;
         Pad_To (Size);
         First := S.Origin + S.Pos;
         declare
            Src : Stream_Element_Array (1 .. Bytes)
              with Import, Address => Address;
         begin
            if not S.Swap or else Size = 1 then
               Buffer (First .. First + Bytes - 1) := Src;
            else
               for E in 0 .. Stream_Element_Offset (Count) - 1 loop
                  for B in 0 .. Stream_Element_Offset (Size) - 1 loop
                     Buffer (First + E * Stream_Element_Offset (Size) + B) :=
                       Src (1 + E * Stream_Element_Offset (Size)
                            + Stream_Element_Offset (Size) - 1 - B);
                  end loop;
               end loop;
            end if;
         end;
         S.Pos := S.Pos + Bytes;
      end Put_Block;

      procedure Put_Node (N : Node_Access);

      procedure Put_Cell (Cell : Field_Cell) is
         T : constant Field_Type := Cell_Type (Cell);
      begin
         if T.Collection in Bounded_Sequence | Unbounded_Sequence then
            Put_Unsigned (Unsigned_64 (Cell.Count), 4);
         end if;
         case T.Kind is
            when Primitive_Kind =>
               if Cell.Count > 0 then
                  Put_Block (Cell.Prims.all'Address, Cell.Count,
                             Primitive_Size (T.Kind));
               end if;
            when String_Kind =>
               for I in 1 .. Cell.Count loop
                  declare
                     Text : constant String := To_String (Cell.Extra.Texts (I));
                  begin
                     Put_Unsigned (Unsigned_64 (Text'Length + 1), 4);
                     for C of Text loop
                        Buffer (S.Origin + S.Pos) := Character'Pos (C);
                        S.Pos := S.Pos + 1;
                     end loop;
                     Buffer (S.Origin + S.Pos) := 0;
                     S.Pos := S.Pos + 1;
                  end;
               end loop;
            when WString_Kind =>
               for I in 1 .. Cell.Count loop
                  declare
                     Text : constant Wide_Wide_String :=
                       To_Wide_Wide_String (Cell.Extra.WTexts (I));
                  begin
                     Put_Unsigned (Unsigned_64 (Text'Length), 4);
                     for C of Text loop
                        Put_Unsigned (Wide_Wide_Character'Pos (C), 4);
                     end loop;
                  end;
               end loop;
            when Message_Kind =>
               for I in 1 .. Cell.Count loop
                  Put_Node (Cell.Extra.Nodes.Element (I));
               end loop;
         end case;
      end Put_Cell;

      procedure Put_Node (N : Node_Access) is
      begin
         for I in N.Cells'Range loop
            Put_Cell (N.Cells (I));
         end loop;
      end Put_Node;

   begin
      if Buffer'Length < Size then
         raise Encode_Error with Full_Name (Msg.Root.Def.all) & ": buffer of"
           & Buffer'Length'Image & " bytes, the encoding needs" & Size'Image;
      end if;
      S.Root := Msg.Root.Def;
      S.Little := Little;
      S.Swap := Little /= Native_Little;
      S.Origin := Buffer'First + Encapsulation_Size;
      Buffer (Buffer'First) := 0;
      Buffer (Buffer'First + 1) := (if Little then 1 else 0);
      Buffer (Buffer'First + 2) := 0;
      Buffer (Buffer'First + 3) := 0;
      if Header.Present then
         Put_Unsigned (Header.Value.GUID, 8);
         Put_Unsigned (Unsigned_64'Mod (Header.Value.Sequence), 8);
      end if;
      Put_Node (Msg.Root);
      Pad_To (4);
      Last := S.Origin + S.Pos - 1;
      pragma Assert (Last - Buffer'First + 1 = Size);
   end Encode;

   ---------------------------------------------------------------------
   -- Decoding --
   ---------------------------------------------------------------------

   function Little_Endian_Header
     (Data : Stream_Element_Array; Type_Name : String := "") return Boolean
   is
      Subject : constant String := (if Type_Name = "" then "" else Type_Name & ": ");
   begin
      if Data'Length < Encapsulation_Size then
         raise Decode_Error with Subject & "buffer of" & Data'Length'Image
           & " bytes is shorter than the 4-byte encapsulation header"
           & " at byte offset 0";
      end if;
      if Data (Data'First) /= 0 or else Data (Data'First + 1) > 1 then
         raise Decode_Error with Subject & "unknown encapsulation identifier"
           & Stream_Element'Image (Data (Data'First)) & ","
           & Stream_Element'Image (Data (Data'First + 1))
           & " (expected 0, 0 for CDR_BE or 0, 1 for CDR_LE) at byte offset 0";
      end if;
      return Data (Data'First + 1) = 1;
   end Little_Endian_Header;

   function Request_Header_Of
     (Data : Stream_Element_Array; Type_Name : String) return CDR.Request_Header
   is
      Little : constant Boolean := Little_Endian_Header (Data, Type_Name);

      function Word (Offset : Stream_Element_Offset; What : String) return Unsigned_64 is
         --  The 8 bytes at Offset from the start of Data.
         V : Unsigned_64 := 0;
      begin
         if Data'Length < Offset + 8 then
            raise Decode_Error with Type_Name & ": request header " & What
              & ": truncated: needs 8 bytes,"
              & Stream_Element_Offset'Max (Data'Length - Offset, 0)'Image
              & " remain at byte offset " & Trimmed (Long_Long_Integer (Offset));
         end if;
         for I in Stream_Element_Offset range 0 .. 7 loop
            V := Shift_Left (V, 8)
              or Unsigned_64 (Data (Data'First + Offset + (if Little then 7 - I else I)));
         end loop;
         return V;
      end Word;

      GUID : constant Unsigned_64 := Word (Encapsulation_Size, "guid");
      Wire : constant Unsigned_64 := Word (Encapsulation_Size + 8, "sequence");
      --  The sequence is an int64 on the wire: any 64 bits, e.g. -1
      --  (FF..FF) from a hostile peer, are a valid value.
   begin
      return (GUID     => UInt64 (GUID),
              Sequence => (if Wire <= Unsigned_64 (Int64'Last) then Int64 (Wire)
                           else -Int64 (not Wire) - 1));
   end Request_Header_Of;

   procedure Free_Words is new Ada.Unchecked_Deallocation
     (Word_Array, Word_Access);

   procedure Decode
     (Data        : Stream_Element_Array;
      Msg         : in out Message;
      With_Header : Boolean;
      Header      : out CDR.Request_Header)
   is
      S : State;

      function Remaining return Long_Long_Integer is
        (Long_Long_Integer (Data'Last) - Long_Long_Integer (S.Origin + S.Pos) + 1);

      procedure Need (Bytes : Long_Long_Integer; What : String) is
      begin
         if Remaining < Bytes then
            Decode_Failure
              (S, "truncated: " & What & " needs" & Bytes'Image & " bytes,"
               & Long_Long_Integer'Max (Remaining, 0)'Image & " remain");
         end if;
      end Need;

      function Get_Unsigned (Size : Positive; What : String) return Unsigned_64 is
         V : Unsigned_64 := 0;
      begin
         S.Pos := Aligned (S.Pos, Size);
         Need (Long_Long_Integer (Size), What);
         for I in 0 .. Stream_Element_Offset (Size) - 1 loop
            declare
               B : constant Unsigned_64 := Unsigned_64
                 (Data (S.Origin + S.Pos
                        + (if S.Little then Stream_Element_Offset (Size) - 1 - I
                           else I)));
            begin
               V := Shift_Left (V, 8) or B;
            end;
         end loop;
         S.Pos := S.Pos + Stream_Element_Offset (Size);
         return V;
      end Get_Unsigned;

      procedure Allocate (Cell : in out Field_Cell; Count : Natural) is
         Size : constant Natural := Primitive_Size (Cell_Type (Cell).Kind);
      begin
         if Count /= Cell.Count or else (Count > 0 and then Cell.Prims = null) then
            Free_Words (Cell.Prims);
            Cell.Count := 0;
            if Count > 0 then
               Cell.Prims := new Word_Array (0 .. (Count * Size - 1) / 8);
            end if;
            Cell.Count := Count;
         end if;
      end Allocate;

      procedure Get_Block (Cell : in out Field_Cell; Count : Natural) is
         T     : constant Field_Type := Cell_Type (Cell);
         Size  : constant Positive := Primitive_Size (T.Kind);
         Bytes : constant Long_Long_Integer := Long_Long_Integer (Count * Size);
      begin
         if Count = 0 then
            Allocate (Cell, 0);
            return;
         end if;
         S.Pos := Aligned (S.Pos, Size);
         if Remaining < Bytes then
            declare
               Whole : constant Natural := Natural
                 (Long_Long_Integer'Max (Remaining, 0) / Long_Long_Integer (Size));
               Text  : constant String :=
                 "truncated: " & Image (T)
                 & (if T.Collection = Single then ""
                    else " of" & Count'Image & " elements")
                 & " needs" & Bytes'Image & " bytes,"
                 & Long_Long_Integer'Max (Remaining, 0)'Image & " remain";
            begin
               if T.Collection /= Single then
                  Set_Index (S, Whole + 1);
                  S.Pos := S.Pos + Stream_Element_Offset (Whole * Size);
               end if;
               Decode_Failure (S, Text);
            end;
         end if;
         Allocate (Cell, Count);
         declare
            First : constant Stream_Element_Offset := S.Origin + S.Pos;
            N     : constant Stream_Element_Offset := Stream_Element_Offset (Bytes);
            Dst   : Stream_Element_Array (1 .. N)
              with Import, Address => Cell.Prims.all'Address;
         begin
            if not S.Swap or else Size = 1 then
               Dst := Data (First .. First + N - 1);
            else
               for E in 0 .. Stream_Element_Offset (Count) - 1 loop
                  for B in 0 .. Stream_Element_Offset (Size) - 1 loop
                     Dst (1 + E * Stream_Element_Offset (Size) + B) :=
                       Data (First + E * Stream_Element_Offset (Size)
                             + Stream_Element_Offset (Size) - 1 - B);
                  end loop;
               end loop;
            end if;
            if T.Kind = Bool_Kind then
               for B of Dst loop
                  B := (if B /= 0 then 1 else 0);
               end loop;
            end if;
         end;
         S.Pos := S.Pos + Stream_Element_Offset (Bytes);
      end Get_Block;

      procedure Get_Node (N : Node_Access);

      procedure Get_Cell (Cell : in out Field_Cell) is
         T     : constant Field_Type := Cell_Type (Cell);
         Count : Natural;
      begin
         case T.Collection is
            when Single =>
               Count := 1;
            when Fixed_Array =>
               Count := T.Size;
            when Bounded_Sequence | Unbounded_Sequence =>
               declare
                  Wire : constant Unsigned_64 := Get_Unsigned (4, "sequence count");
                  Min  : constant Long_Long_Integer := Min_Element_Size (T);
               begin
                  if T.Collection = Bounded_Sequence
                    and then Wire > Unsigned_64 (T.Size)
                  then
                     S.Pos := S.Pos - 4;
                     Decode_Failure
                       (S, "sequence count" & Wire'Image & " exceeds the bound of "
                        & Image (T));
                  end if;
                  if Long_Long_Integer (Wire) * Min > Long_Long_Integer'Max (Remaining, 0)
                  then
                     S.Pos := S.Pos - 4;
                     Decode_Failure
                       (S, "sequence count" & Wire'Image & " cannot fit in the"
                        & Long_Long_Integer'Max (Remaining - 4, 0)'Image
                        & " remaining bytes");
                  end if;
                  Count := Natural (Wire);
               end;
         end case;
         if T.Kind not in Primitive_Kind and then Cell.Count /= Count then
            Set_Count (Cell, Count);  --  Get_Block sizes a primitive cell itself.
         end if;
         case T.Kind is
            when Primitive_Kind =>
               Get_Block (Cell, Count);
            when String_Kind =>
               for I in 1 .. Count loop
                  Set_Index (S, I);
                  declare
                     L : constant Unsigned_64 := Get_Unsigned (4, "string length");
                  begin
                     if L = 0 then
                        S.Pos := S.Pos - 4;
                        Decode_Failure (S, "string length 0 (no room for its NUL)");
                     end if;
                     if Long_Long_Integer (L) > Remaining then
                        S.Pos := S.Pos - 4;
                        Decode_Failure
                          (S, "string length" & L'Image & " exceeds the"
                           & Long_Long_Integer'Max (Remaining - 4, 0)'Image
                           & " remaining bytes");
                     end if;
                     if T.String_Bound > 0 and then L - 1 > Unsigned_64 (T.String_Bound)
                     then
                        S.Pos := S.Pos - 4;
                        Decode_Failure
                          (S, "string of" & Unsigned_64'Image (L - 1)
                           & " characters exceeds its bound" & T.String_Bound'Image);
                     end if;
                     declare
                        First : constant Stream_Element_Offset := S.Origin + S.Pos;
                        Len   : constant Natural := Natural (L) - 1;
                     begin
                        if Data (First + Stream_Element_Offset (Len)) /= 0 then
                           S.Pos := S.Pos + Stream_Element_Offset (Len);
                           Decode_Failure (S, "string not terminated by a NUL");
                        end if;
                        if Len = 0 then
                           Cell.Extra.Texts (I) := Null_Unbounded_String;
                        else
                           declare
                              Text : String (1 .. Len)
                                with Import, Address => Data (First)'Address;
                           begin
                              Cell.Extra.Texts (I) := To_Unbounded_String (Text);
                           end;
                        end if;
                        S.Pos := S.Pos + Stream_Element_Offset (L);
                     end;
                  end;
               end loop;
            when WString_Kind =>
               for I in 1 .. Count loop
                  Set_Index (S, I);
                  declare
                     L : constant Unsigned_64 := Get_Unsigned (4, "wstring length");
                  begin
                     if Long_Long_Integer (L) * 4 > Remaining then
                        S.Pos := S.Pos - 4;
                        Decode_Failure
                          (S, "wstring length" & L'Image & " exceeds the"
                           & Long_Long_Integer'Max (Remaining - 4, 0)'Image
                           & " remaining bytes");
                     end if;
                     if T.String_Bound > 0 and then L > Unsigned_64 (T.String_Bound)
                     then
                        S.Pos := S.Pos - 4;
                        Decode_Failure
                          (S, "wstring of" & L'Image
                           & " characters exceeds its bound" & T.String_Bound'Image);
                     end if;
                     declare
                        Text : Wide_Text_Builders.Builder;
                     begin
                        for Unused in 1 .. L loop
                           declare
                              Code : constant Unsigned_64 :=
                                Get_Unsigned (4, "wstring character");
                           begin
                              if Code > 16#7FFF_FFFF# then
                                 S.Pos := S.Pos - 4;
                                 Decode_Failure
                                   (S, "wstring character" & Code'Image
                                    & " out of range");
                              end if;
                              Wide_Text_Builders.Append (Text, Wide_Wide_Character'Val (Code));
                           end;
                        end loop;
                        Wide_Text_Builders.Take (Text, Cell.Extra.WTexts (I));
                     end;
                  end;
               end loop;
            when Message_Kind =>
               for I in 1 .. Count loop
                  Set_Index (S, I);
                  Get_Node (Cell.Extra.Nodes.Element (I));
               end loop;
         end case;
      end Get_Cell;

      procedure Get_Node (N : Node_Access) is
      begin
         for I in N.Cells'Range loop
            Push (S, N.Cells (I)'Access);
            Get_Cell (N.Cells (I));
            Pop (S);
         end loop;
      end Get_Node;

   begin
      Header := (GUID => 0, Sequence => 0);
      if Msg.Root = null then
         raise Decode_Error with "decoding into an uninitialised message";
      end if;
      Make_Unique (Msg, Referenced => False, Keep_Contents => False);
      S.Root := Msg.Root.Def;
      S.Little := Little_Endian_Header (Data, Full_Name (S.Root.all));
      S.Swap := S.Little /= Native_Little;
      S.Origin := Data'First + Encapsulation_Size;
      if With_Header then
         Header := Request_Header_Of (Data, Full_Name (S.Root.all));
         S.Pos := CDR.Request_Header_Size;
      end if;
      Get_Node (Msg.Root);
   end Decode;

end ROSIDL.Dynamic.Codec;
