package body ROSIDL.Definitions.Rendering is

   LF : constant Character := ASCII.LF;

   Empty_Member_Name : constant String := "structure_needs_at_least_one_member";
   --  As ROSIDL.Parser.Empty_Member_Name (not with'ed: the parser is a
   --  client of this package's parent, not a dependency of renderings).

   function Value_Image (Kind : Element_Kind; Value : String) return String is
      Result : Unbounded_String;
   begin
      if Kind not in Text_Kind then
         return Value;
      end if;
      Append (Result, '"');
      for C of Value loop
         case C is
            when '"' | '\' =>
               Append (Result, '\' & C);
            when ASCII.LF =>
               Append (Result, "\n");
            when ASCII.HT =>
               Append (Result, "\t");
            when ASCII.CR =>
               Append (Result, "\r");
            when others =>
               Append (Result, C);
         end case;
      end loop;
      Append (Result, '"');
      return To_String (Result);
   end Value_Image;

   function Kind_Image (Kind : Element_Kind) return String is
     (case Kind is
         when Primitive_Kind => Type_Name (Kind),
         when String_Kind    => "string",
         when WString_Kind   => "wstring",
         when Message_Kind   => "message");

   function Type_Image (T : Field_Type; Context_Package : Unbounded_String) return String is
      Full : constant String := Image (T);
   begin
      if T.Kind = Message_Kind and then T.Nested.Package_Name = Context_Package then
         return Full (Full'First + Length (Context_Package) + 1 .. Full'Last);
      end if;
      return Full;
   end Type_Image;

   function Is_Generated (F : Field) return Boolean is
     (F.Position.Line = 0 and then F.Name = Empty_Member_Name);

   procedure Render
     (Def    : Message_Definition;
      Depth  : Natural;
      Expand : Boolean;
      Result : in out Unbounded_String)
   is
      Indent : constant String (1 .. Depth) := [others => ASCII.HT];
      C      : Positive := Def.Constants.First_Index;
      F      : Positive := Def.Fields.First_Index;

      procedure Put_Constant (K : Constant_Definition) is
      begin
         Append (Result, Indent & Kind_Image (K.Kind) & " " & K.Name & "="
                 & Value_Image (K.Kind, To_String (K.Value)) & LF);
      end Put_Constant;

      procedure Put_Field (X : Field) is
      begin
         if Is_Generated (X) then
            return;
         end if;
         Append (Result, Indent & Type_Image (X.Of_Type, Def.Package_Name) & " " & X.Name);
         if Has_Default (X) then
            if X.Of_Type.Collection = Single then
               Append (Result, " " & Value_Image (X.Of_Type.Kind, X.Default.First_Element));
            else
               Append (Result, " [");
               for I in X.Default.First_Index .. X.Default.Last_Index loop
                  Append (Result, (if I = X.Default.First_Index then "" else ", ")
                          & Value_Image (X.Of_Type.Kind, X.Default (I)));
               end loop;
               Append (Result, "]");
            end if;
         end if;
         Append (Result, LF);
         if Expand and then X.Of_Type.Kind = Message_Kind then
            Render (X.Of_Type.Nested.all, Depth + 1, Expand, Result);
         end if;
      end Put_Field;

   begin
      --  Constants and fields merged in the order of their lines.
      while C <= Def.Constants.Last_Index or else F <= Def.Fields.Last_Index loop
         if F > Def.Fields.Last_Index
           or else (C <= Def.Constants.Last_Index
                    and then Def.Constants (C).Position.Line <= Def.Fields (F).Position.Line)
         then
            Put_Constant (Def.Constants (C));
            C := C + 1;
         else
            Put_Field (Def.Fields (F));
            F := F + 1;
         end if;
      end loop;
   end Render;

   function Show (M : Message_Definition; Expand : Boolean := True) return String is
      Result : Unbounded_String;
   begin
      Render (M, 0, Expand, Result);
      return To_String (Result);
   end Show;

   function Show (S : Service_Definition; Expand : Boolean := True) return String is
     (Show (S.Request.all, Expand) & "---" & LF & Show (S.Response.all, Expand));

   function Show (A : Action_Definition; Expand : Boolean := True) return String is
     (Show (A.Goal.all, Expand) & "---" & LF & Show (A.Result.all, Expand) & "---" & LF
      & Show (A.Feedback.all, Expand));

end ROSIDL.Definitions.Rendering;
