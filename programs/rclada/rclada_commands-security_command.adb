--  rclada security: SROS2 keystores (RCL.Security.Keystores), and the
--  policy files of "ros2 security create_permission" turned into DDS
--  permissions: SROS2's policy format 0.2.0
--
--     <policy version="0.2.0"><enclaves><enclave path="/talker">
--       <profiles><profile ns="/" node="talker">
--         <topics publish="ALLOW"><topic>chatter</topic></topics>
--         <services reply="ALLOW"><service>add_two_ints</service></services>
--         <actions call="ALLOW"><action>fibonacci</action></actions>
--       </profile></profiles></enclave></enclaves></policy>
--
--  with SROS2's mapping: topics rt/<name>; a service's request "rq/<name>
--  Request" and reply "rr/<name>Reply" (reply="ALLOW": subscribe requests,
--  publish replies; request="ALLOW": the converse); an action's three
--  services (_action/send_goal, cancel_goal, get_result) and two topics
--  (_action/feedback, status); relative names in the profile's namespace,
--  "~" the node's own; ros_discovery_info always allowed both ways.
--  xi:include is not supported (the error says so). The whole file is
--  checked against SROS2's policy.xsd first (Check_Schema); the rules come
--  from the child elements along enclaves/enclave/profiles/profile only, so
--  that what a <metadata> holds grants nothing (as in SROS2's transform).
with Ada.Characters.Handling;
with Ada.Containers.Vectors;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Text_IO;
with DOM.Core.Documents;
with DOM.Core.Elements;
with DOM.Core.Nodes;
with DOM.Readers;
with Input_Sources.File;
with Sax.Locators;
with Sax.Readers;
with Sax.Symbols;
with Sax.Utils;
with Unicode.CES;
with RCL.Names;
with RCL.Security.Keystores;

separate (Rclada_Commands)
procedure Security_Command (Args : Arguments) is

   package Keystores renames RCL.Security.Keystores;
   use type Ada.Directories.File_Size;
   use type DOM.Core.Node;
   use type DOM.Core.Node_Types;

   function Arg (I : Positive) return String is
     (if Natural (Args.Length) >= I then Args (I) else "");

   procedure Need (Count : Positive) is
   begin
      if Natural (Args.Length) /= Count then
         raise Usage_Error with "security " & Arg (1) & ": expected"
           & Natural'Image (Count - 1) & " argument(s)";
      end if;
   end Need;

   -- Policy files --

   type Action_Service is (Send_Goal, Cancel_Goal, Get_Result);
   type Action_Topic is (Feedback, Status);
   --  The services and topics of an action (their names in lower case).

   function Lower (S : String) return String renames Ada.Characters.Handling.To_Lower;

   type Placed_Element is record
      Element : DOM.Core.Node;
      Place   : Sax.Locators.Location;
   end record;

   package Placed_Elements is new Ada.Containers.Vectors (Positive, Placed_Element);

   Max_Policy_Depth : constant := 100;
   Max_Policy_Size  : constant := 1024 * 1024;
   --  SROS2 policies nest 7 deep and take kilobytes. The XML reader takes
   --  time quadratic in the depth (100,000 levels: minutes) and overflows
   --  its stack on a name of megabytes.

   Too_Deep : exception;

   type Locating_Reader is new DOM.Readers.Tree_Reader with record
      Places  : Placed_Elements.Vector;
      Texts   : Placed_Elements.Vector;
      --  For each element with non-blank character data, where the first
      --  non-blank character of it is.
      Last    : Sax.Locators.Location;
      --  Where the last event's markup or text ended.
      In_Cdata : Boolean := False;
      Depth   : Natural := 0;
      Too_Far : Sax.Locators.Location;
      --  The start tag that went past Max_Policy_Depth.
   end record;
   --  A DOM reader that remembers where each element's start tag ends (and
   --  its first text), so that an error about an element (or about text where
   --  none may be) names its line and column; Too_Deep
   --  (at the start tag) when elements nest deeper than Max_Policy_Depth.

   overriding procedure Start_Element
     (Handler    : in out Locating_Reader;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol;
      Atts       : Sax.Readers.Sax_Attribute_List);

   overriding procedure End_Element
     (Handler    : in out Locating_Reader;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol);

   overriding procedure Characters
     (Handler : in out Locating_Reader;
      Ch      : Unicode.CES.Byte_Sequence);

   overriding procedure Ignorable_Whitespace
     (Handler : in out Locating_Reader;
      Ch      : Unicode.CES.Byte_Sequence);
   --  (The reader's report of text made of blanks only.)

   overriding procedure Comment
     (Handler : in out Locating_Reader;
      Comment : Unicode.CES.Byte_Sequence);

   overriding procedure Processing_Instruction
     (Handler : in out Locating_Reader;
      Target  : Unicode.CES.Byte_Sequence;
      Data    : Unicode.CES.Byte_Sequence);

   overriding procedure Start_Cdata (Handler : in out Locating_Reader);
   overriding procedure End_Cdata (Handler : in out Locating_Reader);
   --  These and the two above note where each event ended (the reader tells
   --  where an event ends, not where it starts; of a CDATA section, it tells
   --  where the section ends, even at its start).

   XML_Blanks : constant Ada.Strings.Maps.Character_Set :=
     Ada.Strings.Maps.To_Set (' ' & ASCII.HT & ASCII.LF & ASCII.CR);
   --  XML's white space.

   function Is_Blank (S : String) return Boolean is
     (Ada.Strings.Fixed.Index (S, XML_Blanks, Test => Ada.Strings.Outside) = 0);

   overriding procedure Start_Element
     (Handler    : in out Locating_Reader;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol;
      Atts       : Sax.Readers.Sax_Attribute_List) is
   begin
      Handler.Depth := Handler.Depth + 1;
      if Handler.Depth > Max_Policy_Depth then
         Handler.Too_Far := Handler.Current_Location;
         raise Too_Deep;
      end if;
      DOM.Readers.Tree_Reader (Handler).Start_Element (NS, Local_Name, Atts);
      Handler.Places.Append (Placed_Element'(Handler.Current_Node, Handler.Current_Location));
      Handler.Last := Handler.Current_Location;
   end Start_Element;

   overriding procedure End_Element
     (Handler    : in out Locating_Reader;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol) is
   begin
      DOM.Readers.Tree_Reader (Handler).End_Element (NS, Local_Name);
      Handler.Depth := Handler.Depth - 1;
      Handler.Last := Handler.Current_Location;
   end End_Element;

   overriding procedure Characters
     (Handler : in out Locating_Reader;
      Ch      : Unicode.CES.Byte_Sequence)
   is
      Place : Sax.Locators.Location := Handler.Last;
      --  Ch starts where the last event ended (in a CDATA section, after
      --  the "<![CDATA[" there): its first non-blank character is after the
      --  blanks that come first.
   begin
      if Handler.In_Cdata then
         Place.Column := Place.Column + 9;
      end if;
      DOM.Readers.Tree_Reader (Handler).Characters (Ch);
      if not Is_Blank (Ch)
        and then (Handler.Texts.Is_Empty
                  or else Handler.Texts.Last_Element.Element /= Handler.Current_Node)
      then
         for C of Ch loop
            exit when not Ada.Strings.Maps.Is_In (C, XML_Blanks);
            if C = ASCII.LF then
               Place.Line := Place.Line + 1;
               Place.Column := 1;
            else
               Place.Column := Place.Column + 1;
            end if;
         end loop;
         Handler.Texts.Append (Placed_Element'(Handler.Current_Node, Place));
      end if;
      Handler.Last := Handler.Current_Location;
   end Characters;

   overriding procedure Ignorable_Whitespace
     (Handler : in out Locating_Reader;
      Ch      : Unicode.CES.Byte_Sequence) is
   begin
      DOM.Readers.Tree_Reader (Handler).Ignorable_Whitespace (Ch);
      Handler.Last := Handler.Current_Location;
   end Ignorable_Whitespace;

   overriding procedure Comment
     (Handler : in out Locating_Reader;
      Comment : Unicode.CES.Byte_Sequence) is
   begin
      DOM.Readers.Tree_Reader (Handler).Comment (Comment);
      Handler.Last := Handler.Current_Location;
   end Comment;

   overriding procedure Processing_Instruction
     (Handler : in out Locating_Reader;
      Target  : Unicode.CES.Byte_Sequence;
      Data    : Unicode.CES.Byte_Sequence) is
   begin
      DOM.Readers.Tree_Reader (Handler).Processing_Instruction (Target, Data);
      Handler.Last := Handler.Current_Location;
   end Processing_Instruction;

   overriding procedure Start_Cdata (Handler : in out Locating_Reader) is
   begin
      Handler.In_Cdata := True;  --  Last stays where the section starts.
   end Start_Cdata;

   overriding procedure End_Cdata (Handler : in out Locating_Reader) is
   begin
      Handler.In_Cdata := False;
      Handler.Last := Handler.Current_Location;
   end End_Cdata;

   function Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Place_Of
     (Element : DOM.Core.Node; Places : Placed_Elements.Vector) return String is
      --  "LINE:COLUMN" of Element in Places (a Locating_Reader's).
   begin
      for P of Places loop
         if P.Element = Element then
            return Image (P.Place.Line) & ":" & Image (P.Place.Column);
         end if;
      end loop;
      return "1:1";
   end Place_Of;

   type Schema_Rule is record
      Children, Attributes : Unbounded_String;
      --  The names of the child elements and of the attributes allowed,
      --  separated by spaces.
      Needed_Children, Needed_Attributes : Unbounded_String;
      --  Those of them that must be there (children: at least once).
      Single : Unbounded_String;
      --  The children allowed at most once.
      Text : Boolean := False;
      --  Character data allowed (else only blanks between the children).
      Qualifiers : Boolean := False;
      --  The attributes other than xml:base take ALLOW or DENY.
   end record;
   --  What SROS2's policy schema (policy.xsd, format 0.2.0) says of an
   --  element; <metadata> is of any content and has no rule.

   function "+" (Names : String) return Unbounded_String renames To_Unbounded_String;

   function Group_Rule (Item, Modes : String) return Schema_Rule is
     (Children => +Item, Attributes => +(Modes & " xml:base"),
      Needed_Children => +Item, Needed_Attributes => +"", Single => +"",
      Text => False, Qualifiers => True);
   --  <topics>, <services>, <actions>: one or more items, two optional modes.

   function Schema_Of (Element : String) return Schema_Rule is
     (if Element = "policy" then
        (Children => +"enclaves", Attributes => +"version", Needed_Children => +"enclaves",
         Needed_Attributes => +"version", Single => +"enclaves", others => False)
      elsif Element = "enclaves" then
        (Children => +"enclave", Attributes => +"", Needed_Children => +"enclave",
         Needed_Attributes => +"", Single => +"", others => False)
      elsif Element = "enclave" then
        (Children => +"profiles", Attributes => +"path", Needed_Children => +"profiles",
         Needed_Attributes => +"path", Single => +"", others => False)
      elsif Element = "profiles" then
        (Children => +"profile metadata", Attributes => +"type", Needed_Children => +"profile",
         Needed_Attributes => +"", Single => +"metadata", others => False)
      elsif Element = "profile" then
        (Children => +"topics services actions", Attributes => +"ns node xml:base",
         Needed_Children => +"", Needed_Attributes => +"ns node", Single => +"",
         others => False)
      elsif Element = "topics" then Group_Rule ("topic", "publish subscribe")
      elsif Element = "services" then Group_Rule ("service", "reply request")
      elsif Element = "actions" then Group_Rule ("action", "call execute")
      else
        (Children => +"", Attributes => +"", Needed_Children => +"", Needed_Attributes => +"",
         Single => +"", Text => True, Qualifiers => False));
   --  Example: Schema_Of ("enclave") requires a path and one <profiles> or
   --  more; the names topic, service and action hold text only.

   Policy_Version : constant String := "0.2.0";
   --  The value policy.xsd fixes for <policy version>.

   function Listed (Word, List : String) return Boolean is
     (Ada.Strings.Fixed.Index (" " & List & " ", " " & Word & " ") > 0);

   function Alternatives (List : String; Last : String := "or") return String is
      --  Example: "a b c" -> "a, b or c"; "" -> "none"; ("a b", "and") -> "a and b".
      Space : constant Natural := Ada.Strings.Fixed.Index (List, " ");
      Rest  : constant String := (if Space = 0 then "" else List (Space + 1 .. List'Last));
   begin
      if List = "" then
         return "none";
      elsif Space = 0 then
         return List;
      elsif Ada.Strings.Fixed.Index (Rest, " ") = 0 then
         return List (List'First .. Space - 1) & " " & Last & " " & Rest;
      end if;
      return List (List'First .. Space - 1) & ", " & Alternatives (Rest, Last);
   end Alternatives;

   function Trimmed (S : String) return String is
     (Ada.Strings.Fixed.Trim (S, Left => XML_Blanks, Right => XML_Blanks));

   function Excerpt (S : String) return String is
      --  The start of S without blanks around, up to a line's end or 30
      --  bytes (not inside a UTF-8 character); "..." when cut.
      T    : constant String := Trimmed (S);
      Last : Natural := Natural'Min (T'Last, T'First + 29);
   begin
      for I in T'First .. Last loop
         if Character'Pos (T (I)) < 32 then
            Last := I - 1;
            exit;
         end if;
      end loop;
      while Last in T'Range and then Last < T'Last
        and then Character'Pos (T (Last + 1)) in 16#80# .. 16#BF#
      loop
         Last := Last - 1;
      end loop;
      return T (T'First .. Last) & (if Last < T'Last then "..." else "");
   end Excerpt;

   function Is_Namespace_Declaration (Attribute : String) return Boolean is
     (Attribute = "xmlns"
      or else (Attribute'Length > 6
               and then Attribute (Attribute'First .. Attribute'First + 5) = "xmlns:"));
   --  xmlns="..." and xmlns:PREFIX="...": no attributes to a schema.

   type Rule_Vector is array (Positive range <>) of Keystores.Topic_Rule;

   function Policy_Rules (File, Enclave : String) return Keystores.Topic_Rules is
      Input  : Input_Sources.File.File_Input;
      Reader : Locating_Reader;
      Doc    : DOM.Core.Document;
      Rules  : Rule_Vector (1 .. 10_000);
      Count  : Natural := 0;
      Found  : Boolean := False;

      procedure Fail (Why : String) with No_Return is
      begin
         raise Command_Error with File & ": " & Why;
      end Fail;

      procedure Fail (Element : DOM.Core.Node; Why : String) with No_Return is
      begin
         raise Command_Error with File & ":" & Place_Of (Element, Reader.Places) & ": " & Why;
      end Fail;

      procedure Fail_In_Text (Element : DOM.Core.Node; Why : String) with No_Return is
         --  At Element's first non-blank text.
      begin
         raise Command_Error with File & ":" & Place_Of (Element, Reader.Texts) & ": " & Why;
      end Fail_In_Text;

      procedure Add (Allow : Boolean; Kind : Keystores.Access_Kind; Topic : String) is
      begin
         if Count = Rules'Last then
            Fail ("more than" & Rules'Last'Image & " rules");
         end if;
         Count := Count + 1;
         Rules (Count) := (Allow, Kind, To_Unbounded_String (Topic));
      end Add;

      procedure For_Each
        (Parent  : DOM.Core.Node;
         Name    : String;
         Process : not null access procedure (Child : DOM.Core.Node))
      is
         --  Process each child element of Parent named Name, in order; not
         --  the grandchildren (a <metadata> may hold <profile>s: no rules).
         Nodes : constant DOM.Core.Node_List := DOM.Core.Nodes.Child_Nodes (Parent);
      begin
         for I in 0 .. DOM.Core.Nodes.Length (Nodes) - 1 loop
            declare
               Child : constant DOM.Core.Node := DOM.Core.Nodes.Item (Nodes, I);
            begin
               if DOM.Core.Nodes.Node_Type (Child) = DOM.Core.Element_Node
                 and then DOM.Core.Nodes.Node_Name (Child) = Name
               then
                  Process (Child);
               end if;
            end;
         end loop;
      end For_Each;

      function Attribute (E : DOM.Core.Node; Name : String) return String is
        (DOM.Core.Elements.Get_Attribute (E, Name));

      function Text (E : DOM.Core.Node) return String is
         Children : constant DOM.Core.Node_List := DOM.Core.Nodes.Child_Nodes (E);
         Result   : Unbounded_String;
      begin
         for I in 0 .. DOM.Core.Nodes.Length (Children) - 1 loop
            declare
               C : constant DOM.Core.Node := DOM.Core.Nodes.Item (Children, I);
            begin
               if DOM.Core.Nodes.Node_Type (C) = DOM.Core.Text_Node then
                  Append (Result, DOM.Core.Nodes.Node_Value (C));
               end if;
            end;
         end loop;
         return Trimmed (To_String (Result));
      end Text;

      function Qualified (Name, Namespace, Node_Name : String) return String
        with Pre => Name /= ""
      is
         --  SROS2's resolution: absolute names as they are, "~" the node's
         --  own namespace, others relative to the profile's namespace.
         NS : constant String :=
           (if Namespace = "" or else Namespace = "/" then ""
            elsif Namespace (Namespace'Last) = '/' then
               Namespace (Namespace'First .. Namespace'Last - 1)
            else Namespace);
      begin
         return (if Name (Name'First) = '/' then Name
                 elsif Name (Name'First) = '~'
                 then NS & "/" & Node_Name & Name (Name'First + 1 .. Name'Last)
                 else NS & "/" & Name);
      end Qualified;

      function Without_Slash (Name : String) return String is
        (Name (Name'First + 1 .. Name'Last));

      procedure Service_Rules (Name : String; Allow, Server : Boolean) is
         Request : constant String := "rq/" & Without_Slash (Name) & "Request";
         Reply   : constant String := "rr/" & Without_Slash (Name) & "Reply";
         use Keystores;
      begin
         Add (Allow, (if Server then Subscribe else Publish), Request);
         Add (Allow, (if Server then Publish else Subscribe), Reply);
      end Service_Rules;

      function Name_Problem (Name : String) return String is
         --  "" when Name is a ROS 2 name (relative, absolute or "~/...")
         --  or a pattern of them (* ? [a-z] [!x] as DDS permissions match
         --  topic names), else which character is not.
      begin
         for I in Name'Range loop
            declare
               C : constant Character := Name (I);
            begin
               if not (C in 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_' | '/'
                              | '*' | '?' | '[' | ']' | '!' | '^' | '-'
                       or else (C = '~' and then I = Name'First
                                and then (I = Name'Last or else Name (I + 1) = '/')))
               then
                  return "invalid character "
                    & (if C in ' ' .. '~' then "'" & C & "'"
                       else "(byte" & Character'Pos (C)'Image & ")")
                    & " at position" & Natural'Image (I - Name'First + 1);
               end if;
            end;
         end loop;
         return "";
      end Name_Problem;

      procedure Check_Schema (Element : DOM.Core.Node) is
         --  Refuses what SROS2's policy schema (policy.xsd, format 0.2.0)
         --  refuses, as SROS2 does: elements and attributes it does not
         --  define where they stand (a misspelt <topcis> would otherwise give
         --  no rule), required ones missing, one too many, text between
         --  elements, a mode other than ALLOW or DENY, another version.
         --  Example: <topics><topicz>a</topicz></topics> ->
         --  "FILE:L:C: unknown element 'topicz' in <topics> (expected topic)"
         Name     : constant String := DOM.Core.Nodes.Node_Name (Element);
         Rule     : constant Schema_Rule := Schema_Of (Name);
         Children : constant String := To_String (Rule.Children);
         Allowed  : constant String := To_String (Rule.Attributes);
         Attrs    : constant DOM.Core.Named_Node_Map := DOM.Core.Nodes.Attributes (Element);
         Nodes    : constant DOM.Core.Node_List := DOM.Core.Nodes.Child_Nodes (Element);
         Seen     : Unbounded_String;
         --  The names of the children met so far, each once.

         procedure Each_Word
           (List : String; Process : not null access procedure (Word : String)) is
            First : Positive := List'First;
         begin
            for I in List'Range loop
               if List (I) = ' ' then
                  Process (List (First .. I - 1));
                  First := I + 1;
               elsif I = List'Last then
                  Process (List (First .. I));
               end if;
            end loop;
         end Each_Word;

         procedure Need_Attribute (Attr : String) is
         begin
            if DOM.Core.Elements.Get_Attribute_Node (Element, Attr) = null then
               Fail (Element, "missing attribute '" & Attr & "' in <" & Name & "> (required: "
                     & Alternatives (To_String (Rule.Needed_Attributes), "and") & ")");
            end if;
         end Need_Attribute;

         procedure Need_Child (Child : String) is
         begin
            if not Listed (Child, To_String (Seen)) then
               Fail (Element, "missing element <" & Child & "> in <" & Name & "> (required: "
                     & (if Listed (Child, To_String (Rule.Single)) then "one" else "one or more")
                     & ")");
            end if;
         end Need_Child;
      begin
         if Name = "metadata" then
            return;  --  Any attributes and content (xs:anyType).
         end if;
         for A in 0 .. DOM.Core.Nodes.Length (Attrs) - 1 loop
            declare
               Attr  : constant String := DOM.Core.Nodes.Node_Name (DOM.Core.Nodes.Item (Attrs, A));
               Value : constant String :=
                 DOM.Core.Nodes.Node_Value (DOM.Core.Nodes.Item (Attrs, A));
            begin
               if Is_Namespace_Declaration (Attr) then
                  null;
               elsif not Listed (Attr, Allowed) then
                  Fail (Element, "unknown attribute '" & Attr & "' in <" & Name & "> (expected "
                        & Alternatives (Allowed) & ")");
               elsif Rule.Qualifiers and then Attr /= "xml:base"
                 and then Value not in "ALLOW" | "DENY"
               then
                  Fail (Element, "<" & Name & " " & Attr & "=""" & Excerpt (Value)
                        & """>: expected ALLOW or DENY");
               elsif Name = "policy" and then Attr = "version" and then Value /= Policy_Version
               then
                  Fail (Element, "<policy version=""" & Excerpt (Value) & """>: expected version "
                        & Policy_Version & " (SROS2's policy format)");
               end if;
            end;
         end loop;
         Each_Word (To_String (Rule.Needed_Attributes), Need_Attribute'Access);
         if Name = "profile" then
            --  The names SROS2 joins into topic names: a namespace ("" and a
            --  final '/' as SROS2 takes them) and a node name, as in ROS 2.
            declare
               NS      : constant String := Attribute (Element, "ns");
               Node    : constant String := Attribute (Element, "node");
               Problem : constant String :=
                 (if NS = "" then ""
                  elsif NS'Length > 1 and then NS (NS'Last) = '/'
                  then RCL.Names.Namespace_Problem (NS (NS'First .. NS'Last - 1))
                  else RCL.Names.Namespace_Problem (NS));
            begin
               if Problem /= "" then
                  Fail (Element, "in <profile>: " & Problem);
               elsif RCL.Names.Node_Name_Problem (Node) /= "" then
                  Fail (Element, "in <profile>: " & RCL.Names.Node_Name_Problem (Node));
               end if;
            end;
         elsif Rule.Text and then Text (Element) = "" then
            Fail (Element, "an empty name in the profile of node "
                  & Attribute (DOM.Core.Nodes.Parent_Node (DOM.Core.Nodes.Parent_Node (Element)),
                               "node"));
         elsif Rule.Text and then Name_Problem (Text (Element)) /= "" then
            Fail (Element, "<" & Name & "> '" & Excerpt (Text (Element)) & "': "
                  & Name_Problem (Text (Element)));
         end if;
         for I in 0 .. DOM.Core.Nodes.Length (Nodes) - 1 loop
            declare
               Child      : constant DOM.Core.Node := DOM.Core.Nodes.Item (Nodes, I);
               Child_Name : constant String := DOM.Core.Nodes.Node_Name (Child);
            begin
               if DOM.Core.Nodes.Node_Type (Child) = DOM.Core.Element_Node then
                  if Child_Name = "xi:include" then
                     Fail (Child, "xi:include is not supported: put the included rules in the"
                           & " profile");
                  elsif not Listed (Child_Name, Children) then
                     Fail (Child, "unknown element '" & Child_Name & "' in <" & Name
                           & "> (expected " & Alternatives (Children) & ")");
                  elsif Listed (Child_Name, To_String (Seen))
                    and then Listed (Child_Name, To_String (Rule.Single))
                  then
                     Fail (Child, "a second <" & Child_Name & "> in <" & Name
                           & "> (allowed: one)");
                  elsif Name = "profiles" and then Listed ("metadata", To_String (Seen)) then
                     Fail (Child, "<" & Child_Name & "> after <metadata> in <profiles> (the"
                           & " <metadata> comes last)");
                  end if;
                  if not Listed (Child_Name, To_String (Seen)) then
                     Append (Seen, (if Seen = "" then "" else " ") & Child_Name);
                  end if;
                  Check_Schema (Child);
               elsif DOM.Core.Nodes.Node_Type (Child) = DOM.Core.Text_Node
                 and then not Rule.Text
                 and then not Is_Blank (DOM.Core.Nodes.Node_Value (Child))
               then
                  Fail_In_Text (Element, "text '" & Excerpt (DOM.Core.Nodes.Node_Value (Child))
                                & "' in <" & Name & "> (only elements are allowed there)");
               end if;
            end;
         end loop;
         Each_Word (To_String (Rule.Needed_Children), Need_Child'Access);
      end Check_Schema;

      procedure Profile_Rules (Profile : DOM.Core.Node) is
         NS   : constant String := Attribute (Profile, "ns");
         Node : constant String := Attribute (Profile, "node");

         procedure Each
           (Group, Item, Mode_1, Mode_2 : String;
            Action : not null access procedure (Name : String; Mode, Value : String))
         is
            --  Every <Group Mode_1|Mode_2="ALLOW|DENY"> of the profile and
            --  every <Item> in it (Check_Schema checked the values).
            procedure Group_Rules (G : DOM.Core.Node) is
               Attrs : constant DOM.Core.Named_Node_Map := DOM.Core.Nodes.Attributes (G);
            begin
               for A in 0 .. DOM.Core.Nodes.Length (Attrs) - 1 loop
                  declare
                     Mode  : constant String :=
                       DOM.Core.Nodes.Node_Name (DOM.Core.Nodes.Item (Attrs, A));
                     Value : constant String :=
                       DOM.Core.Nodes.Node_Value (DOM.Core.Nodes.Item (Attrs, A));

                     procedure Item_Rule (I : DOM.Core.Node) is
                     begin
                        --  (Check_Schema refused an empty name.)
                        Action (Qualified (Text (I), NS, Node), Mode, Value);
                     end Item_Rule;
                  begin
                     if Mode = Mode_1 or else Mode = Mode_2 then
                        For_Each (G, Item, Item_Rule'Access);
                     end if;
                  end;
               end loop;
            end Group_Rules;
         begin
            For_Each (Profile, Group, Group_Rules'Access);
         end Each;

         procedure Topic (Name, Mode, Value : String) is
         begin
            Add (Value = "ALLOW",
                 (if Mode = "publish" then Keystores.Publish else Keystores.Subscribe),
                 "rt/" & Without_Slash (Name));
         end Topic;

         procedure Service (Name, Mode, Value : String) is
         begin
            Service_Rules (Name, Value = "ALLOW", Server => Mode = "reply");
         end Service;

         procedure Action (Name, Mode, Value : String) is
            Server : constant Boolean := Mode = "execute";
         begin
            for S in Action_Service loop
               Service_Rules (Name & "/_action/" & Lower (Action_Service'Image (S)),
                              Value = "ALLOW", Server);
            end loop;
            for T in Action_Topic loop
               Add (Value = "ALLOW", (if Server then Keystores.Publish else Keystores.Subscribe),
                    "rt/" & Without_Slash (Name) & "/_action/" & Lower (Action_Topic'Image (T)));
            end loop;
         end Action;
      begin
         Each ("topics", "topic", "publish", "subscribe", Topic'Access);
         Each ("services", "service", "reply", "request", Service'Access);
         Each ("actions", "action", "call", "execute", Action'Access);
      end Profile_Rules;

   begin
      begin
         Input_Sources.File.Open (File, Input);
      exception
         when others =>
            raise Command_Error with File & ": cannot open";
      end;
      if Ada.Directories.Size (File) > Max_Policy_Size then
         Input_Sources.File.Close (Input);
         Fail (Ada.Strings.Fixed.Trim (Ada.Directories.Size (File)'Image, Ada.Strings.Left)
               & " bytes: a policy file may not exceed" & Max_Policy_Size'Image & " bytes");
      end if;
      Reader.Set_Feature (Sax.Readers.Namespace_Feature, False);
      begin
         Reader.Parse (Input);
      exception
         when E : Sax.Readers.XML_Fatal_Error =>
            Input_Sources.File.Close (Input);
            --  XML/Ada's message starts with "FILE:LINE:COLUMN: " already.
            declare
               Message : constant String := Ada.Exceptions.Exception_Message (E);
               Located : constant Boolean :=
                 Message'Length > File'Length
                 and then Message (Message'First .. Message'First + File'Length) = File & ":";
            begin
               raise Command_Error with
                 (if Located
                  then File & ":" & Message (Message'First + File'Length + 1 .. Message'Last)
                    & " (malformed XML)"
                  elsif Message'Length > 0 and then Message (Message'First) = ':'
                  then File & Message & " (malformed XML)"  --  ":1:0: No root element"
                  else File & ": malformed XML: " & Message);
            end;
         when Too_Deep =>
            Input_Sources.File.Close (Input);
            raise Command_Error with File & ":" & Image (Reader.Too_Far.Line) & ":"
              & Image (Reader.Too_Far.Column) & ": elements nested deeper than"
              & Max_Policy_Depth'Image;
         when E : Unicode.CES.Invalid_Encoding =>
            Input_Sources.File.Close (Input);
            declare
               Place : constant Sax.Locators.Location := Reader.Current_Location;
            begin
               raise Command_Error with File & ":" & Image (Place.Line) & ":"
                 & Image (Place.Column) & ": " & Ada.Exceptions.Exception_Message (E)
                 & " (malformed XML)";
            end;
      end;
      Input_Sources.File.Close (Input);
      Doc := Reader.Get_Tree;
      declare
         Root : constant DOM.Core.Element := DOM.Core.Documents.Get_Element (Doc);

         procedure Profiles_Rules (Profiles : DOM.Core.Node) is
         begin
            For_Each (Profiles, "profile", Profile_Rules'Access);
         end Profiles_Rules;

         procedure Enclave_Rules (E : DOM.Core.Node) is
         begin
            if Attribute (E, "path") = Enclave then
               Found := True;
               For_Each (E, "profiles", Profiles_Rules'Access);
            end if;
         end Enclave_Rules;

         procedure Enclaves_Rules (Enclaves : DOM.Core.Node) is
         begin
            For_Each (Enclaves, "enclave", Enclave_Rules'Access);
         end Enclaves_Rules;
      begin
         if DOM.Core.Nodes.Node_Name (Root) /= "policy" then
            Fail (Root, "the root element is <" & DOM.Core.Nodes.Node_Name (Root)
                  & ">, expected <policy>");
         end if;
         Check_Schema (Root);
         For_Each (Root, "enclaves", Enclaves_Rules'Access);
      end;
      if not Found then
         Fail ("no <enclave path=""" & Enclave & """>");
      end if;
      Add (True, Keystores.Publish, "ros_discovery_info");
      Add (True, Keystores.Subscribe, "ros_discovery_info");
      return Keystores.Topic_Rules (Rules (1 .. Count));
   end Policy_Rules;

   Verb : constant String := Arg (1);
begin
   if Verb = "create_keystore" then
      Need (2);
      Keystores.Create_Keystore (Arg (2));
      Ada.Text_IO.Put_Line ("keystore " & Arg (2) & " ready");
   elsif Verb = "create_enclave" then
      Need (3);
      Keystores.Create_Enclave (Arg (2), Arg (3));
      Ada.Text_IO.Put_Line ("enclave " & Arg (3) & " created in " & Arg (2));
   elsif Verb = "create_permission" then
      Need (4);
      Keystores.Create_Permission (Arg (2), Arg (3), Policy_Rules (Arg (4), Arg (3)));
      Ada.Text_IO.Put_Line ("permissions of " & Arg (3) & " written and signed");
   elsif Verb = "list_enclaves" then
      Need (2);
      for Name of Keystores.List_Enclaves (Arg (2)) loop
         Ada.Text_IO.Put_Line (To_String (Name));
      end loop;
   elsif Verb = "" then
      raise Usage_Error with "security: a sub-command is needed";
   else
      raise Usage_Error with "security: unknown sub-command '" & Verb & "'";
   end if;
end Security_Command;
