with Ada.Exceptions;
with Ada.Strings.UTF_Encoding.Wide_Wide_Strings;
with ROSIDL.Definitions;

package body RCL.YAML.Messages is

   use ROSIDL.Definitions;
   use ROSIDL.Dynamic;

   type Getter is access function (Name : String) return Field_Ref;

   procedure Fail (From : Document; N : Node; Message : String) is
   begin
      raise Parse_Error with From.Where (N) & ": " & Message;
   end Fail;

   function Kind_Name (K : Element_Kind) return String is
     (case K is
         when Primitive_Kind => Type_Name (K),
         when String_Kind => "string",
         when WString_Kind => "wstring",
         when Message_Kind => "message");

   --  Numbers -----------------------------------------------------------

   function Integer_Value (From : Document; N : Node; What : String) return Long_Long_Integer is
      S : constant String := From.Text (N);
   begin
      if From.Kind (N) /= Scalar or else From.Scalar_Type (N) /= Int_Scalar then
         Fail (From, N, What & ": '" & S & "' is not an integer");
      end if;
      return RCL.YAML.Integer_Value (S);
   exception
      when Constraint_Error =>
         Fail (From, N, What & ": " & S & " is out of range");
         return 0;
   end Integer_Value;

   function Float_Value (From : Document; N : Node; What : String) return Long_Float is
      S : constant String := From.Text (N);
   begin
      if From.Kind (N) /= Scalar
        or else From.Scalar_Type (N) not in Int_Scalar | Float_Scalar
      then
         Fail (From, N, What & ": '" & S & "' is not a number");
      end if;
      return RCL.YAML.Float_Value (S);
   exception
      when Constraint_Error =>
         Fail (From, N, What & ": " & S & " is not a valid number");
         return 0.0;
   end Float_Value;

   --  Elements ------------------------------------------------------------

   procedure Fill_Fields (Get : Getter; Def : Message_Access; From : Document; N : Node);

   procedure Set_Element
     (Ref : Field_Ref; FT : Field_Type; Field : String; From : Document; N : Node)
   is
      What : constant String := "field '" & Field & "' is " & Kind_Name (FT.Kind);

      procedure Check (V, Low, High : Long_Long_Integer) is
      begin
         if V < Low or else V > High then
            Fail (From, N, From.Text (N) & " is out of range for " & Kind_Name (FT.Kind)
                  & " (" & Low'Image & " .." & High'Image & ") in field '" & Field & "'");
         end if;
      end Check;
   begin
      case FT.Kind is
         when Bool_Kind =>
            if From.Kind (N) /= Scalar or else From.Scalar_Type (N) /= Bool_Scalar then
               Fail (From, N, What & ": '" & From.Text (N) & "' is not true or false");
            end if;
            Ref.As_Bool.Element.all := From.Text (N) in "true" | "True" | "TRUE";
         when Byte_Kind | Char_Kind | UInt8_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, 0, 255);
               case FT.Kind is
                  when Byte_Kind => Ref.As_Byte.Element.all := ROSIDL.UInt8 (V);
                  when Char_Kind => Ref.As_Char.Element.all := ROSIDL.UInt8 (V);
                  when others => Ref.As_UInt8.Element.all := ROSIDL.UInt8 (V);
               end case;
            end;
         when Int8_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, -128, 127);
               Ref.As_Int8.Element.all := ROSIDL.Int8 (V);
            end;
         when Int16_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, -32_768, 32_767);
               Ref.As_Int16.Element.all := ROSIDL.Int16 (V);
            end;
         when UInt16_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, 0, 65_535);
               Ref.As_UInt16.Element.all := ROSIDL.UInt16 (V);
            end;
         when Int32_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, -2**31, 2**31 - 1);
               Ref.As_Int32.Element.all := ROSIDL.Int32 (V);
            end;
         when UInt32_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, 0, 2**32 - 1);
               Ref.As_UInt32.Element.all := ROSIDL.UInt32 (V);
            end;
         when Int64_Kind =>
            Ref.As_Int64.Element.all := ROSIDL.Int64 (Integer_Value (From, N, What));
         when UInt64_Kind =>
            declare
               V : constant Long_Long_Integer := Integer_Value (From, N, What);
            begin
               Check (V, 0, Long_Long_Integer'Last);
               Ref.As_UInt64.Element.all := ROSIDL.UInt64 (V);
            end;
         when Float32_Kind =>
            Ref.As_Float32.Element.all := ROSIDL.Float32 (Float_Value (From, N, What));
         when Float64_Kind =>
            Ref.As_Float64.Element.all := ROSIDL.Float64 (Float_Value (From, N, What));
         when String_Kind | WString_Kind =>
            if From.Kind (N) not in Scalar | Null_Value then
               Fail (From, N, What & ": expected a string, found a "
                     & (if From.Kind (N) = Sequence then "sequence" else "mapping"));
            end if;
            if FT.Kind = String_Kind then
               Ref.Set_String (From.Text (N));
            else
               Ref.Set_WString
                 (Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode (From.Text (N)));
            end if;
         when Message_Kind =>
            declare
               function Get (Name : String) return Field_Ref is (Ref.Field_Reference (Name));
            begin
               Fill_Fields (Get'Unrestricted_Access, FT.Nested, From, N);
            end;
      end case;
   end Set_Element;

   procedure Set_Field (Ref : Field_Ref; Field : String; From : Document; N : Node) is
      FT : constant Field_Type := Ref.Field_Type_Of;
   begin
      if FT.Collection = Single then
         Set_Element (Ref, FT, Field, From, N);
         return;
      end if;
      if From.Kind (N) /= Sequence then
         Fail (From, N, "field '" & Field & "' is " & Image (FT) & ": expected a sequence"
               & " ([...] or '- ' items)");
      end if;
      declare
         Arr   : constant Array_Ref := Ref.As_Array;
         Count : constant Natural := From.Length (N);
      begin
         if FT.Collection = Fixed_Array and then Count /= FT.Size then
            Fail (From, N, "field '" & Field & "' is " & Image (FT) & ": expected"
                  & FT.Size'Image & " elements, found" & Count'Image);
         elsif FT.Collection = Bounded_Sequence and then Count > FT.Size then
            Fail (From, N, "field '" & Field & "' is " & Image (FT) & ": at most"
                  & FT.Size'Image & " elements, found" & Count'Image);
         end if;
         Arr.Resize (Count);
         for I in 1 .. Count loop
            declare
               Index : constant String := Natural'Image (I - 1);
            begin
               Set_Element (Arr.Element (I), FT,
                            Field & "[" & Index (Index'First + 1 .. Index'Last) & "]",
                            From, From.Item (N, I));
            end;
         end loop;
      end;
   end Set_Field;

   procedure Fill_Fields (Get : Getter; Def : Message_Access; From : Document; N : Node) is
   begin
      if From.Kind (N) = Null_Value then
         return;
      elsif From.Kind (N) /= Mapping then
         Fail (From, N, Full_Name (Def.all) & " is a message: expected a mapping of its"
               & " fields ({" & Field_Names (Def.all) & "}), found '" & From.Image (N) & "'");
      end if;
      for I in 1 .. From.Length (N) loop
         declare
            Name : constant String := From.Key (N, I);
            V    : constant Node := From.Item (N, I);
         begin
            if Field_Index (Def.all, Name) = 0 then
               raise Parse_Error with From.Key_Where (N, I) & ": " & Full_Name (Def.all)
                 & " has no field '" & Name & "' (fields: " & Field_Names (Def.all) & ")";
            end if;
            Set_Field (Get (Name), Name, From, V);
         end;
      end loop;
   exception
      when E : ROSIDL.Field_Error | ROSIDL.Encode_Error =>
         Fail (From, N, Ada.Exceptions.Exception_Message (E));
   end Fill_Fields;

   ----------
   -- Fill --
   ----------

   procedure Fill (Msg : ROSIDL.Dynamic.Message; From : Document; N : Node) is
      function Get (Name : String) return Field_Ref is (Msg.Reference (Name));
   begin
      Fill_Fields (Get'Unrestricted_Access, Msg.Definition, From, N);
   end Fill;

   function From_YAML
     (Support : ROSIDL.Typesupport.Message_Support;
      Text    : String;
      Source  : String := "<message>") return ROSIDL.Dynamic.Message
   is
      Doc : constant Document := Parse (Text, Source);
   begin
      return Msg : constant ROSIDL.Dynamic.Message := Init (Support) do
         if Doc.Kind (Doc.Root) = Null_Value then
            Fail (Doc, Doc.Root, Full_Name (Msg.Definition.all) & " is a message: expected a"
                  & " mapping of its fields ({" & Field_Names (Msg.Definition.all)
                  & "}), found nothing ('{}' is the default message)");
         end if;
         Fill (Msg, Doc, Doc.Root);
      end return;
   end From_YAML;

end RCL.YAML.Messages;
