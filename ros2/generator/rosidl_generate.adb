--  rosidl_generate: Ada packages for ROS 2 interface definitions.
--
--     rosidl_generate -o OUTPUT_DIR [--registry UNIT] [--project NAME] FOLDER...
--
--  Every interface package found in the FOLDERs (each holding <pkg>/msg,
--  <pkg>/srv, <pkg>/action) becomes Ada sources in OUTPUT_DIR:
--  <pkg>/msg/<Type> the package ROSIDL.Static.<Pkg>.Messages.<Type>,
--  <pkg>/srv/<Srv> ROSIDL.Static.<Pkg>.Services.<Srv> (nested Request and
--  Response), <pkg>/action/<Act> ROSIDL.Static.<Pkg>.Actions.<Act> (nested
--  Goal, Result, Feedback, FeedbackMessage, SendGoal_Request, ...; Handling,
--  a ROSIDL.Static.Action_Support instance for RCL.Actions.Typed). Types
--  they refer to are found on the library's search path (the bundled
--  share/ros2_interfaces first; ROSIDL.Interfaces). With --registry, UNIT
--  lists every generated type (for tests); with --project, NAME.gpr in
--  OUTPUT_DIR builds the packages as a library (a user's own interfaces,
--  "make interfaces FROM=folder"). Files are rewritten only when
--  their text changes and files of types no longer defined are removed, so
--  that gprbuild recompiles only what changed. Exit status 1 with
--  "file:line:column: ..." on a malformed definition.
with Ada.Characters.Handling;
with Ada.Command_Line;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Ordered_Sets;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with ROSIDL.Definitions;
with ROSIDL.Interfaces;
with ROSIDL.Type_Hashes;

