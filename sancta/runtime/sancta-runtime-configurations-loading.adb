with Ada.Characters.Handling;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Vectors;
with Ada.Directories;
with Ada.Strings.Fixed;
with Sancta.Runtime.Configurations.Wiring;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Factory;
with Sancta.Runtime.Values;

package body Sancta.Runtime.Configurations.Loading is

   Max_Id_Length : constant := 64;
   Max_Agents    : constant := 1_000;

   function Printable (Text : String) return String is
     --  Text with control characters as '?', at most 80 characters.
     ([for I in Text'First .. Integer'Min (Text'Last, Text'First + 79) =>
         (if Text (I) < ' ' or else Text (I) > '~' then '?' else Text (I))]);

   use type Components.Port_Direction;
   use type Components.Type_Refiner;
   use type Components.Options_Check;
   use type XML_Trees.Element_Id;
   use XML_Trees;

   --  Loading state --

   type Element_Ref is record
      Doc  : Positive;
      --  Index in the loader's trees.
      Node : Element_Id;
   end record;

   package Tree_Vectors is new Ada.Containers.Vectors (Positive, Tree);
   package Ref_Vectors is new Ada.Containers.Vectors (Positive, Element_Ref);
   package Group_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Ref_Vectors.Vector,
      "=" => Ref_Vectors."=");
   package Group_Where_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Position);

   type Loader is record
      Trees       : Tree_Vectors.Vector;
      Open_Files  : Local_Databases.Key_Vectors.Vector;
      --  Full names of the files being included (cycle detection).
      Agents      : Ref_Vectors.Vector;
      Groups      : Group_Maps.Map;
      Group_Where : Group_Where_Maps.Map;
      Overrides   : String_Map;
   end record;

   function Is_Constant_Name (S : String) return Boolean is
     (S'Length >= 2 and then S (S'First) = '$'
      and then Ada.Characters.Handling.Is_Letter (S (S'First + 1))
      and then (for all C of S (S'First + 1 .. S'Last) => Is_Identifier_Char (C)));

   procedure Substitute
     (Text      : String;
      Constants : String_Map;
      Result    : out Unbounded_String;
      Problem   : out Unbounded_String)
   --  Replace "$name" (longest identifier) and "${name}" by the constant's
   --  value ("$$" is a literal "$"). Problem is set when a constant is unknown.
   is
      I : Natural := Text'First;
   begin
      Result := Null_Unbounded_String;
      Problem := Null_Unbounded_String;
      while I <= Text'Last loop
         if Text (I) = '$' and then I < Text'Last and then Text (I + 1) = '$' then
            Append (Result, '$');
            I := I + 2;
         elsif Text (I) = '$' then
            declare
               First : Natural := I + 1;
               Last  : Natural;
               Next  : Natural;
            begin
               if First <= Text'Last and then Text (First) = '{' then
                  First := First + 1;
                  Last := First;
                  while Last <= Text'Last and then Text (Last) /= '}' loop
                     Last := Last + 1;
                  end loop;
                  if Last > Text'Last then
                     Problem := To_Unbounded_String ("unterminated ""${"" in '" & Text & "'");
                     return;
                  end if;
                  Next := Last + 1;
                  Last := Last - 1;
               else
                  Last := First - 1;
                  while Last < Text'Last and then Is_Identifier_Char (Text (Last + 1)) loop
                     Last := Last + 1;
                  end loop;
                  Next := Last + 1;
               end if;
               declare
                  Name : constant String := "$" & Text (First .. Last);
               begin
                  if Constants.Contains (Name) then
                     if Length (Result) + Constants.Element (Name)'Length
                       > XML_Trees.Max_Attribute_Size
                     then
                        --  Constants made of constants grow exponentially.
                        Problem := To_Unbounded_String
                          ("the value would exceed" & Natural'Image (XML_Trees.Max_Attribute_Size)
                           & " characters once constants are substituted");
                        return;
                     end if;
                     Append (Result, Constants (Name));
                  else
                     Problem := To_Unbounded_String
                       ("unknown constant '" & Name & "'"
                        & (if Name = "$" then " (a lone ""$"" is written ""$$"")" else ""));
                     return;
                  end if;
               end;
               I := Next;
            end;
         else
            Append (Result, Text (I));
            I := I + 1;
         end if;
      end loop;
   end Substitute;

   --  Checks that E has only the attributes in Allowed (space-separated).
   procedure Check_Attributes
     (Result : in out Configuration; T : Tree; E : Element_Id; Allowed : String)
   is
      Words : Local_Databases.Key_Vectors.Vector;
      First : Positive := Allowed'First;
   begin
      for I in Allowed'Range loop
         if Allowed (I) = ' ' then
            Words.Append (Allowed (First .. I - 1));
            First := I + 1;
         end if;
      end loop;
      Words.Append (Allowed (First .. Allowed'Last));
      for A of T.Attributes (E) loop
         if not Words.Contains (To_String (A.Name)) then
            Report (Result, Error, A.Where,
                    "unknown attribute '" & To_String (A.Name) & "' of <" & T.Name (E)
                    & "> (expected: " & Allowed & ")");
         end if;
      end loop;
   end Check_Attributes;

   procedure Require_Attribute
     (Result : in out Configuration; T : Tree; E : Element_Id; Name : String; Ok : out Boolean) is
   begin
      Ok := T.Has_Attribute (E, Name) and then T.Attribute_Value (E, Name) /= "";
      if not Ok then
         Report (Result, Error, T.Where (E),
                 "<" & T.Name (E) & "> needs a non-empty attribute '" & Name & "'");
      end if;
   end Require_Attribute;

   --  First pass over a file: constants, groups, includes; agents recorded.
   procedure Scan_File
     (L : in out Loader; Result : in out Configuration; File : String; From : Position;
      Is_Root : Boolean)
   is
      Full : constant String :=
        (if Ada.Directories.Exists (File) then Ada.Directories.Full_Name (File) else File);
      T       : Tree;
      Doc     : Positive;
      Problem : XML_Trees.Load_Error;
   begin
      if L.Open_Files.Contains (Full) then
         Report (Result, Error, From, "include cycle: '" & File & "' is already being read");
         return;
      end if;
      XML_Trees.Load (File, T, Problem);
      if Problem.Failed then
         if not Is_Root then
            Report (Result, Error, From, "cannot include '" & File & "'");
         end if;
         Report (Result, Error, Problem.Where, To_String (Problem.Text));
         return;
      end if;
      L.Trees.Append (T);
      Doc := L.Trees.Last_Index;
      L.Open_Files.Append (Full);
      if Is_Root then
         Result.Name := To_Unbounded_String (T.Name (T.Root));
      end if;
      --  The root element may have any name and any attributes.
      for Child of T.Children (T.Root) loop
         declare
            Kind : constant String := T.Name (Child);
            Ok   : Boolean;
         begin
            if Kind = "constant" then
               Check_Attributes (Result, T, Child, "name value");
               Require_Attribute (Result, T, Child, "name", Ok);
               if Ok then
                  declare
                     Raw_Name : constant String := T.Attribute_Value (Child, "name");
                     Name     : constant String :=
                       (if Raw_Name (Raw_Name'First) = '$' then Raw_Name else "$" & Raw_Name);
                     Value    : Unbounded_String;
                     Problem  : Unbounded_String;
                  begin
                     if not Is_Constant_Name (Name) then
                        Report (Result, Error, T.Attribute_Where (Child, "name"),
                                "malformed constant name '" & Raw_Name
                                & "' (expected ""$"" and an identifier)");
                     elsif Name = "$id" then
                        Report (Result, Error, T.Attribute_Where (Child, "name"),
                                "constant '$id' is reserved (it is each agent's id)");
                     elsif not T.Has_Attribute (Child, "value") then
                        Report (Result, Error, T.Where (Child),
                                "<constant> needs an attribute 'value'");
                     elsif L.Overrides.Contains (Name) then
                        Result.Constants.Include (Name, L.Overrides (Name));
                     else
                        Substitute (T.Attribute_Value (Child, "value"), Result.Constants,
                                    Value, Problem);
                        if Length (Problem) > 0 then
                           Report (Result, Error, T.Attribute_Where (Child, "value"),
                                   To_String (Problem));
                        elsif Result.Constants.Contains (Name) then
                           Report (Result, Error, T.Attribute_Where (Child, "name"),
                                   "constant '" & Name & "' defined twice");
                        else
                           Result.Constants.Insert (Name, To_String (Value));
                        end if;
                     end if;
                  end;
               end if;
            elsif Kind = "group" then
               Check_Attributes (Result, T, Child, "name");
               Require_Attribute (Result, T, Child, "name", Ok);
               if Ok then
                  declare
                     Name : constant String := T.Attribute_Value (Child, "name");
                     Refs : Ref_Vectors.Vector;
                  begin
                     if L.Groups.Contains (Name) then
                        Report (Result, Error, T.Attribute_Where (Child, "name"),
                                "group '" & Name & "' defined twice (first at "
                                & Image (L.Group_Where (Name)) & ")");
                     else
                        for Member of T.Children (Child) loop
                           if T.Name (Member) = "component" then
                              Refs.Append (Element_Ref'(Doc, Member));
                           else
                              Report (Result, Error, T.Where (Member),
                                      "unknown element <" & T.Name (Member)
                                      & "> in <group> (expected <component>)");
                           end if;
                        end loop;
                        L.Groups.Insert (Name, Refs);
                        L.Group_Where.Insert (Name, T.Where (Child));
                     end if;
                  end;
               end if;
            elsif Kind = "include" then
               Check_Attributes (Result, T, Child, "file");
               Require_Attribute (Result, T, Child, "file", Ok);
               if Ok then
                  declare
                     Name     : constant String := T.Attribute_Value (Child, "file");
                     Dir      : constant String := Ada.Directories.Containing_Directory (File);
                     Included : constant String :=
                       (if Name (Name'First) = '/' then Name else Dir & "/" & Name);
                  begin
                     Scan_File (L, Result, Included, T.Attribute_Where (Child, "file"),
                                Is_Root => False);
                  end;
               end if;
            elsif Kind = "agent" then
               L.Agents.Append (Element_Ref'(Doc, Child));
            else
               Report (Result, Error, T.Where (Child),
                       "unknown element <" & Kind
                       & "> (expected <agent>, <constant>, <group> or <include>)");
            end if;
         end;
      end loop;
      L.Open_Files.Delete_Last;
   end Scan_File;

   function Port_List
     (Info : Components.Descriptor; Direction : Components.Port_Direction) return String
   is
      Result : Unbounded_String;
   begin
      for P of Info.Ports loop
         if P.Direction = Direction then
            if Length (Result) > 0 then
               Append (Result, ", ");
            end if;
            Append (Result, P.Data);
         end if;
      end loop;
      return (if Length (Result) = 0 then "none" else To_String (Result));
   end Port_List;

   function Port_Names
     (Info : Components.Descriptor; Direction : Components.Port_Direction)
      return Local_Databases.Key_Vectors.Vector
   is
      Result : Local_Databases.Key_Vectors.Vector;
   begin
      for P of Info.Ports loop
         if P.Direction = Direction then
            Result.Append (To_String (P.Data));
         end if;
      end loop;
      return Result;
   end Port_Names;

   --  Builds one component instance of an agent.
   procedure Read_Component
     (Result    : in out Configuration;
      T         : Tree;
      E         : Element_Id;
      Constants : String_Map;
      Rank      : Positive;
      Item      : out Instance;
      Valid     : out Boolean)
   is
      Values_Of : String_Map;
      --  Attribute values after substitution.
      Failed    : Boolean := False;

      procedure Expand (Element : Element_Id; Into : out String_Map) is
         Text    : Unbounded_String;
         Problem : Unbounded_String;
      begin
         Into := Components.String_Maps.Empty_Map;
         for A of T.Attributes (Element) loop
            Substitute (To_String (A.Value), Constants, Text, Problem);
            if Length (Problem) > 0 then
               Report (Result, Error, A.Where, To_String (Problem));
               Failed := True;
            else
               Into.Include (To_String (A.Name), To_String (Text));
            end if;
         end loop;
      end Expand;

      function Get (Map : String_Map; Name : String; Default : String := "") return String is
        (if Map.Contains (Name) then Map (Name) else Default);

      Info : Components.Descriptor;
   begin
      Valid := False;
      Item := (Where => T.Where (E), Rank => Rank, others => <>);
      Expand (E, Values_Of);
      declare
         Name : constant String := Get (Values_Of, "name");
      begin
         if Name = "" then
            Report (Result, Error, T.Where (E), "<component> needs a non-empty attribute 'name'");
            return;
         elsif not Factory.Is_Registered (Name) then
            Report (Result, Error, T.Attribute_Where (E, "name"),
                    "unknown component '" & Name & "'" & Suggest (Name, Factory.Names));
            return;
         end if;
         Info := Factory.Description (Name);
         Item.Component := To_Unbounded_String (Name);
         Item.Name := To_Unbounded_String (Name & "#" & Trim (Rank));
      end;

      --  Common attributes.
      declare
         Enabled : constant String := Get (Values_Of, "enabled", "true");
         Order   : constant String := Get (Values_Of, "order", "0");
         Policy  : constant String := Get (Values_Of, "on_error", "retry");
         Retry   : constant String := Get (Values_Of, "retry_after", "1.0");
      begin
         if Enabled in "true" | "false" then
            Item.Enabled := Enabled = "true";
         else
            Report (Result, Error, T.Attribute_Where (E, "enabled"),
                    "malformed value of 'enabled': expected true or false, found '"
                    & Enabled & "'");
            Failed := True;
         end if;
         begin
            Item.Order := Integer'Value (Order);
         exception
            when Constraint_Error =>
               Report (Result, Error, T.Attribute_Where (E, "order"),
                       "malformed value of 'order': expected an integer, found '" & Order & "'");
               Failed := True;
         end;
         if Policy in "retry" | "stop" then
            Item.Policy := (if Policy = "stop" then Components.Stop else Components.Retry);
         else
            Report (Result, Error, T.Attribute_Where (E, "on_error"),
                    "malformed value of 'on_error': expected retry or stop, found '"
                    & Policy & "'");
            Failed := True;
         end if;
         declare
            Check : constant String := Components.Check_Value
              (Components.Make_Option ("retry_after", Components.Duration_Option), Retry);
         begin
            if Check = "" then
               Item.Retry_After := Duration (Long_Float'Value (Retry));
            else
               Report (Result, Error, T.Attribute_Where (E, "retry_after"),
                       "malformed value of 'retry_after': " & Check);
               Failed := True;
            end if;
         end;
      end;

      --  Declared options: defaults, then attributes.
      for O of Info.Options loop
         Item.Options.Include (To_String (O.Name), To_String (O.Default));
      end loop;
      for A of T.Attributes (E) loop
         declare
            Name : constant String := To_String (A.Name);
         begin
            if Components.Is_Common_Option (Name) then
               null;
            elsif not (for some O of Info.Options => O.Name = Name) then
               declare
                  Known : Local_Databases.Key_Vectors.Vector;
                  All_Names : Unbounded_String;
               begin
                  for O of Info.Options loop
                     Known.Append (To_String (O.Name));
                     Append (All_Names, " " & To_String (O.Name));
                  end loop;
                  Report (Result, Error, A.Where,
                          "unknown option '" & Name & "' of component '"
                          & To_String (Item.Component) & "'" & Suggest (Name, Known)
                          & " (options:" & (if Length (All_Names) = 0 then " none"
                                            else To_String (All_Names))
                          & "; and name enabled order on_error retry_after)");
                  Failed := True;
               end;
            elsif Values_Of.Contains (Name) then
               for O of Info.Options loop
                  if O.Name = Name then
                     declare
                        Problem : constant String := Components.Check_Value (O, Values_Of (Name));
                     begin
                        if Problem = "" then
                           Item.Options.Include (Name, Values_Of (Name));
                        else
                           Report (Result, Error, A.Where,
                                   "malformed value of option '" & Name & "': " & Problem);
                           Failed := True;
                        end if;
                     end;
                  end if;
               end loop;
            end if;
         end;
      end loop;
      for O of Info.Options loop
         if O.Required and then not Values_Of.Contains (To_String (O.Name)) then
            Report (Result, Error, T.Where (E),
                    "component '" & To_String (Item.Component) & "' needs option '"
                    & To_String (O.Name) & "'");
            Failed := True;
         end if;
      end loop;

      if not Failed and then Info.Check /= null then
         declare
            Option, Problem : Unbounded_String;
         begin
            Info.Check (Item.Options, Option, Problem);
            if Length (Problem) > 0 then
               Report (Result, Error,
                       (if T.Has_Attribute (E, To_String (Option))
                        then T.Attribute_Where (E, To_String (Option)) else T.Where (E)),
                       "option '" & To_String (Option) & "' of component '"
                       & To_String (Item.Component) & "': " & To_String (Problem));
               Failed := True;
            end if;
         end;
      end if;

      --  Inputs and outputs.
      for Child of T.Children (E) loop
         declare
            Kind : constant String := T.Name (Child);
            Attrs : String_Map;
         begin
            if Kind not in "provides" | "requires" then
               Report (Result, Error, T.Where (Child),
                       "unknown element <" & Kind & "> in <component> (expected <provides> or "
                       & "<requires>)");
               Failed := True;
            else
               Check_Attributes (Result, T, Child, "data as type");
               Expand (Child, Attrs);
               declare
                  Direction : constant Components.Port_Direction :=
                    (if Kind = "provides" then Components.Output else Components.Input);
                  Data      : constant String := Get (Attrs, "data");
                  Key       : constant String := Get (Attrs, "as", Data);
                  Given     : constant String := Get (Attrs, "type");
                  Found     : Boolean := False;
                  Declared  : Components.Port;
                  Side      : constant String :=
                    (if Direction = Components.Input then "input" else "output");
               begin
                  if Data = "" then
                     Report (Result, Error, T.Where (Child),
                             "<" & Kind & "> needs a non-empty attribute 'data'");
                     Failed := True;
                     goto Next_Child;
                  end if;
                  if Key = "" then
                     Report (Result, Error, T.Attribute_Where (Child, "as"),
                             "empty external name ('as') for data '" & Data & "'");
                     Failed := True;
                     goto Next_Child;
                  end if;
                  for P of Info.Ports loop
                     if P.Direction = Direction and then P.Data = Data then
                        Found := True;
                        Declared := P;
                     end if;
                  end loop;
                  if not Found and then Direction = Components.Input and then Info.Any_Inputs then
                     Found := True;
                     Declared := Components.In_Port (Data, Values.Any_Type, Optional => True);
                  end if;
                  if not Found then
                     Report (Result, Error, T.Attribute_Where (Child, "data"),
                             "component '" & To_String (Item.Component) & "' has no " & Side
                             & " '" & Data & "'"
                             & Suggest (Data, Port_Names (Info, Direction))
                             & " (" & Side & "s: " & Port_List (Info, Direction) & ")");
                     Failed := True;
                     goto Next_Child;
                  end if;
                  if (for some B of Item.Bindings =>
                        B.Direction = Direction and then B.Data = Data)
                  then
                     Report (Result, Error, T.Attribute_Where (Child, "data"),
                             Side & " '" & Data & "' of component '"
                             & To_String (Item.Component) & "' bound twice");
                     Failed := True;
                     goto Next_Child;
                  end if;
                  declare
                     Effective : Unbounded_String := Declared.Type_Name;
                  begin
                     if Info.Refine /= null
                       and then To_String (Declared.Type_Name) = Values.Any_Type
                     then
                        begin
                           declare
                              Refined : constant String :=
                                Info.Refine (Item.Options, Data, Direction);
                           begin
                              if Refined /= "" then
                                 Declared.Type_Name := To_Unbounded_String (Refined);
                                 Effective := Declared.Type_Name;
                              end if;
                           end;
                        exception
                           when others =>
                              null;
                              --  Options already reported as wrong: keep "any".
                        end;
                     end if;
                     if Given /= "" then
                        if not Values.Is_Known_Type (Given) then
                           Report (Result, Error, T.Attribute_Where (Child, "type"),
                                   "unknown type '" & Given & "' (known types: "
                                   & Values.Known_Types & ")");
                           Failed := True;
                        elsif To_String (Declared.Type_Name) = Values.Any_Type then
                           Effective := To_Unbounded_String (Given);
                        elsif Given /= To_String (Declared.Type_Name) then
                           Report (Result, Error, T.Attribute_Where (Child, "type"),
                                   "type mismatch: " & Side & " '" & Data & "' of component '"
                                   & To_String (Item.Component) & "' is of type "
                                   & To_String (Declared.Type_Name) & ", not " & Given);
                           Failed := True;
                        end if;
                     end if;
                     Item.Bindings.Append
                       (Binding'(Direction => Direction,
                                 Data      => To_Unbounded_String (Data),
                                 Key       => To_Unbounded_String (Key),
                                 Type_Name => Effective,
                                 Optional  => Declared.Optional,
                                 Any_Port  =>
                                   To_String (Declared.Type_Name) = Values.Any_Type,
                                 Where     => T.Where (Child)));
                  end;
               end;
            end if;
         end;
         <<Next_Child>>
      end loop;

      --  Mandatory inputs.
      for P of Info.Ports loop
         if P.Direction = Components.Input and then not P.Optional
           and then not (for some B of Item.Bindings =>
                           B.Direction = Components.Input and then B.Data = P.Data)
         then
            Report (Result, Error, T.Where (E),
                    "component '" & To_String (Item.Component) & "' needs its input '"
                    & To_String (P.Data) & "' (add <requires data=""" & To_String (P.Data)
                    & """ as=""...""/>)");
            Failed := True;
         end if;
      end loop;
      Valid := not Failed;
   end Read_Component;

   function Before (A, B : Instance) return Boolean is
     (A.Order < B.Order or else (A.Order = B.Order and then A.Rank < B.Rank));

   package Instance_Sorting is new Instance_Vectors.Generic_Sorting (Before);

   procedure Read_Agent (L : Loader; Result : in out Configuration; Ref : Element_Ref) is
      T     : Tree renames L.Trees (Ref.Doc);
      E     : constant Element_Id := Ref.Node;
      A     : Agent;
      Ok    : Boolean;
      Rank  : Positive := 1;
      Constants : String_Map := Result.Constants;
      Members   : Ref_Vectors.Vector;
      Used      : String_Map;
      --  The groups this agent uses, and where ("team.xml:16:5").

      function Group_Names return Local_Databases.Key_Vectors.Vector is
         Result : Local_Databases.Key_Vectors.Vector;
      begin
         for C in L.Groups.Iterate loop
            Result.Append (Group_Maps.Key (C));
         end loop;
         return Result;
      end Group_Names;

   begin
      Check_Attributes (Result, T, E, "id kind");
      Require_Attribute (Result, T, E, "id", Ok);
      if not Ok then
         return;
      end if;
      A.Id := To_Unbounded_String (T.Attribute_Value (E, "id"));
      A.Kind := To_Unbounded_String (T.Attribute_Value (E, "kind"));
      A.Where := T.Where (E);
      declare
         Id : constant String := To_String (A.Id);
      begin
         --  Ids name DDS nodes, topics and files: a safe alphabet only.
         if Id'Length not in 1 .. Max_Id_Length
           or else (for some C of Id => C not in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_')
         then
            Report (Result, Error, T.Attribute_Where (E, "id"),
                    "agent id '" & Printable (Id) & "': 1 .." & Max_Id_Length'Image
                    & " letters, digits and '_'");
            return;
         end if;
      end;
      if To_String (A.Kind) not in "" | "robot" | "operator" then
         Report (Result, Error, T.Attribute_Where (E, "kind"),
                 "agent kind '" & Printable (To_String (A.Kind))
                 & "': expected robot or operator");
         return;
      end if;
      if Find_Agent (Result, To_String (A.Id)) > 0 then
         Report (Result, Error, T.Attribute_Where (E, "id"),
                 "agent '" & To_String (A.Id) & "' defined twice (first at "
                 & Image (Result.Agents (Find_Agent (Result, To_String (A.Id))).Where) & ")");
         return;
      end if;
      Constants.Include ("$id", To_String (A.Id));
      for Child of T.Children (E) loop
         if T.Name (Child) = "component" then
            Members.Append (Element_Ref'(Ref.Doc, Child));
         elsif T.Name (Child) = "use" then
            Check_Attributes (Result, T, Child, "group");
            Require_Attribute (Result, T, Child, "group", Ok);
            if Ok then
               declare
                  Name : constant String := T.Attribute_Value (Child, "group");
               begin
                  if Used.Contains (Name) then
                     --  Its components twice: every key they provide would be
                     --  reported in the group's file, far from this line.
                     Report (Result, Error, T.Attribute_Where (Child, "group"),
                             "group '" & Name & "' is used twice in agent '" & To_String (A.Id)
                             & "' (first at " & Used (Name) & ")");
                  elsif L.Groups.Contains (Name) then
                     Members.Append (L.Groups (Name));
                     Used.Insert (Name, Image (T.Where (Child)));
                  else
                     Report (Result, Error, T.Attribute_Where (Child, "group"),
                             "unknown group '" & Name & "'"
                             & Suggest (Name, Group_Names));
                  end if;
               end;
            end if;
         else
            Report (Result, Error, T.Where (Child),
                    "unknown element <" & T.Name (Child)
                    & "> in <agent> (expected <component> or <use>)");
         end if;
      end loop;
      for M of Members loop
         declare
            Item  : Instance;
            Valid : Boolean;
         begin
            Read_Component (Result, L.Trees (M.Doc), M.Node, Constants, Rank, Item, Valid);
            if Valid then
               A.Instances.Append (Item);
            end if;
            Rank := Rank + 1;
         end;
      end loop;
      Instance_Sorting.Sort (A.Instances);
      Wiring.Propagate_Types (Result, A);
      Wiring.Wire (Result, A);
      Result.Agents.Append (A);
   end Read_Agent;

   function Diagnostic_Before (A, B : Diagnostic) return Boolean is
     (A.Where.File < B.Where.File
      or else (A.Where.File = B.Where.File
               and then (A.Where.Line < B.Where.Line
                         or else (A.Where.Line = B.Where.Line
                                  and then A.Where.Column < B.Where.Column))));

   package Diagnostic_Sorting is new Diagnostic_Vectors.Generic_Sorting (Diagnostic_Before);

   function Mentions_Constant (L : Loader; Bare : String) return Boolean is
      --  True when some attribute of the loaded files names $Bare (as
      --  <constant name=...>, "$Bare" followed by a non-identifier
      --  character, or "${Bare}").
      function In_Text (Text : String) return Boolean is
         Plain : constant String := "$" & Bare;
      begin
         if Ada.Strings.Fixed.Index (Text, "${" & Bare & "}") > 0 then
            return True;
         end if;
         for I in Text'First .. Text'Last - Plain'Length + 1 loop
            if Text (I .. I + Plain'Length - 1) = Plain
              and then (I + Plain'Length > Text'Last
                        or else not Is_Identifier_Char (Text (I + Plain'Length)))
            then
               return True;
            end if;
         end loop;
         return False;
      end In_Text;

      function In_Element (T : Tree; E : Element_Id; Depth : Natural) return Boolean is
      begin
         if Depth > XML_Trees.Max_Depth then
            return False;
         end if;
         for A of T.Attributes (E) loop
            if In_Text (To_String (A.Value))
              or else (T.Name (E) = "constant" and then To_String (A.Name) = "name"
                       and then To_String (A.Value) in Bare | "$" & Bare)
            then
               return True;
            end if;
         end loop;
         return (for some C of T.Children (E) => In_Element (T, C, Depth + 1));
      end In_Element;
   begin
      return Bare = "id"
        or else (for some T of L.Trees => In_Element (T, T.Root, 0));
   end Mentions_Constant;

   procedure Load (File : String; Result : out Configuration; Overrides : String_Map) is
      L : Loader;
   begin
      Result := (File => To_Unbounded_String (File), others => <>);
      for C in Overrides.Iterate loop
         declare
            Name : constant String := Components.String_Maps.Key (C);
            Full : constant String :=
              (if Name'Length > 0 and then Name (Name'First) = '$' then Name else "$" & Name);
         begin
            L.Overrides.Include (Full, Components.String_Maps.Element (C));
            --  Overrides are also usable when the file does not define them.
            Result.Constants.Include (Full, Components.String_Maps.Element (C));
         end;
      end loop;
      Scan_File (L, Result, File, (To_Unbounded_String (File), 1, 1), Is_Root => True);
      for K in L.Agents.First_Index .. L.Agents.Last_Index loop
         if K > Max_Agents then
            Report (Result, Error, L.Trees (L.Agents (K).Doc).Where (L.Agents (K).Node),
                    "more than" & Max_Agents'Image & " agents in one configuration");
            exit;
         end if;
         Read_Agent (L, Result, L.Agents (K));
      end loop;
      --  An override must name a constant the files define or use.
      for C in Overrides.Iterate loop
         declare
            Name : constant String := Components.String_Maps.Key (C);
            Bare : constant String :=
              (if Name'Length > 0 and then Name (Name'First) = '$'
               then Name (Name'First + 1 .. Name'Last) else Name);
         begin
            if not Mentions_Constant (L, Bare) then
               Report (Result, Error, (To_Unbounded_String (File), 1, 1),
                       "--set " & Printable (Bare) & ": no constant $" & Printable (Bare)
                       & " is defined or used in the configuration");
            end if;
         end;
      end loop;
      if not L.Trees.Is_Empty and then Result.Agents.Is_Empty
        and then Error_Count (Result) = 0
      then
         Report (Result, Error, L.Trees.First_Element.Where (L.Trees.First_Element.Root),
                 "no <agent> in the configuration");
      end if;
      Diagnostic_Sorting.Sort (Result.Diagnostics);
   end Load;

end Sancta.Runtime.Configurations.Loading;
