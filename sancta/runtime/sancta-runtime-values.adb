with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Long_Float_Text_IO;
with Ada.Strings.Fixed;

package body Sancta.Runtime.Values is

   use Ada.Strings.Unbounded;

   package Type_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (Key_Type => String, Element_Type => String);

   type Family is record
      Prefix : Unbounded_String;
      Check  : Family_Check;
   end record;

   type Family_Array is array (1 .. 8) of Family;

   protected Registry is
      procedure Add (Name, Description : String);
      procedure Add_Family (Prefix : String; Check : Family_Check);
      function Contains (Name : String) return Boolean;
      function Family_Of (Name : String) return Family_Check;
      function All_Names return String;
   private
      Types    : Type_Maps.Map;
      Families : Family_Array;
      Count    : Natural := 0;
   end Registry;

   protected body Registry is
      procedure Add (Name, Description : String) is
      begin
         Types.Include (Name, Description);
      end Add;

      function Contains (Name : String) return Boolean is (Types.Contains (Name));

      procedure Add_Family (Prefix : String; Check : Family_Check) is
      begin
         if Count = Families'Last then
            raise Program_Error with "too many value type families";
         end if;
         Count := Count + 1;
         Families (Count) := (To_Unbounded_String (Prefix), Check);
      end Add_Family;

      function Family_Of (Name : String) return Family_Check is
      begin
         for F of Families (1 .. Count) loop
            declare
               P : constant String := To_String (F.Prefix);
            begin
               if Name'Length > P'Length
                 and then Name (Name'First .. Name'First + P'Length - 1) = P
               then
                  return F.Check;
               end if;
            end;
         end loop;
         return null;
      end Family_Of;

      function All_Names return String is
         Result : Unbounded_String;
      begin
         for Position in Types.Iterate loop
            if Length (Result) > 0 then
               Append (Result, ", ");
            end if;
            Append (Result, Type_Maps.Key (Position));
         end loop;
         for F of Families (1 .. Count) loop
            Append (Result, ", " & To_String (F.Prefix) & "...");
         end loop;
         return To_String (Result);
      end All_Names;
   end Registry;

   function JSON (This : Value) return String is
     (JSON_String (Value'Class (This).Image));

   procedure Register_Type (Name : String; Description : String) is
   begin
      Registry.Add (Name, Description);
   end Register_Type;

   procedure Register_Family (Prefix : String; Check : not null Family_Check) is
   begin
      Registry.Add_Family (Prefix, Check);
   end Register_Family;

   function Is_Known_Type (Name : String) return Boolean is
      Check : Family_Check;
   begin
      if Name = Any_Type or else Registry.Contains (Name) then
         return True;
      end if;
      Check := Registry.Family_Of (Name);
      --  The family's check runs outside the registry's protected action.
      return Check /= null and then Check (Name);
   end Is_Known_Type;

   function Known_Types return String is (Registry.All_Names & ", " & Any_Type);

   function Trimmed (S : String) return String is
     (if S'Length > 0 and then S (S'First) = ' ' then S (S'First + 1 .. S'Last) else S);

   function Real_Image (X : Long_Float) return String is
      Text : String (1 .. 60);
      Last : Natural;
   begin
      if not X'Valid then
         return "nan";
      elsif abs X >= 1.0E15 or else (X /= 0.0 and then abs X < 1.0E-6) then
         Ada.Long_Float_Text_IO.Put (Text, X, Aft => 9, Exp => 3);
         return Ada.Strings.Fixed.Trim (Text, Ada.Strings.Both);
      end if;
      Ada.Long_Float_Text_IO.Put (Text, X, Aft => 9, Exp => 0);
      Last := Text'Last;
      while Text (Last) = '0' and then Text (Last - 1) /= '.' loop
         Last := Last - 1;
      end loop;
      return Ada.Strings.Fixed.Trim (Text (1 .. Last), Ada.Strings.Both);
   end Real_Image;

   function JSON_String (S : String) return String is
      Hex_Digits : constant String (1 .. 16) := "0123456789abcdef";
      Result : Unbounded_String := To_Unbounded_String ("""");
   begin
      for C of S loop
         case C is
            when '"' => Append (Result, "\""");
            when '\' => Append (Result, "\\");
            when ASCII.LF => Append (Result, "\n");
            when ASCII.CR => Append (Result, "\r");
            when ASCII.HT => Append (Result, "\t");
            when Character'Val (0) .. Character'Val (8) | Character'Val (11)
               | Character'Val (12) | Character'Val (14) .. Character'Val (31) =>
               Append (Result, "\u00");
               Append (Result, Hex_Digits (Character'Pos (C) / 16 + 1));
               Append (Result, Hex_Digits (Character'Pos (C) mod 16 + 1));
            when others => Append (Result, C);
         end case;
      end loop;
      Append (Result, '"');
      return To_String (Result);
   end JSON_String;

   overriding function Image (This : Integer_Value) return String is
     (Trimmed (This.Data'Image));
   overriding function JSON (This : Integer_Value) return String is (This.Image);

   overriding function Image (This : Real_Value) return String is (Real_Image (This.Data));
   overriding function JSON (This : Real_Value) return String is (This.Image);

   overriding function Image (This : Boolean_Value) return String is
     (if This.Data then "true" else "false");
   overriding function JSON (This : Boolean_Value) return String is (This.Image);

   overriding function Image (This : String_Value) return String is (To_String (This.Data));

   overriding function Image (This : Pose_Value) return String is
     ("(" & Real_Image (Long_Float (This.Data.X)) & ", " & Real_Image (Long_Float (This.Data.Y))
      & ", " & Real_Image (Long_Float (This.Data.Yaw)) & ")");
   overriding function JSON (This : Pose_Value) return String is
     ("{""x"": " & Real_Image (Long_Float (This.Data.X)) & ", ""y"": "
      & Real_Image (Long_Float (This.Data.Y)) & ", ""yaw"": "
      & Real_Image (Long_Float (This.Data.Yaw)) & "}");

begin
   Register_Type ("types.integer", "a whole number (Integer_Value)");
   Register_Type ("types.real", "a real number (Real_Value)");
   Register_Type ("types.boolean", "true or false (Boolean_Value)");
   Register_Type ("types.string", "a text (String_Value)");
   Register_Type ("types.pose", "x, y, yaw (Pose_Value)");
end Sancta.Runtime.Values;
