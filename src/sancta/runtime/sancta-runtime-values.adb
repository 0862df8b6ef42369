with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Long_Float_Text_IO;
with Ada.Strings.Fixed;

package body Sancta.Runtime.Values is

   use Ada.Strings.Unbounded;

   package Type_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (Key_Type => String, Element_Type => String);

   protected Registry is
      procedure Add (Name, Description : String);
      function Contains (Name : String) return Boolean;
      function All_Names return String;
   private
      Types : Type_Maps.Map;
   end Registry;

   protected body Registry is
      procedure Add (Name, Description : String) is
      begin
         Types.Include (Name, Description);
      end Add;

      function Contains (Name : String) return Boolean is (Types.Contains (Name));

      function All_Names return String is
         Result : Unbounded_String;
      begin
         for Position in Types.Iterate loop
            if Length (Result) > 0 then
               Append (Result, ", ");
            end if;
            Append (Result, Type_Maps.Key (Position));
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

   function Is_Known_Type (Name : String) return Boolean is
     (Name = Any_Type or else Registry.Contains (Name));

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
