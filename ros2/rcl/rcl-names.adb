with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;

package body RCL.Names is

   use Ada.Strings.Unbounded;

   function Is_Word_Char (C : Character) return Boolean is
     (C in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_');

   function Shortened
     (Text : String; Longest : Positive := 40; Tail : Natural := 7) return String is
     (if Text'Length <= Longest then Text
      else Text (Text'First .. Text'First + (Longest - 3 - Tail) - 1) & "..."
           & Text (Text'Last - Tail + 1 .. Text'Last));

   function Quoted (Name : String) return String is ('"' & Shortened (Name) & '"');

   function Too_Long (What, Name : String; Limit : Positive) return String is
     (if Name'Length <= Limit then ""
      else What & " " & Quoted (Name) & ":" & Name'Length'Image
           & " characters, longer than" & Limit'Image & " (rmw's limit)");

   function Position (Name : String; I : Positive) return String is
     (Ada.Strings.Fixed.Trim (Natural'Image (I - Name'First + 1), Ada.Strings.Left));

   function Bad_Char (What, Name : String; I : Positive) return String is
     (What & " " & Quoted (Name) & ": invalid character '" & Name (I) & "' at position "
      & Position (Name, I));

   -----------------------
   -- Node_Name_Problem --
   -----------------------

   function Node_Name_Problem (Name : String) return String is
   begin
      if Name = "" then
         return "node name is empty";
      elsif Too_Long ("node name", Name, Node_Name_Limit) /= "" then
         return Too_Long ("node name", Name, Node_Name_Limit);
      end if;
      for I in Name'Range loop
         if not Is_Word_Char (Name (I)) then
            return Bad_Char ("node name", Name, I)
              & " (allowed: letters, digits, '_')";
         end if;
      end loop;
      if Name (Name'First) in '0' .. '9' then
         return "node name " & Quoted (Name) & ": must not start with a digit";
      end if;
      return "";
   end Node_Name_Problem;

   procedure Validate_Node_Name (Name : String) is
      Problem : constant String := Node_Name_Problem (Name);
   begin
      if Problem /= "" then
         raise Name_Error with Problem;
      end if;
   end Validate_Node_Name;

   --  Checks a fully qualified name made of '/'-separated tokens.
   function Path_Problem (What, Name : String; Root_Allowed : Boolean) return String is
   begin
      if Name = "" then
         return What & " is empty";
      elsif Name (Name'First) /= '/' then
         return What & " " & Quoted (Name) & ": must start with '/'";
      elsif Name = "/" then
         return (if Root_Allowed then "" else What & " ""/"": must have a name after '/'");
      end if;
      for I in Name'Range loop
         if Name (I) = '/' then
            if I < Name'Last and then Name (I + 1) = '/' then
               return What & " " & Quoted (Name) & ": repeated '/' at position "
                 & Position (Name, I + 1);
            elsif I = Name'Last then
               return What & " " & Quoted (Name) & ": must not end with '/'";
            elsif Name (I + 1) in '0' .. '9' then
               return What & " " & Quoted (Name) & ": a token must not start with a digit"
                 & " (position " & Position (Name, I + 1) & ")";
            end if;
         elsif not Is_Word_Char (Name (I)) then
            return Bad_Char (What, Name, I) & " (allowed: letters, digits, '_', '/')";
         end if;
      end loop;
      return "";
   end Path_Problem;

   function Namespace_Problem (Namespace : String) return String is
     (if Too_Long ("namespace", Namespace, Namespace_Limit) /= ""
      then Too_Long ("namespace", Namespace, Namespace_Limit)
      else Path_Problem ("namespace", Namespace, Root_Allowed => True));

   function Normalize_Namespace (Namespace : String) return String is
      Result : Unbounded_String := To_Unbounded_String (Namespace);
   begin
      if Length (Result) = 0 or else Element (Result, 1) /= '/' then
         Result := "/" & Result;
      end if;
      if Length (Result) > 1 and then Element (Result, Length (Result)) = '/' then
         Result := Unbounded_Slice (Result, 1, Length (Result) - 1);
      end if;
      declare
         Problem : constant String := Namespace_Problem (To_String (Result));
      begin
         if Problem /= "" then
            raise Name_Error with Problem;
         end if;
      end;
      return To_String (Result);
   end Normalize_Namespace;

   function Topic_Problem (Name : String) return String is
     (if Too_Long ("topic name", Name, Topic_Name_Limit) /= ""
      then Too_Long ("topic name", Name, Topic_Name_Limit)
      else Path_Problem ("topic name", Name, Root_Allowed => False));

   function Parameter_Name_Problem (Name : String) return String is
      Token_Start : Positive := Name'First;
   begin
      if Name = "" then
         return "parameter name is empty";
      end if;
      for I in Name'Range loop
         if Name (I) = '.' then
            if I = Token_Start then
               return "parameter name " & Quoted (Name) & ": empty part before the '.' at position "
                 & Position (Name, I);
            end if;
            Token_Start := I + 1;
         elsif not (Is_Word_Char (Name (I)) or else Name (I) = '/') then
            return Bad_Char ("parameter name", Name, I)
              & " (allowed: letters, digits, '_', '/', '.')";
         end if;
      end loop;
      if Name (Name'Last) = '.' then
         return "parameter name " & Quoted (Name) & ": must not end with '.'";
      end if;
      return "";
   end Parameter_Name_Problem;

   function Fully_Qualified_Node_Name (Node : String; Namespace : String) return String is
     ((if Namespace = "/" then "" else Namespace) & "/" & Node);

   -----------------------
   -- Expand_Topic_Name --
   -----------------------

   function Expand_Topic_Name
     (Name : String; Node : Node_Name; Namespace : Namespace_Name) return Topic_Name
   is
      FQN    : constant String := Fully_Qualified_Node_Name (Node, Namespace);
      Result : Unbounded_String;
      I      : Natural := Name'First;
   begin
      if Name = "" then
         raise Name_Error with "topic name is empty";
      end if;
      --  Substitutions.
      while I <= Name'Last loop
         if Name (I) = '{' then
            declare
               Close : constant Natural :=
                 Ada.Strings.Fixed.Index (Name (I .. Name'Last), "}");
            begin
               if Close = 0 then
                  raise Name_Error with "topic name """ & Name
                    & """: unmatched '{' at position " & Position (Name, I);
               end if;
               declare
                  Key : constant String := Name (I + 1 .. Close - 1);
               begin
                  if Key = "node" then
                     Append (Result, Node);
                  elsif Key = "ns" or else Key = "namespace" then
                     Append (Result, Namespace);
                  else
                     raise Name_Error with "topic name """ & Name
                       & """: unknown substitution '{" & Key & "}' at position "
                       & Position (Name, I);
                  end if;
               end;
               I := Close + 1;
            end;
         else
            Append (Result, Name (I));
            I := I + 1;
         end if;
      end loop;
      declare
         S        : constant String := To_String (Result);
         Expanded : Unbounded_String;
      begin
         if S (S'First) = '/' then
            Expanded := To_Unbounded_String (S);
         elsif S (S'First) = '~' then
            if S'Length = 1 then
               Expanded := To_Unbounded_String (FQN);
            elsif S (S'First + 1) = '/' then
               Expanded := To_Unbounded_String (FQN & S (S'First + 1 .. S'Last));
            else
               raise Name_Error with "topic name """ & Name
                 & """: '~' must be followed by '/' (position 2)";
            end if;
         else
            Expanded := To_Unbounded_String
              ((if Namespace = "/" then "" else Namespace) & "/" & S);
         end if;
         declare
            Final   : constant String := To_String (Expanded);
            Problem : constant String := Topic_Problem (Final);
         begin
            if Problem /= "" then
               raise Name_Error with Problem
                 & (if Final /= Name then " (expanded from " & Quoted (Name) & ")" else "");
            end if;
            return Final;
         end;
      end;
   end Expand_Topic_Name;

   function DDS_Topic_Name (Fully_Qualified : String) return String is
     ("rt" & Fully_Qualified);

end RCL.Names;