procedure Rosidl_Generate is

   use Ada.Strings.Unbounded;
   use ROSIDL.Definitions;

   package Text_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, String);
   package Name_Sets is new Ada.Containers.Indefinite_Ordered_Sets (String);

   Usage_Error : exception;

   Output_Dir    : Unbounded_String;
   Registry_Unit : Unbounded_String;
   Project_Name  : Unbounded_String;
   Folders       : String_Vectors.Vector;

   Files      : Text_Maps.Map;
   --  File name -> contents, everything to write.
   Registered : String_Vectors.Vector;
   --  Ada paths of the generated message packages (for the registry).
   Units      : Name_Sets.Set;
   --  Every unit generated (for the registry's with clauses).

   NL : constant String := [1 => ASCII.LF];

   ------------
   -- Naming --
   ------------

   Reserved : constant Name_Sets.Set :=
     ["abort", "abs", "abstract", "accept", "access", "aliased", "all", "and", "array", "at",
      "begin", "body", "case", "constant", "declare", "delay", "delta", "digits", "do", "else",
      "elsif", "end", "entry", "exception", "exit", "for", "function", "generic", "goto",
      "if", "in", "interface", "is", "limited", "loop", "mod", "new", "not", "null", "of",
      "or", "others", "out", "overriding", "package", "parallel", "pragma", "private",
      "procedure", "protected", "raise", "range", "record", "rem", "renames", "requeue",
      "return", "reverse", "select", "separate", "some", "subtype", "synchronized", "tagged",
      "task", "terminate", "then", "type", "until", "use", "when", "while", "with", "xor"];

   Package_Level : constant Name_Sets.Set :=
     ["message", "message_array", "default_message", "sequences", "handling", "size_body",
      "write_body", "read_body", "encode", "decode", "encoded_size", "full_name",
      "dds_type_name", "type_hash", "is_bounded", "request", "response", "standard",
      "rosidl", "ada", "interfaces", "system"];

   function Lower (S : String) return String renames Ada.Characters.Handling.To_Lower;

   function Capitalised (Snake : String) return String is
      Result : String := Snake;
      Start  : Boolean := True;
   begin
      for C of Result loop
         if Start then
            C := Ada.Characters.Handling.To_Upper (C);
         end if;
         Start := C = '_';
      end loop;
      return Result;
   end Capitalised;

   function Field_Name (Name : String) return String is
     (if Reserved.Contains (Lower (Name)) then Capitalised (Name) & "_Field"
      else Capitalised (Name));
   --  "frame_id" -> Frame_Id; "type" -> Type_Field.

   function Constant_Name (Name : String) return String is
     (if Reserved.Contains (Lower (Name)) or else Package_Level.Contains (Lower (Name))
      then Name & "_Constant" else Name);

   function Type_Name (Name : String) return String is
     (if Reserved.Contains (Lower (Name)) or else Package_Level.Contains (Lower (Name))
      then Name & "_Type" else Name);
   --  "Range" -> Range_Type (sensor_msgs/msg/Range).

   function Package_Name (Ros_Package : String) return String is (Capitalised (Ros_Package));

   function Trim (N : Long_Long_Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Trim (N : Natural) return String is (Trim (Long_Long_Integer (N)));

   function Split_Part (Name : String) return Natural is
     (Ada.Strings.Fixed.Index (Name, "_"));

   function Unit_Of (Def : Message_Definition) return String is
      Pkg  : constant String := Package_Name (To_String (Def.Package_Name));
      Name : constant String := To_String (Def.Name);
      Cut  : constant Natural := Split_Part (Name);
   begin
      case Def.Namespace is
         when Msg =>
            return "ROSIDL.Static." & Pkg & ".Messages." & Type_Name (Name);
         when Srv =>
            return "ROSIDL.Static." & Pkg & ".Services." & Type_Name (Name (Name'First .. Cut - 1));
         when Action =>
            return "ROSIDL.Static." & Pkg & ".Actions." & Type_Name (Name (Name'First .. Cut - 1));
      end case;
   end Unit_Of;
   --  The library unit holding a message (a service's or action's parts
   --  share the unit of their service or action).

   function Path_Of (Def : Message_Definition) return String is
      Name : constant String := To_String (Def.Name);
   begin
      if Def.Namespace = Msg then
         return Unit_Of (Def);
      end if;
      return Unit_Of (Def) & "." & Name (Split_Part (Name) + 1 .. Name'Last);
   end Path_Of;
   --  The Ada package holding a message's record:
   --  ROSIDL.Static.Example_Interfaces.Services.AddTwoInts.Request.

   function File_Of (Unit : String; Body_File : Boolean) return String is
      Result : String := Lower (Unit);
   begin
      for C of Result loop
         if C = '.' then
            C := '-';
         end if;
      end loop;
      return Result & (if Body_File then ".adb" else ".ads");
   end File_Of;

   -------------------------------
   -- Ada types of field types --
   -------------------------------

   function Prim_Name (K : Primitive_Kind) return String is
     (case K is
         when Bool_Kind => "Bool", when Byte_Kind | Char_Kind | UInt8_Kind => "UInt8",
         when Int8_Kind => "Int8", when Int16_Kind => "Int16", when UInt16_Kind => "UInt16",
         when Int32_Kind => "Int32", when UInt32_Kind => "UInt32", when Int64_Kind => "Int64",
         when UInt64_Kind => "UInt64", when Float32_Kind => "Float32",
         when Float64_Kind => "Float64");

   function Prim_Type (K : Primitive_Kind) return String is
     (if K = Bool_Kind then "Standard.Boolean"
      else "ROSIDL." & (case K is
                           when Byte_Kind => "Byte", when Char_Kind => "Char",
                           when others => Prim_Name (K)));

   function Codec (K : Primitive_Kind) return String is
     ("ROSIDL.Static.Impl.Codecs." & Prim_Name (K) & "_Codec");

   function Zero (K : Primitive_Kind) return String is
     (case K is
         when Bool_Kind => "False",
         when Float_Kind => "0.0",
         when others => "0");

   function Bounded_Text_Package (T : Field_Type) return String is
     ((if T.Kind = String_Kind then "Bounded_String_" else "Bounded_WString_")
      & Trim (T.String_Bound));
   --  A local instance of Ada.Strings[.Wide_Wide].Bounded, per bound.

   function Element_Type (T : Field_Type) return String is
     (case T.Kind is
         when Primitive_Kind => Prim_Type (T.Kind),
         when String_Kind =>
           (if T.String_Bound = 0 then "Ada.Strings.Unbounded.Unbounded_String"
            else Bounded_Text_Package (T) & ".Bounded_String"),
         when WString_Kind =>
           (if T.String_Bound = 0
            then "Ada.Strings.Wide_Wide_Unbounded.Unbounded_Wide_Wide_String"
            else Bounded_Text_Package (T) & ".Bounded_Wide_Wide_String"),
         when Message_Kind => Path_Of (T.Nested.all) & ".Message");

   function Element_Array (T : Field_Type) return String is
     (case T.Kind is
         when Primitive_Kind => "ROSIDL.Static." & Prim_Name (T.Kind) & "_Array",
         when String_Kind | WString_Kind =>
           (if T.String_Bound = 0
            then "ROSIDL.Static." & (if T.Kind = String_Kind then "String" else "WString")
                 & "_Array"
            else Bounded_Text_Package (T) & "_Array"),
         when Message_Kind => Path_Of (T.Nested.all) & ".Message_Array");

   function Element_Default (T : Field_Type) return String is
     (case T.Kind is
         when Primitive_Kind => Zero (T.Kind),
         when String_Kind =>
           (if T.String_Bound = 0 then "Ada.Strings.Unbounded.Null_Unbounded_String"
            else Bounded_Text_Package (T) & ".Null_Bounded_String"),
         when WString_Kind =>
           (if T.String_Bound = 0
            then "Ada.Strings.Wide_Wide_Unbounded.Null_Unbounded_Wide_Wide_String"
            else Bounded_Text_Package (T) & ".Null_Bounded_Wide_Wide_String"),
         when Message_Kind => Path_Of (T.Nested.all) & ".Default_Message");

   function Element_Equality (T : Field_Type) return String is
     (case T.Kind is
         when Bool_Kind => "Standard.""=""",
         when Byte_Kind .. UInt64_Kind => "Interfaces.""=""",
         when String_Kind | WString_Kind =>
           (if T.String_Bound = 0
            then (if T.Kind = String_Kind then "Ada.Strings.Unbounded.""="""
                  else "Ada.Strings.Wide_Wide_Unbounded.""=""")
            else Bounded_Text_Package (T) & ".""="""),
         when Message_Kind => Path_Of (T.Nested.all) & ".""=""");

   function Unbounded_Sequence (T : Field_Type) return String is
     (case T.Kind is
         when Primitive_Kind =>
           "ROSIDL.Static.Sequences." & Prim_Name (T.Kind) & "_Sequences.Sequence",
         when String_Kind | WString_Kind =>
           (if T.String_Bound = 0
            then "ROSIDL.Static.Sequences."
                 & (if T.Kind = String_Kind then "String" else "WString") & "_Sequences.Sequence"
            else Bounded_Text_Package (T) & "_Sequences.Sequence"),
         when Message_Kind => Path_Of (T.Nested.all) & ".Sequences.Sequence");

   function Component_Type (F : Field) return String is
      T : constant Field_Type := F.Of_Type;
   begin
      case T.Collection is
         when Single => return Element_Type (T);
         when Fixed_Array => return Element_Array (T) & " (0 .. " & Trim (T.Size - 1) & ")";
         when Unbounded_Sequence => return Unbounded_Sequence (T);
         when Bounded_Sequence => return Field_Name (To_String (F.Name)) & "_Sequences.Sequence";
      end case;
   end Component_Type;

   function Is_Bounded (Def : Message_Access) return Boolean is
   begin
      for F of Def.Fields loop
         declare
            T : constant Field_Type := F.Of_Type;
         begin
            if T.Collection = Unbounded_Sequence
              or else (T.Kind in Text_Kind and then T.String_Bound = 0)
              or else (T.Kind = Message_Kind and then not Is_Bounded (T.Nested))
            then
               return False;
            end if;
         end;
      end loop;
      return True;
   end Is_Bounded;

   --------------------
   -- Default values --
   --------------------

   function String_Literal (S : String) return String is
      Result : Unbounded_String := To_Unbounded_String ("""");
      Open   : Boolean := True;
   begin
      for C of S loop
         if Character'Pos (C) in 32 .. 126 then
            if not Open then
               Append (Result, " & """);
               Open := True;
            end if;
            Append (Result, (if C = '"' then """""" else [1 => C]));
         else
            if Open then
               Append (Result, """");
               Open := False;
            end if;
            Append (Result, " & Standard.Character'Val ("
                    & Trim (Natural'(Character'Pos (C))) & ")");
         end if;
      end loop;
      if Open then
         Append (Result, """");
      end if;
      return To_String (Result);
   end String_Literal;

   function Scalar_Value (T : Field_Type; Value : String) return String is
   begin
      case T.Kind is
         when Bool_Kind =>
            return (if Value = "true" then "True" else "False");
         when Float_Kind =>
            if Value = "inf" then
               return "ROSIDL.Static.Infinity";
            elsif Value = "-inf" then
               return "-ROSIDL.Static.Infinity";
            elsif Value = "nan" then
               return "ROSIDL.Static.NaN";
            end if;
            return Value;
         when Integer_Kind | Byte_Kind | Char_Kind =>
            return Value;
         when String_Kind =>
            return (if T.String_Bound = 0 then "Ada.Strings.Unbounded.To_Unbounded_String ("
                    else Bounded_Text_Package (T) & ".To_Bounded_String (")
              & String_Literal (Value) & ")";
         when WString_Kind =>
            return (if T.String_Bound = 0
                    then "Ada.Strings.Wide_Wide_Unbounded.To_Unbounded_Wide_Wide_String ("
                    else Bounded_Text_Package (T) & ".To_Bounded_Wide_Wide_String (")
              & "Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode "
              & "(Ada.Strings.UTF_Encoding.UTF_8_String'("
              & String_Literal (Value) & ")))";
         when Message_Kind =>
            raise Program_Error;
      end case;
   end Scalar_Value;

   function Aggregate (T : Field_Type; Values : String_Vectors.Vector) return String is
      Result : Unbounded_String := To_Unbounded_String ("[");
   begin
      for I in Values.First_Index .. Values.Last_Index loop
         if I > Values.First_Index then
            Append (Result, ", ");
         end if;
         Append (Result, Scalar_Value (T, Values (I)));
      end loop;
      return To_String (Result) & "]";
   end Aggregate;

   function Default_Of (F : Field) return String is
      T : constant Field_Type := F.Of_Type;
   begin
      if T.Kind = Message_Kind then
         return "";
      end if;
      case T.Collection is
         when Single =>
            if Has_Default (F) then
               return Scalar_Value (T, F.Default.First_Element);
            elsif T.Kind in Primitive_Kind then
               return Zero (T.Kind);
            end if;
         when Fixed_Array =>
            if Has_Default (F) then
               return Aggregate (T, F.Default);
            elsif T.Kind in Primitive_Kind then
               return "[others => " & Zero (T.Kind) & "]";
            end if;
         when Unbounded_Sequence | Bounded_Sequence =>
            if Has_Default (F) then
               return Ada.Strings.Fixed.Head
                 (Component_Type (F), Component_Type (F)'Length - 9)
                 & ".To_Sequence (" & Aggregate (T, F.Default) & ")";
            end if;
      end case;
      return "";
   end Default_Of;

   --------------
   -- Emitting --
   --------------

   type Emitter is record
      Spec, Impl : Unbounded_String;
      Withs      : Name_Sets.Set;
      Self_Unit  : Unbounded_String;
   end record;

   procedure Line (To : in out Unbounded_String; Indent : Natural; Text : String) is
   begin
      Append (To, [1 .. Indent => ' '] & Text & NL);
   end Line;

   procedure Need_Unit (E : in out Emitter; T : Field_Type) is
   begin
      if T.Kind = Message_Kind then
         declare
            Unit : constant String := Unit_Of (T.Nested.all);
         begin
            if Unit /= To_String (E.Self_Unit) then
               E.Withs.Include (Unit);
            end if;
         end;
      end if;
   end Need_Unit;

   --  The statements of the three passes for one element held in Expr.
   function Size_Element (T : Field_Type; Expr : String) return String is
     (case T.Kind is
         when Primitive_Kind =>
           "ROSIDL.Static.Impl.Wire.Add (Pos, " & Trim (Primitive_Size (T.Kind)) & ", "
           & Trim (Primitive_Size (T.Kind)) & ");",
         when String_Kind =>
           "ROSIDL.Static.Impl.Wire.Add_String (Pos, "
           & (if T.String_Bound = 0 then "Ada.Strings.Unbounded" else Bounded_Text_Package (T))
           & ".Length (" & Expr & "));",
         when WString_Kind =>
           "ROSIDL.Static.Impl.Wire.Add_WString (Pos, "
           & (if T.String_Bound = 0 then "Ada.Strings.Wide_Wide_Unbounded"
              else Bounded_Text_Package (T))
           & ".Length (" & Expr & "));",
         when Message_Kind => Path_Of (T.Nested.all) & ".Size_Body (" & Expr & ", Pos);");

   function Write_Element (T : Field_Type; Expr : String) return String is
     (case T.Kind is
         when Primitive_Kind => Codec (T.Kind) & ".Put (B, C, " & Expr & ");",
         when String_Kind =>
           "ROSIDL.Static.Impl.Wire.Put_String (B, C, "
           & (if T.String_Bound = 0 then Expr
              else Bounded_Text_Package (T) & ".To_String (" & Expr & ")") & ");",
         when WString_Kind =>
           "ROSIDL.Static.Impl.Wire.Put_WString (B, C, "
           & (if T.String_Bound = 0 then "Ada.Strings.Wide_Wide_Unbounded"
              else Bounded_Text_Package (T))
           & ".To_Wide_Wide_String (" & Expr & "));",
         when Message_Kind => Path_Of (T.Nested.all) & ".Write_Body (" & Expr & ", B, C);");

   function Read_Element (T : Field_Type; Expr, What : String) return String is
     (case T.Kind is
         when Primitive_Kind => Codec (T.Kind) & ".Get (B, C, " & Expr & ", " & What & ");",
         when String_Kind =>
           (if T.String_Bound = 0
            then "ROSIDL.Static.Impl.Wire.Get_String (B, C, 0, " & Expr & ", " & What & ");"
            else Expr & " := " & Bounded_Text_Package (T)
                 & ".To_Bounded_String (ROSIDL.Static.Impl.Wire.Text (B, "
                 & "ROSIDL.Static.Impl.Wire.Get_String_Span (B, C, " & Trim (T.String_Bound)
                 & ", " & What & ")));"),
         when WString_Kind =>
           (if T.String_Bound = 0
            then "ROSIDL.Static.Impl.Wire.Get_WString (B, C, 0, " & Expr & ", " & What & ");"
            else Expr & " := " & Bounded_Text_Package (T)
                 & ".To_Bounded_Wide_Wide_String (ROSIDL.Static.Impl.Wire.Get_WString (B, C, "
                 & Trim (T.String_Bound) & ", " & What & "));"),
         when Message_Kind => Path_Of (T.Nested.all) & ".Read_Body (B, C, " & Expr & ");");

   function Relative (Where : String; Def : Message_Access) return String is
      Pkg : constant String := "/" & To_String (Def.Package_Name) & "/";
      At_Pkg : constant Natural := Ada.Strings.Fixed.Index (Where, Pkg, Ada.Strings.Backward);
   begin
      return (if At_Pkg = 0 then Where else Where (At_Pkg + 1 .. Where'Last));
   end Relative;
   --  "std_msgs/msg/Header.msg:1:1": the same text in every checkout.

   procedure Emit_Message
     (E : in out Emitter; Def : Message_Access; Simple_Name : String; Indent : Natural)
   is
      Spec : Unbounded_String renames E.Spec;
      Impl : Unbounded_String renames E.Impl;
      I    : constant Natural := Indent;
      Path : constant String := Path_Of (Def.all);
      Full : constant String := Full_Name (Def.all);
      Text_Packages : Name_Sets.Set;
      Sequence_Packages : Name_Sets.Set;
   begin
      Line (Spec, I, "--  " & Full & " (" & Relative (Image (Def.Position), Def) & ")");
      Line (Spec, I, "package " & Simple_Name & " is");
      Line (Spec, I, "");
      Line (Spec, I + 3, "Full_Name : constant Standard.String := """ & Full & """;");
      Line (Spec, I + 3, "DDS_Type_Name : constant Standard.String := """
            & DDS_Type_Name (Def.all) & """;");
      Line (Spec, I + 3, "Type_Hash : constant Standard.String := """
            & ROSIDL.Type_Hashes.Hash (Def) & """;");
      Line (Spec, I + 3, "Is_Bounded : constant Standard.Boolean := "
            & (if Is_Bounded (Def) then "True" else "False") & ";");
      Line (Spec, I + 3,
            (if Is_Bounded (Def)
             then "--  No unbounded string or sequence: a message needs no heap."
             else "--  An unbounded string or sequence (maybe nested): a message allocates."));
      Line (Spec, I, "");

      --  Constants.
      for K of Def.Constants loop
         declare
            T : constant Field_Type := (Kind => K.Kind, others => <>);
            V : constant String := To_String (K.Value);
         begin
            Line (Spec, I + 3, Constant_Name (To_String (K.Name)) & " : constant "
                  & (case K.Kind is
                        when Primitive_Kind => Prim_Type (K.Kind) & " := " & Scalar_Value (T, V),
                        when String_Kind => "Standard.String := " & String_Literal (V),
                        when others =>
                          "Standard.Wide_Wide_String := "
                          & "Ada.Strings.UTF_Encoding.Wide_Wide_Strings.Decode "
              & "(Ada.Strings.UTF_Encoding.UTF_8_String'("
                          & String_Literal (V) & "))")
                  & ";");
         end;
      end loop;
      if not Def.Constants.Is_Empty then
         Line (Spec, I, "");
      end if;

      --  Local instances: bounded strings, their arrays and sequences,
      --  bounded sequences.
      for F of Def.Fields loop
         declare
            T : constant Field_Type := F.Of_Type;
            P : constant String := Bounded_Text_Package (T);
         begin
            Need_Unit (E, T);
            if T.Kind in Text_Kind and then T.String_Bound > 0
              and then not Text_Packages.Contains (P)
            then
               Text_Packages.Insert (P);
               if T.Kind = String_Kind then
                  Line (Spec, I + 3, "package " & P & " is new Ada.Strings.Bounded."
                        & "Generic_Bounded_Length (" & Trim (T.String_Bound) & ");");
                  Line (Spec, I + 3, "type " & P & "_Array is array (Natural range <>) "
                        & "of aliased " & P & ".Bounded_String;");
               else
                  Line (Spec, I + 3, "package " & P & " is new Ada.Strings.Wide_Wide_Bounded."
                        & "Generic_Bounded_Length (" & Trim (T.String_Bound) & ");");
                  Line (Spec, I + 3, "type " & P & "_Array is array (Natural range <>) "
                        & "of aliased " & P & ".Bounded_Wide_Wide_String;");
               end if;
            end if;
            if T.Kind in Text_Kind and then T.String_Bound > 0
              and then T.Collection = Unbounded_Sequence
              and then not Sequence_Packages.Contains (P)
            then
               Sequence_Packages.Insert (P);
               Line (Spec, I + 3, "package " & P & "_Sequences is new "
                     & "ROSIDL.Static.Unbounded_Sequences (" & Element_Type (T) & ", "
                     & Element_Array (T) & ", " & Element_Default (T) & ", " & P & ".""="");");
            end if;
            if T.Collection = Bounded_Sequence then
               Line (Spec, I + 3, "package " & Field_Name (To_String (F.Name))
                     & "_Sequences is new ROSIDL.Static.Bounded_Sequences ("
                     & Element_Type (T) & ", " & Element_Array (T) & ", " & Trim (T.Size)
                     & ", " & Element_Default (T) & ", " & Element_Equality (T) & ");");
            end if;
         end;
      end loop;

      --  The record.
      Line (Spec, I + 3, "type Message is record");
      for F of Def.Fields loop
         declare
            Default : constant String := Default_Of (F);
         begin
            Line (Spec, I + 6, Field_Name (To_String (F.Name)) & " : " & Component_Type (F)
                  & (if Default = "" then "" else " := " & Default) & ";");
         end;
      end loop;
      Line (Spec, I + 3, "end record;");
      Line (Spec, I, "");
      Line (Spec, I + 3, "type Message_Array is array (Natural range <>) of aliased Message;");
      Line (Spec, I + 3, "Default_Message : constant Message := (others => <>);");
      Line (Spec, I + 3, "package Sequences is new ROSIDL.Static.Unbounded_Sequences "
            & "(Message, Message_Array, Default_Message);");
      Line (Spec, I, "");
      Line (Spec, I + 3, "--  For generated code (ROSIDL.Static.Impl): the body codec, "
            & "the actuals of Handling.");
      Line (Spec, I + 3, "procedure Size_Body (Msg : Message; "
            & "Pos : in out Ada.Streams.Stream_Element_Offset);");
      Line (Spec, I + 3, "procedure Write_Body (Msg : Message; "
            & "B : in out Ada.Streams.Stream_Element_Array; "
            & "C : in out ROSIDL.Static.Impl.Wire.Cursor);");
      Line (Spec, I + 3, "procedure Read_Body (B : Ada.Streams.Stream_Element_Array; "
            & "C : in out ROSIDL.Static.Impl.Wire.Cursor; Msg : in out Message);");
      Line (Spec, I, "");
      Line (Spec, I + 3, "package Handling is new ROSIDL.Static.Message_Support");
      Line (Spec, I + 5, "(Message, Full_Name, DDS_Type_Name, Type_Hash, Is_Bounded,");
      Line (Spec, I + 6, "Size_Body, Write_Body, Read_Body);");
      Line (Spec, I, "");
      Line (Spec, I + 3, "function Encode (Msg : Message; Order : ROSIDL.CDR.Byte_Order := "
            & "ROSIDL.CDR.Native_Order) return Ada.Streams.Stream_Element_Array");
      Line (Spec, I + 5, "renames Handling.Encode;");
      Line (Spec, I + 3, "function Decode (Data : Ada.Streams.Stream_Element_Array) "
            & "return Message");
      Line (Spec, I + 5, "renames Handling.Decode;");
      Line (Spec, I + 3, "procedure Decode (Data : Ada.Streams.Stream_Element_Array; "
            & "Msg : in out Message)");
      Line (Spec, I + 5, "renames Handling.Decode;");
      Line (Spec, I, "");
      Line (Spec, I, "end " & Simple_Name & ";");

      --  The body.
      Line (Impl, I, "package body " & Simple_Name & " is");
      Line (Impl, I, "");

      --  Size pass.
      Line (Impl, I + 3, "procedure Size_Body (Msg : Message; "
            & "Pos : in out Ada.Streams.Stream_Element_Offset) is");
      Line (Impl, I + 3, "begin");
      for F of Def.Fields loop
         declare
            T   : constant Field_Type := F.Of_Type;
            X   : constant String := "Msg." & Field_Name (To_String (F.Name));
            Sz  : constant String :=
              (if T.Kind in Primitive_Kind then Trim (Primitive_Size (T.Kind)) else "");
         begin
            case T.Collection is
               when Single =>
                  Line (Impl, I + 6, Size_Element (T, X));
               when Fixed_Array =>
                  if T.Kind in Primitive_Kind then
                     Line (Impl, I + 6, "ROSIDL.Static.Impl.Wire.Add (Pos, " & Sz & ", "
                           & Trim (T.Size * Primitive_Size (T.Kind)) & ");");
                  else
                     Line (Impl, I + 6, "for E of " & X & " loop "
                           & Size_Element (T, "E") & " end loop;");
                  end if;
               when Unbounded_Sequence | Bounded_Sequence =>
                  Line (Impl, I + 6, "ROSIDL.Static.Impl.Wire.Add (Pos, 4, 4);");
                  if T.Kind in Primitive_Kind then
                     Line (Impl, I + 6, "if " & X & ".Length > 0 then "
                           & "ROSIDL.Static.Impl.Wire.Add (Pos, " & Sz
                           & ", Ada.Streams.Stream_Element_Offset (" & X & ".Length) * "
                           & Sz & "); end if;");
                  elsif T.Collection = Unbounded_Sequence then
                     Line (Impl, I + 6, "if " & X & ".Length > 0 then for E of " & X
                           & ".Storage (0 .. " & X & ".Length - 1) loop "
                           & Size_Element (T, "E") & " end loop; end if;");
                  else
                     Line (Impl, I + 6, "for E of " & X & ".Items (0 .. " & X
                           & ".Length - 1) loop " & Size_Element (T, "E") & " end loop;");
                  end if;
            end case;
         end;
      end loop;
      Line (Impl, I + 3, "end Size_Body;");
      Line (Impl, I, "");

      --  Write pass.
      Line (Impl, I + 3, "procedure Write_Body (Msg : Message; "
            & "B : in out Ada.Streams.Stream_Element_Array; "
            & "C : in out ROSIDL.Static.Impl.Wire.Cursor) is");
      Line (Impl, I + 3, "begin");
      for F of Def.Fields loop
         declare
            T : constant Field_Type := F.Of_Type;
            X : constant String := "Msg." & Field_Name (To_String (F.Name));
            Items : constant String :=
              (case T.Collection is
                  when Single | Fixed_Array => X,
                  when Unbounded_Sequence => X & ".Storage (0 .. " & X & ".Length - 1)",
                  when Bounded_Sequence => X & ".Items (0 .. " & X & ".Length - 1)");
            Guard : constant Boolean := T.Collection = Unbounded_Sequence;
         begin
            if T.Collection in Unbounded_Sequence | Bounded_Sequence then
               Line (Impl, I + 6, "ROSIDL.Static.Impl.Wire.Put_Count (B, C, " & X & ".Length);");
            end if;
            if T.Collection = Single then
               Line (Impl, I + 6, Write_Element (T, X));
            else
               Line (Impl, I + 6,
                     (if Guard then "if " & X & ".Length > 0 then " else "")
                     & (if T.Kind in Primitive_Kind
                        then Codec (T.Kind) & ".Put_Array (B, C, " & Items & ");"
                        else "for E of " & Items & " loop " & Write_Element (T, "E")
                             & " end loop;")
                     & (if Guard then " end if;" else ""));
            end if;
         end;
      end loop;
      Line (Impl, I + 3, "end Write_Body;");
      Line (Impl, I, "");

      --  Read pass.
      Line (Impl, I + 3, "procedure Read_Body (B : Ada.Streams.Stream_Element_Array; "
            & "C : in out ROSIDL.Static.Impl.Wire.Cursor; Msg : in out Message) is");
      Line (Impl, I + 3, "begin");
      for F of Def.Fields loop
         declare
            T    : constant Field_Type := F.Of_Type;
            X    : constant String := "Msg." & Field_Name (To_String (F.Name));
            What : constant String := """" & Full & "." & To_String (F.Name) & """";
         begin
            case T.Collection is
               when Single =>
                  Line (Impl, I + 6, Read_Element (T, X, What));
               when Fixed_Array =>
                  if T.Kind in Primitive_Kind then
                     Line (Impl, I + 6, Codec (T.Kind) & ".Get_Array (B, C, " & X & ", "
                           & What & ");");
                  else
                     Line (Impl, I + 6, "for E of " & X & " loop "
                           & Read_Element (T, "E", What) & " end loop;");
                  end if;
               when Unbounded_Sequence | Bounded_Sequence =>
                  declare
                     Items : constant String :=
                       (if T.Collection = Unbounded_Sequence
                        then X & ".Storage (0 .. Count - 1)" else X & ".Items (0 .. Count - 1)");
                  begin
                     Line (Impl, I + 6, "declare");
                     Line (Impl, I + 9, "Count : constant Natural := "
                           & "ROSIDL.Static.Impl.Wire.Get_Count (B, C, "
                           & Trim (Min_Element_Size (T)) & ", "
                           & (if T.Collection = Bounded_Sequence then Trim (T.Size) else "0")
                           & ", " & What & ");");
                     Line (Impl, I + 6, "begin");
                     if T.Collection = Unbounded_Sequence then
                        Line (Impl, I + 9, X & ".Set_Length (Count);");
                     else
                        Line (Impl, I + 9, X & ".Length := Count;");
                     end if;
                     Line (Impl, I + 9, "if Count > 0 then");
                     if T.Kind in Primitive_Kind then
                        Line (Impl, I + 12, Codec (T.Kind) & ".Get_Array (B, C, " & Items
                              & ", " & What & ");");
                     else
                        Line (Impl, I + 12, "for E of " & Items & " loop "
                              & Read_Element (T, "E", What) & " end loop;");
                     end if;
                     Line (Impl, I + 9, "end if;");
                     Line (Impl, I + 6, "end;");
                  end;
            end case;
         end;
      end loop;
      Line (Impl, I + 3, "end Read_Body;");
      Line (Impl, I, "");
      Line (Impl, I, "end " & Simple_Name & ";");

      Registered.Append (Path);
   end Emit_Message;

   Spec_Header : constant String :=
     "--  Generated by rosidl_generate (ros2/generator): do not edit." & NL
     & "pragma Style_Checks (Off);" & NL
     & "pragma Warnings (Off);" & NL
     & "pragma Validity_Checks (Off);" & NL;

   Body_Header : constant String :=
     "--  Generated by rosidl_generate (ros2/generator): do not edit." & NL
     & "pragma Style_Checks (Off);" & NL
     & "pragma Warnings (Off);" & NL
     & "pragma Validity_Checks (Off);" & NL
     & "with Ada.Streams;" & NL
     & "with ROSIDL.Static.Impl.Codecs;" & NL
     & "use type Ada.Streams.Stream_Element_Offset;" & NL;

   Spec_Withs : constant String :=
     "with Ada.Streams;" & NL
     & "with Ada.Strings.Bounded;" & NL
     & "with Ada.Strings.Unbounded;" & NL
     & "with Ada.Strings.UTF_Encoding.Wide_Wide_Strings;" & NL
     & "with Ada.Strings.Wide_Wide_Bounded;" & NL
     & "with Ada.Strings.Wide_Wide_Unbounded;" & NL
     & "with Interfaces;" & NL
     & "use type Interfaces.Integer_8, Interfaces.Integer_16, Interfaces.Integer_32," & NL
     & "   Interfaces.Integer_64, Interfaces.IEEE_Float_32, Interfaces.IEEE_Float_64;" & NL
     & "with ROSIDL.CDR;" & NL
     & "with ROSIDL.Static.Bounded_Sequences;" & NL
     & "with ROSIDL.Static.Message_Support;" & NL
     & "with ROSIDL.Static.Sequences;" & NL
     & "with ROSIDL.Static.Service_Support;" & NL
     & "with ROSIDL.Static.Unbounded_Sequences;" & NL
     & "with ROSIDL.Static.Impl.Wire;" & NL;

   procedure Store (File, Text : String) is
   begin
      Files.Include (File, Text);
   end Store;

   procedure Store_Unit (E : Emitter; Unit : String) is
      Withs : Unbounded_String;
   begin
      for W of E.Withs loop
         Append (Withs, "with " & W & ";" & NL);
      end loop;
      Store (File_Of (Unit, False), Spec_Header & Spec_Withs & To_String (Withs) & NL
             & To_String (E.Spec));
      Store (File_Of (Unit, True), Body_Header & NL & To_String (E.Impl));
      Units.Include (Unit);
   end Store_Unit;

   procedure Parent_Unit (Unit : String) is
   begin
      if not Files.Contains (File_Of (Unit, False)) then
         Store (File_Of (Unit, False), Spec_Header & "package " & Unit & " is" & NL
                & "end " & Unit & ";" & NL);
      end if;
   end Parent_Unit;

   procedure Generate_Message (Def : Message_Access) is
      Unit : constant String := Unit_Of (Def.all);
      Cut  : constant Natural := Ada.Strings.Fixed.Index (Unit, ".", Ada.Strings.Backward);
      E    : Emitter;
   begin
      E.Self_Unit := To_Unbounded_String (Unit);
      Emit_Message (E, Def, Unit, 0);
      Store_Unit (E, Unit);
      Parent_Unit (Unit (Unit'First .. Cut - 1));
   end Generate_Message;

   type Message_Access_Array is array (Positive range <>) of Message_Access;

   procedure Generate_Parts
     (Unit       : String;
      Parts      : Message_Access_Array;
      Full       : String;
      Is_Service : Boolean)
   is
      Cut : constant Natural := Ada.Strings.Fixed.Index (Unit, ".", Ada.Strings.Backward);
      E   : Emitter;
   begin
      E.Self_Unit := To_Unbounded_String (Unit);
      Line (E.Spec, 0, "package " & Unit & " is");
      Line (E.Spec, 0, "");
      Line (E.Spec, 3, "Full_Name : constant Standard.String := """ & Full & """;");
      Line (E.Spec, 0, "");
      Line (E.Impl, 0, "package body " & Unit & " is");
      Line (E.Impl, 0, "");
      for P of Parts loop
         declare
            Path : constant String := Path_Of (P.all);
         begin
            Emit_Message (E, P, Path (Ada.Strings.Fixed.Index
                                        (Path, ".", Ada.Strings.Backward) + 1 .. Path'Last), 3);
            Line (E.Spec, 0, "");
            Line (E.Impl, 0, "");
         end;
      end loop;
      if Is_Service then
         Line (E.Spec, 3, "package Handling is new ROSIDL.Static.Service_Support");
         Line (E.Spec, 5, "(Request.Handling, Response.Handling, Full_Name);");
         Line (E.Spec, 0, "");
      else
         E.Withs.Include ("ROSIDL.Static.Action_Support");
         Line (E.Spec, 3, "package Handling is new ROSIDL.Static.Action_Support");
         Line (E.Spec, 5, "(Goal.Handling, Result.Handling, Feedback.Handling, Full_Name);");
         Line (E.Spec, 0, "");
      end if;
      Line (E.Spec, 0, "end " & Unit & ";");
      Line (E.Impl, 0, "end " & Unit & ";");
      Store_Unit (E, Unit);
      Parent_Unit (Unit (Unit'First .. Cut - 1));
   end Generate_Parts;

   procedure Generate_Package (Pkg : String) is
      Root : constant String := "ROSIDL.Static." & Package_Name (Pkg);
   begin
      Parent_Unit (Root);
      for Name of ROSIDL.Interfaces.Messages (Pkg) loop
         Generate_Message (ROSIDL.Interfaces.Message (Pkg, Name));
      end loop;
      for Name of ROSIDL.Interfaces.Services (Pkg) loop
         declare
            S : constant Service_Access := ROSIDL.Interfaces.Service (Pkg, Name);
         begin
            Generate_Parts (Root & ".Services." & Type_Name (Name), [S.Request, S.Response],
                            Pkg & "/srv/" & Name, Is_Service => True);
         end;
      end loop;
      for Name of ROSIDL.Interfaces.Actions (Pkg) loop
         declare
            A : constant Action_Access := ROSIDL.Interfaces.Action (Pkg, Name);
         begin
            Generate_Parts
              (Root & ".Actions." & Type_Name (Name),
               [A.Goal, A.Result, A.Feedback, A.Feedback_Message,
                A.Send_Goal.Request, A.Send_Goal.Response,
                A.Get_Result.Request, A.Get_Result.Response],
               Pkg & "/action/" & Name, Is_Service => False);
         end;
      end loop;
   end Generate_Package;

   procedure Generate_Registry (Unit : String) is
      Spec : Unbounded_String := To_Unbounded_String (Spec_Header);
   begin
      Append (Spec, "with ROSIDL.Static.Registries;" & NL);
      for U of Units loop
         Append (Spec, "with " & U & ";" & NL);
      end loop;
      Append (Spec, NL & "--  Every type generated with this registry, for tests." & NL);
      Line (Spec, 0, "package " & Unit & " is");
      Line (Spec, 3, "use ROSIDL.Static.Registries;");
      Line (Spec, 3, "Types : constant Type_Entries := [");
      for I in Registered.First_Index .. Registered.Last_Index loop
         declare
            P : constant String := Registered (I);
         begin
            Line (Spec, 6, "(new Standard.String'(" & P & ".Full_Name), new Standard.String'("
                  & P & ".DDS_Type_Name), new Standard.String'(" & P & ".Type_Hash), "
                  & P & ".Is_Bounded, " & P & ".Handling.Recode'Access, "
                  & P & ".Handling.Recode_Into'Access, "
                  & P & ".Handling.Round_Trips'Access, "
                  & P & ".Handling.Encode_Default'Access)"
                  & (if I = Registered.Last_Index then "];" else ","));
         end;
      end loop;
      Line (Spec, 0, "end " & Unit & ";");
      Store (File_Of (Unit, False), To_String (Spec));
   end Generate_Registry;

   --  A library project of the generated sources, withing the bundled
   --  types' project of this installation (bin/..).
   procedure Generate_Project (Name : String) is
      use Ada.Directories;
      Root : constant String :=
        Containing_Directory (Containing_Directory (Full_Name (Ada.Command_Line.Command_Name)));
   begin
      Store (Lower (Name) & ".gpr",
             "--  Generated by rosidl_generate (ros2/generator): do not edit." & NL
             & "with """ & Root & "/common.gpr"";" & NL
             & "with """ & Root & "/ros2/rclada_messages.gpr"";" & NL & NL
             & "library project " & Name & " is" & NL
             & "   for Source_Dirs use (""."");" & NL
             & "   for Object_Dir use ""obj/"" & Common.Build_Mode;" & NL
             & "   for Library_Dir use ""lib/"" & Common.Build_Mode;" & NL
             & "   for Library_Name use """ & Lower (Name) & """;" & NL
             & "   package Compiler renames RCLAda_Messages.Compiler;" & NL
             & "end " & Name & ";" & NL);
   end Generate_Project;

   --  Writes what changed, removes what is no longer generated.
   procedure Write_All is
      use Ada.Directories;
      Dir     : constant String := To_String (Output_Dir);
      Written : Natural := 0;
      Removed : Natural := 0;

      function Current (Path : String) return String is
         use Ada.Text_IO;
         F      : File_Type;
         Result : Unbounded_String;
      begin
         if not Exists (Path) then
            return "";
         end if;
         Open (F, In_File, Path);
         while not End_Of_File (F) loop
            Append (Result, Get_Line (F) & NL);
         end loop;
         Close (F);
         return To_String (Result);
      end Current;

      procedure Check_Stale (Entry_Found : Directory_Entry_Type) is
         Name : constant String := Simple_Name (Entry_Found);
      begin
         if not Files.Contains (Name) then
            Delete_File (Full_Name (Entry_Found));
            Removed := Removed + 1;
         end if;
      end Check_Stale;
   begin
      Create_Path (Dir);
      for C in Files.Iterate loop
         declare
            Path : constant String := Compose (Dir, Text_Maps.Key (C));
            Text : constant String := Text_Maps.Element (C);
         begin
            if Current (Path) /= Text then
               declare
                  use Ada.Text_IO;
                  F : File_Type;
               begin
                  Create (F, Out_File, Path);
                  Put (F, Text);
                  Close (F);
                  Written := Written + 1;
               end;
            end if;
         end;
      end loop;
      Search (Dir, "*.ad?", [Ordinary_File => True, others => False], Check_Stale'Access);
      if Length (Project_Name) = 0 then
         Search (Dir, "*.gpr", [Ordinary_File => True, others => False], Check_Stale'Access);
      end if;
      Ada.Text_IO.Put_Line ("rosidl_generate: " & Dir & ":" & Files.Length'Image & " files,"
                            & Written'Image & " written," & Removed'Image & " removed");
   end Write_All;

   function Packages_In (Folder : String) return String_Vectors.Vector is
      use Ada.Directories;
      Result : String_Vectors.Vector;
      Found  : Name_Sets.Set;
      procedure Visit (D : Directory_Entry_Type) is
         Name : constant String := Simple_Name (D);
         Path : constant String := Full_Name (D);
      begin
         if Name /= "." and then Name /= ".."
           and then (Exists (Compose (Path, "msg")) or else Exists (Compose (Path, "srv"))
                     or else Exists (Compose (Path, "action")))
         then
            Found.Include (Name);
         end if;
      end Visit;
   begin
      Search (Folder, "", [Directory => True, others => False], Visit'Access);
      for N of Found loop
         Result.Append (N);
      end loop;
      return Result;
   end Packages_In;

   Arg : Positive := 1;
   use Ada.Command_Line;
begin
   while Arg <= Argument_Count loop
      declare
         A : constant String := Argument (Arg);
      begin
         if A = "-o" and then Arg < Argument_Count then
            Output_Dir := To_Unbounded_String (Argument (Arg + 1));
            Arg := Arg + 1;
         elsif A = "--project" and then Arg < Argument_Count then
            Project_Name := To_Unbounded_String (Argument (Arg + 1));
            Arg := Arg + 1;
         elsif A = "--registry" and then Arg < Argument_Count then
            Registry_Unit := To_Unbounded_String (Argument (Arg + 1));
            Arg := Arg + 1;
         elsif A'Length > 0 and then A (A'First) = '-' then
            raise Usage_Error with "unknown option " & A;
         else
            if not Ada.Directories.Exists (A) then
               raise Usage_Error with "no such folder: " & A;
            end if;
            Folders.Append (Ada.Directories.Full_Name (A));
         end if;
      end;
      Arg := Arg + 1;
   end loop;
   if Length (Output_Dir) = 0 or else Folders.Is_Empty then
      raise Usage_Error with "missing -o OUTPUT_DIR or FOLDER";
   end if;

   for F of Folders loop
      ROSIDL.Interfaces.Add_Folder (F);
   end loop;
   for F of Folders loop
      for Pkg of Packages_In (F) loop
         Generate_Package (Pkg);
      end loop;
   end loop;
   if Length (Registry_Unit) > 0 then
      Generate_Registry (To_String (Registry_Unit));
   end if;
   if Length (Project_Name) > 0 then
      Generate_Project (To_String (Project_Name));
   end if;
   Write_All;
exception
   when E : Usage_Error =>
      Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, "rosidl_generate: "
                            & Ada.Exceptions.Exception_Message (E));
      Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error,
                            "usage: rosidl_generate -o OUTPUT_DIR [--registry UNIT] "
                            & "[--project NAME] FOLDER...");
      Set_Exit_Status (2);
   when E : ROSIDL.Definition_Error | ROSIDL.Unknown_Type =>
      Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, "rosidl_generate: "
                            & Ada.Exceptions.Exception_Message (E));
      Set_Exit_Status (1);
end Rosidl_Generate;
