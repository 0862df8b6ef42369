with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with ROSIDL.YAML_Strings;
with RCL.Parameters.Initial_Values;
with RCL.Parameters.Serving;
with RCL.Parameters.Stores;

package body RCL.Parameters is

   use Stores;

   use ROSIDL.Dynamic;
   use type RCL.YAML.Node_Kind;
   use type RCL.YAML.Scalar_Kind;

   ----------------
   -- Type_Image --
   ----------------

   function Type_Image (T : Parameter_Type) return String is
     (case T is
         when Not_Set => "not set",
         when Bool_Type => "boolean",
         when Integer_Type => "integer",
         when Double_Type => "double",
         when String_Type => "string",
         when Byte_Array_Type => "byte array",
         when Bool_Array_Type => "boolean array",
         when Integer_Array_Type => "integer array",
         when Double_Array_Type => "double array",
         when String_Array_Type => "string array");

   function To_Value (B : Boolean) return Value is ((Kind => Bool_Type, Bool => B, others => <>));
   function To_Value (I : Long_Long_Integer) return Value is
     ((Kind => Integer_Type, Int => I, others => <>));
   function To_Value (D : Long_Float) return Value is
     ((Kind => Double_Type, Double => D, others => <>));
   function To_Value (S : String) return Value is
     ((Kind => String_Type, Text => To_Unbounded_String (S), others => <>));

   -----------
   -- Image --
   -----------

   function Trim (S : String) return String is
     (Ada.Strings.Fixed.Trim (S, Ada.Strings.Both));

   function Double_Image (D : Long_Float) return String is
      --  The shortest decimal form that reads back as D ("2.5", "0.1").
      package F is new Ada.Text_IO.Float_IO (Long_Float);
      Buffer : String (1 .. 64);
   begin
      if D /= D then
         return ".nan";
      elsif D > Long_Float'Last then
         return ".inf";
      elsif D < Long_Float'First then
         return "-.inf";
      end if;
      for Aft in 1 .. 17 loop
         if abs D >= 1.0E-4 and then abs D < 1.0E15 then
            F.Put (Buffer, D, Aft => Aft, Exp => 0);
         else
            F.Put (Buffer, D, Aft => Aft, Exp => 3);
         end if;
         if Long_Float'Value (Buffer) = D or else Aft = 17 then
            return Trim (Buffer);
         end if;
      end loop;
      return Trim (Buffer);
   end Double_Image;

   --  The one formatter behind Image and YAML_Image: scalars and arrays
   --  ("[a, b]") with the element images given.
   function Format
     (V          : Value;
      Unset      : String;
      Bool_Image : not null access function (B : Boolean) return String;
      Real_Image : not null access function (D : Long_Float) return String;
      Text_Image : not null access function (S : String) return String) return String
   is
      R : Unbounded_String;
      procedure Add (S : String) is
      begin
         Append (R, (if Length (R) = 1 then "" else ", ") & S);
      end Add;
   begin
      case V.Kind is
         when Not_Set => return Unset;
         when Bool_Type => return Bool_Image (V.Bool);
         when Integer_Type => return Trim (V.Int'Image);
         when Double_Type => return Real_Image (V.Double);
         when String_Type => return Text_Image (To_String (V.Text));
         when others => null;
      end case;
      R := To_Unbounded_String ("[");
      case V.Kind is
         when Byte_Array_Type =>
            for B of V.Bytes loop
               Add (Trim (B'Image));
            end loop;
         when Bool_Array_Type =>
            for B of V.Bools loop
               Add (Bool_Image (B));
            end loop;
         when Integer_Array_Type =>
            for I of V.Ints loop
               Add (Trim (I'Image));
            end loop;
         when Double_Array_Type =>
            for D of V.Doubles loop
               Add (Real_Image (D));
            end loop;
         when String_Array_Type =>
            for T of V.Texts loop
               Add (Text_Image (To_String (T)));
            end loop;
         when others => null;
      end case;
      Append (R, "]");
      return To_String (R);
   end Format;

   function Image (V : Value) return String is
      function Bool (B : Boolean) return String is (if B then "True" else "False");
      function Text (S : String) return String is
        (if V.Kind = String_Type then S else "'" & S & "'");
      --  Strings bare, string array elements quoted.
   begin
      return Format (V, "", Bool'Access, Double_Image'Access, Text'Access);
   end Image;

   ----------------
   -- YAML_Image --
   ----------------

   function YAML_Image (V : Value) return String is
      function Real (D : Long_Float) return String is
         S : constant String := Double_Image (D);
      begin
         --  Keep it a float for YAML ("3" would read back as an integer).
         return (if Ada.Strings.Fixed.Index (S, ".") = 0
                   and then Ada.Strings.Fixed.Index (S, "E") = 0
                 then S & ".0" else S);
      end Real;

      function Bool (B : Boolean) return String is (if B then "true" else "false");
   begin
      return Format (V, "~", Bool'Access, Real'Access, ROSIDL.YAML_Strings.Quoted'Access);
   end YAML_Image;

   ---------------
   -- From_YAML --
   ---------------

   function From_YAML (From : RCL.YAML.Document; N : RCL.YAML.Node) return Value is
      use RCL.YAML;

      procedure Fail (At_Node : Node; Message : String) is
      begin
         raise Parse_Error with From.Where (At_Node) & ": " & Message;
      end Fail;

      function Scalar_Value (At_Node : Node) return Value is
         T : constant String := From.Text (At_Node);
      begin
         if From.Kind (At_Node) in Sequence | Mapping then
            Fail (At_Node, "a parameter value must be a scalar or a sequence of scalars");
         end if;
         case From.Scalar_Type (At_Node) is
            when Null_Scalar =>
               Fail (At_Node, "a parameter value cannot be null");
               return (others => <>);
            when Bool_Scalar =>
               return To_Value (T in "true" | "True" | "TRUE");
            when Int_Scalar =>
               return To_Value (Integer_Value (T));
            when Float_Scalar =>
               return To_Value (Float_Value (T));
            when String_Scalar =>
               return To_Value (T);
         end case;
      exception
         when Constraint_Error =>
            Fail (At_Node, "'" & T & "' is out of range");
            return (others => <>);
      end Scalar_Value;
   begin
      if From.Kind (N) /= Sequence then
         return Scalar_Value (N);
      end if;
      declare
         Items : array (1 .. From.Length (N)) of Value;
         Kind  : Parameter_Type := Not_Set;
         R     : Value;
      begin
         for I in Items'Range loop
            Items (I) := Scalar_Value (From.Item (N, I));
            if Kind = Not_Set then
               Kind := Items (I).Kind;
            elsif Kind /= Items (I).Kind then
               if Kind in Integer_Type | Double_Type
                 and then Items (I).Kind in Integer_Type | Double_Type
               then
                  Kind := Double_Type;
               else
                  Fail (From.Item (N, I), "a parameter array holds values of one type ("
                        & Type_Image (Kind) & " here, not " & Type_Image (Items (I).Kind) & ")");
               end if;
            end if;
         end loop;
         case Kind is
            when Bool_Type | Not_Set =>
               R.Kind := (if Kind = Not_Set then String_Array_Type else Bool_Array_Type);
               for V of Items loop
                  R.Bools.Append (V.Bool);
               end loop;
            when Integer_Type =>
               R.Kind := Integer_Array_Type;
               for V of Items loop
                  R.Ints.Append (V.Int);
               end loop;
            when Double_Type =>
               R.Kind := Double_Array_Type;
               for V of Items loop
                  R.Doubles.Append (if V.Kind = Integer_Type then Long_Float (V.Int) else V.Double);
               end loop;
            when others =>
               R.Kind := String_Array_Type;
               for V of Items loop
                  R.Texts.Append (V.Text);
               end loop;
         end case;
         return R;
      end;
   end From_YAML;

   function Parse (Text : String; Source : String := "<value>") return Value is
      D : constant RCL.YAML.Document := RCL.YAML.Parse (Text, Source);
   begin
      return From_YAML (D, D.Root);
   end Parse;


   procedure Add_Override
     (Node_Pattern, Name : String; New_Value : Value; Origin : String := "") is
   begin
      Store.Add_Override ((To_Unbounded_String (Node_Pattern), To_Unbounded_String (Name),
                           New_Value, To_Unbounded_String (Origin)));
   end Add_Override;

   procedure Clear_Overrides is
   begin
      Store.Clear_Overrides;
   end Clear_Overrides;

   procedure Put_Parameter_Value (Ref : Field_Ref; V : Value) is
   begin
      Ref.Field_Reference ("type").As_UInt8.Element.all := Parameter_Type'Pos (V.Kind);
      case V.Kind is
         when Not_Set => null;
         when Bool_Type => Ref.Field_Reference ("bool_value").As_Bool.Element.all := V.Bool;
         when Integer_Type =>
            Ref.Field_Reference ("integer_value").As_Int64.Element.all := ROSIDL.Int64 (V.Int);
         when Double_Type =>
            Ref.Field_Reference ("double_value").As_Float64.Element.all :=
              ROSIDL.Float64 (V.Double);
         when String_Type =>
            Ref.Field_Reference ("string_value").Set_String (To_String (V.Text));
         when Byte_Array_Type =>
            declare
               A : UInt8_Array (1 .. Natural (V.Bytes.Length));
            begin
               for I in A'Range loop
                  A (I) := V.Bytes (I);
               end loop;
               Ref.Field_Reference ("byte_array_value").Set_UInt8_Array (A);
            end;
         when Bool_Array_Type =>
            declare
               A : Bool_Array (1 .. Natural (V.Bools.Length));
            begin
               for I in A'Range loop
                  A (I) := V.Bools (I);
               end loop;
               Ref.Field_Reference ("bool_array_value").Set_Bool_Array (A);
            end;
         when Integer_Array_Type =>
            declare
               A : Int64_Array (1 .. Natural (V.Ints.Length));
            begin
               for I in A'Range loop
                  A (I) := ROSIDL.Int64 (V.Ints.Element (I));
               end loop;
               Ref.Field_Reference ("integer_array_value").Set_Int64_Array (A);
            end;
         when Double_Array_Type =>
            declare
               A : Float64_Array (1 .. Natural (V.Doubles.Length));
            begin
               for I in A'Range loop
                  A (I) := ROSIDL.Float64 (V.Doubles.Element (I));
               end loop;
               Ref.Field_Reference ("double_array_value").Set_Float64_Array (A);
            end;
         when String_Array_Type =>
            declare
               A : constant Array_Ref := Ref.Field_Reference ("string_array_value").As_Array;
            begin
               A.Resize (Natural (V.Texts.Length));
               for I in 1 .. Natural (V.Texts.Length) loop
                  A.Element (I).Set_String (To_String (V.Texts (I)));
               end loop;
            end;
      end case;
   end Put_Parameter_Value;

   function Get_Parameter_Value (Ref : Field_Ref) return Value is
      T : constant Natural := Natural (Ref.Field_Reference ("type").As_UInt8.Element.all);
      V : Value;
   begin
      if T > Parameter_Type'Pos (Parameter_Type'Last) then
         raise Parameter_Error with "unknown parameter type" & T'Image;
      end if;
      V.Kind := Parameter_Type'Val (T);
      case V.Kind is
         when Not_Set => null;
         when Bool_Type => V.Bool := Ref.Field_Reference ("bool_value").As_Bool.Element.all;
         when Integer_Type =>
            V.Int := Long_Long_Integer
              (Ref.Field_Reference ("integer_value").As_Int64.Element.all);
         when Double_Type =>
            V.Double := Long_Float (Ref.Field_Reference ("double_value").As_Float64.Element.all);
         when String_Type =>
            V.Text := To_Unbounded_String (Ref.Field_Reference ("string_value").Get_String);
         when Byte_Array_Type =>
            for B of Ref.Field_Reference ("byte_array_value").Get_UInt8_Array loop
               V.Bytes.Append (B);
            end loop;
         when Bool_Array_Type =>
            for B of Ref.Field_Reference ("bool_array_value").Get_Bool_Array loop
               V.Bools.Append (B);
            end loop;
         when Integer_Array_Type =>
            for I of Ref.Field_Reference ("integer_array_value").Get_Int64_Array loop
               V.Ints.Append (Long_Long_Integer (I));
            end loop;
         when Double_Array_Type =>
            for D of Ref.Field_Reference ("double_array_value").Get_Float64_Array loop
               V.Doubles.Append (Long_Float (D));
            end loop;
         when String_Array_Type =>
            declare
               A : constant Array_Ref := Ref.Field_Reference ("string_array_value").As_Array;
            begin
               for I in 1 .. A.Length loop
                  V.Texts.Append (To_Unbounded_String (A.Element (I).Get_String));
               end loop;
            end;
      end case;
      return V;
   end Get_Parameter_Value;

   ---------------------
   -- Declare and get --
   ---------------------

   procedure Declare_Parameter
     (Node        : RCL.Nodes.Node'Class;
      Name        : String;
      Default     : Value;
      Description : String := "";
      Read_Only   : Boolean := False)
   is
      Node_Name : constant String := Node.Fully_Qualified_Name;
      Loaded    : Boolean;
      Found     : Boolean;
      Initial   : Value := Default;
      Given     : Stores.Override;
      Done      : Boolean;

      --  "p.yaml:4:11: " (where the override was given, as the location of
      --  the error about it), then "parameter 'rate' of /node".
      function Subject return String is
        ((if Given.Origin = "" then "" else To_String (Given.Origin) & ": ")
         & "parameter '" & Name & "' of " & Node_Name);
   begin
      if Name = "" then
         raise Parameter_Error with "empty parameter name";
      end if;
      Store.Mark_Loaded (Loaded);
      if not Loaded then
         Load_Arguments;
      end if;
      Store.Find_Override (Node_Name, Name, Found, Given);
      if Found then
         Initial := Given.New_Value;
      end if;
      if Initial.Kind /= Default.Kind then
         if Default.Kind = Double_Type and then Initial.Kind = Integer_Type then
            Initial := To_Value (Long_Float (Initial.Int));
         else
            raise Parameter_Error with Subject & " is " & Type_Image (Default.Kind)
              & ", but the override for '" & To_String (Given.Pattern) & "' is "
              & Type_Image (Initial.Kind) & " (" & Image (Initial) & ")";
         end if;
      end if;
      if Found then
         --  An override passes the node's validation like any later set (else a
         --  command line could give a value the node rejects).
         declare
            V      : constant Validator := Store.Validator_Of (Node_Name);
            Reason : constant String := (if V = null then "" else V (Name, Initial));
         begin
            if Reason /= "" then
               raise Parameter_Error with Subject & ": the override for '"
                 & To_String (Given.Pattern) & "' (" & Image (Initial) & ") is rejected: "
                 & Reason;
            end if;
         end;
      end if;
      Store.Insert (Node_Name, Name,
                    (Desc    => (Name        => To_Unbounded_String (Name),
                                 Kind        => Default.Kind,
                                 Description => To_Unbounded_String (Description),
                                 Read_Only   => Read_Only),
                     Current => Initial), Done);
      if not Done then
         raise Parameter_Error with "parameter '" & Name & "' of " & Node_Name
           & " is already declared";
      end if;
      Serving.Publish_Event (Node_Name,
                            Text_Vectors.To_Vector (To_Unbounded_String (Name), 1), True);
   end Declare_Parameter;

   function Has_Parameter (Node : RCL.Nodes.Node'Class; Name : String) return Boolean is
     (Store.Contains (Node.Fully_Qualified_Name, Name));

   function Get (Node : RCL.Nodes.Node'Class; Name : String) return Value is
   begin
      if not Store.Contains (Node.Fully_Qualified_Name, Name) then
         raise Parameter_Error with "parameter '" & Name & "' of "
           & Node.Fully_Qualified_Name & " is not declared";
      end if;
      return Store.Get (Node.Fully_Qualified_Name, Name).Current;
   end Get;

   procedure On_Set
     (Node  : RCL.Nodes.Node'Class;
      Check : not null access function (Name : String; New_Value : Value) return String)
   is
      Stored : constant Validator with Import, Address => Check'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
   begin
      Store.Set_Validator (Node.Fully_Qualified_Name, Stored);
   end On_Set;

   ---------
   -- Set --
   ---------

   function Check (Node_Name, Name : String; New_Value : Value) return String is
      --  "" when New_Value may be set, else the reason.
   begin
      if not Store.Contains (Node_Name, Name) then
         return "parameter '" & Name & "' is not declared";
      end if;
      declare
         E : constant Entry_Record := Store.Get (Node_Name, Name);
         V : constant Validator := Store.Validator_Of (Node_Name);
      begin
         if E.Desc.Read_Only then
            return "parameter '" & Name & "' is read-only";
         elsif New_Value.Kind = Not_Set then
            return "cannot undeclare a statically typed parameter";  --  rclcpp's words.
         elsif New_Value.Kind /= E.Desc.Kind then
            return "parameter '" & Name & "' is " & Type_Image (E.Desc.Kind) & ", not "
              & Type_Image (New_Value.Kind);
         elsif V /= null then
            return V (Name, New_Value);
         end if;
         return "";
      end;
   exception
      when E : others =>
         return "the validation of '" & Name & "' failed: "
           & Ada.Exceptions.Exception_Name (E) & ": " & Ada.Exceptions.Exception_Message (E);
   end Check;

   function Try_Set (Node_Name, Name : String; New_Value : Value) return String is
      Reason : constant String := Check (Node_Name, Name, New_Value);
   begin
      if Reason = "" then
         Store.Put_Value (Node_Name, Name, New_Value);
         Serving.Publish_Event (Node_Name,
                               Text_Vectors.To_Vector (To_Unbounded_String (Name), 1), False);
      end if;
      return Reason;
   end Try_Set;

   procedure Set (Node : RCL.Nodes.Node'Class; Name : String; New_Value : Value) is
      Reason : constant String := Try_Set (Node.Fully_Qualified_Name, Name, New_Value);
   begin
      if Reason /= "" then
         raise Parameter_Error with Reason;
      end if;
   end Set;

   function Try_Set_Atomically (Node_Name : String; Values : Assignment_Array) return String is
      Changed : Text_Vectors.Vector;
   begin
      for A of Values loop
         declare
            Reason : constant String := Check (Node_Name, To_String (A.Name), A.New_Value);
         begin
            if Reason /= "" then
               return Reason;
            end if;
         end;
      end loop;
      for A of Values loop
         Store.Put_Value (Node_Name, To_String (A.Name), A.New_Value);
         Changed.Append (A.Name);
      end loop;
      Serving.Publish_Event (Node_Name, Changed, False);
      return "";
   end Try_Set_Atomically;

   function Names (Node_Name : String) return Text_Vectors.Vector is (Store.Names_Of (Node_Name));

   function Describe (Node_Name, Name : String) return Descriptor is
     (if Store.Contains (Node_Name, Name) then Store.Get (Node_Name, Name).Desc
      else (Name => To_Unbounded_String (Name), others => <>));
   procedure Serve (Node : in out RCL.Nodes.Node'Class) is
   begin
      Serving.Serve (Node);
   end Serve;

   procedure Load_File (Path : String) is
   begin
      Initial_Values.Load_File (Path);
   end Load_File;

   procedure Load_Arguments is
   begin
      Initial_Values.Load_Arguments;
   end Load_Arguments;

end RCL.Parameters;
