package body ROSIDL.Definitions is

   function Type_Name (Kind : Primitive_Kind) return String is
     (case Kind is
         when Bool_Kind    => "bool",
         when Byte_Kind    => "byte",
         when Char_Kind    => "char",
         when Float32_Kind => "float32",
         when Float64_Kind => "float64",
         when Int8_Kind    => "int8",
         when UInt8_Kind   => "uint8",
         when Int16_Kind   => "int16",
         when UInt16_Kind  => "uint16",
         when Int32_Kind   => "int32",
         when UInt32_Kind  => "uint32",
         when Int64_Kind   => "int64",
         when UInt64_Kind  => "uint64");

   function Trimmed (N : Natural) return String is
      S : constant String := N'Image;
   begin
      return S (S'First + 1 .. S'Last);
   end Trimmed;

   function Image (T : Field_Type) return String is

      function Element return String is
        (case T.Kind is
            when Primitive_Kind => Type_Name (T.Kind),
            when String_Kind | WString_Kind =>
              (if T.Kind = String_Kind then "string" else "wstring")
              & (if T.String_Bound > 0 then "<=" & Trimmed (T.String_Bound) else ""),
            when Message_Kind =>
              To_String (T.Nested.Package_Name) & "/" & To_String (T.Nested.Name));

   begin
      return Element
        & (case T.Collection is
              when Single             => "",
              when Fixed_Array        => "[" & Trimmed (T.Size) & "]",
              when Bounded_Sequence   => "[<=" & Trimmed (T.Size) & "]",
              when Unbounded_Sequence => "[]");
   end Image;

   function Image (P : Source_Position) return String is
     (To_String (P.File) & ":" & Trimmed (P.Line) & ":" & Trimmed (P.Column));

   function Namespace_Image (K : Interface_Kind) return String is
     (case K is
         when Msg    => "msg",
         when Srv    => "srv",
         when Action => "action");

   function Full_Name (M : Message_Definition) return String is
     (To_String (M.Package_Name) & "/" & Namespace_Image (M.Namespace) & "/"
      & To_String (M.Name));

   function DDS_Type_Name (M : Message_Definition) return String is
     (To_String (M.Package_Name) & "::" & Namespace_Image (M.Namespace)
      & "::dds_::" & To_String (M.Name) & "_");

   function Field_Index (M : Message_Definition; Name : String) return Natural is
   begin
      for I in M.Fields.First_Index .. M.Fields.Last_Index loop
         if M.Fields (I).Name = Name then
            return I;
         end if;
      end loop;
      return 0;
   end Field_Index;

   function Field_Names (M : Message_Definition) return String is
      Result : Unbounded_String;
   begin
      for F of M.Fields loop
         if Length (Result) > 0 then
            Append (Result, ", ");
         end if;
         Append (Result, F.Name);
      end loop;
      return To_String (Result);
   end Field_Names;

   function Min_Element_Size (T : Field_Type) return Long_Long_Integer is
     (case T.Kind is
         when Primitive_Kind => Long_Long_Integer (Primitive_Size (T.Kind)),
         when String_Kind    => 5,
         when WString_Kind   => 4,
         when Message_Kind   => Min_Size (T.Nested));

   function Min_Size (Def : Message_Access) return Long_Long_Integer is
      Total : Long_Long_Integer := 0;
   begin
      for F of Def.Fields loop
         Total := Total +
           (case F.Of_Type.Collection is
               when Single => Min_Element_Size (F.Of_Type),
               when Fixed_Array =>
                 Long_Long_Integer (F.Of_Type.Size) * Min_Element_Size (F.Of_Type),
               when Bounded_Sequence | Unbounded_Sequence => 4);
      end loop;
      return Long_Long_Integer'Max (Total, 1);
   end Min_Size;

end ROSIDL.Definitions;
