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
--  xi:include is not supported (the error says so).
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
      Depth   : Natural := 0;
      Too_Far : Sax.Locators.Location;
      --  The start tag that went past Max_Policy_Depth.
   end record;
   --  A DOM reader that remembers where each element's start tag ends, so
   --  that an error about an element names its line and column; Too_Deep
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
   end Start_Element;

   overriding procedure End_Element
     (Handler    : in out Locating_Reader;
      NS         : Sax.Utils.XML_NS;
      Local_Name : Sax.Symbols.Symbol) is
   begin
      DOM.Readers.Tree_Reader (Handler).End_Element (NS, Local_Name);
      Handler.Depth := Handler.Depth - 1;
   end End_Element;

   function Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Place_Of (Reader : Locating_Reader; Element : DOM.Core.Node) return String is
      --  "LINE:COLUMN" where Element's start tag ends.
   begin
      for P of Reader.Places loop
         if P.Element = Element then
            return Image (P.Place.Line) & ":" & Image (P.Place.Column);
         end if;
      end loop;
      return "1:1";
   end Place_Of;

   type Schema_Rule is record
      Children, Attributes : Unbounded_String;
   end record;
   --  What SROS2's policy schema allows in an element: the names of its
   --  child elements and of its attributes, separated by spaces.

   function "+" (Names : String) return Unbounded_String renames To_Unbounded_String;

   function Schema_Of (Element : String) return Schema_Rule is
     (if Element = "policy" then (+"enclaves", +"version")
      elsif Element = "enclaves" then (+"enclave", +"")
      elsif Element = "enclave" then (+"profiles", +"path")
      elsif Element = "profiles" then (+"profile metadata", +"type")
      elsif Element = "profile" then (+"topics services actions", +"ns node xml:base")
      elsif Element = "topics" then (+"topic", +"publish subscribe xml:base")
      elsif Element = "services" then (+"service", +"reply request xml:base")
      elsif Element = "actions" then (+"action", +"call execute xml:base")
      else (+"", +""));
   --  Example: Schema_Of ("topics") = (+"topic", +"publish subscribe xml:base");
   --  the names topic, service and action hold text only: (+"", +"").

   function Listed (Word, List : String) return Boolean is
     (Ada.Strings.Fixed.Index (" " & List & " ", " " & Word & " ") > 0);

   function Alternatives (List : String) return String is
      --  Example: "a b c" -> "a, b or c"; "" -> "none".
      Space : constant Natural := Ada.Strings.Fixed.Index (List, " ");
      Rest  : constant String := (if Space = 0 then "" else List (Space + 1 .. List'Last));
   begin
      if List = "" then
         return "none";
      elsif Space = 0 then
         return List;
      elsif Ada.Strings.Fixed.Index (Rest, " ") = 0 then
         return List (List'First .. Space - 1) & " or " & Rest;
      end if;
      return List (List'First .. Space - 1) & ", " & Alternatives (Rest);
   end Alternatives;

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
         raise Command_Error with File & ":" & Place_Of (Reader, Element) & ": " & Why;
      end Fail;

      procedure Add (Allow : Boolean; Kind : Keystores.Access_Kind; Topic : String) is
      begin
         if Count = Rules'Last then
            Fail ("more than" & Rules'Last'Image & " rules");
         end if;
         Count := Count + 1;
         Rules (Count) := (Allow, Kind, To_Unbounded_String (Topic));
      end Add;

      function Elements (Parent : DOM.Core.Node; Name : String) return DOM.Core.Node_List is
        (DOM.Core.Elements.Get_Elements_By_Tag_Name (Parent, Name));

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
         return Ada.Strings.Fixed.Trim (To_String (Result), Ada.Strings.Both);
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

      procedure Check_Schema (Element : DOM.Core.Node) is
         --  Refuses an element or attribute that SROS2's policy schema
         --  (policy.xsd, format 0.2.0) does not define where it stands,
         --  as SROS2 does: a misspelt <topcis> would otherwise give no rule.
         --  Example: <topics><topicz>a</topicz></topics> ->
         --  "FILE:L:C: unknown element 'topicz' in <topics> (expected topic)"
         Name     : constant String := DOM.Core.Nodes.Node_Name (Element);
         Rule     : constant Schema_Rule := Schema_Of (Name);
         Children : constant String := To_String (Rule.Children);
         Allowed  : constant String := To_String (Rule.Attributes);
         Attrs    : constant DOM.Core.Named_Node_Map := DOM.Core.Nodes.Attributes (Element);
         Nodes    : constant DOM.Core.Node_List := DOM.Core.Nodes.Child_Nodes (Element);
      begin
         for A in 0 .. DOM.Core.Nodes.Length (Attrs) - 1 loop
            declare
               Attr : constant String := DOM.Core.Nodes.Node_Name (DOM.Core.Nodes.Item (Attrs, A));
            begin
               if not Listed (Attr, Allowed) and then not Is_Namespace_Declaration (Attr) then
                  Fail (Element, "unknown attribute '" & Attr & "' in <" & Name & "> (expected "
                        & Alternatives (Allowed) & ")");
               end if;
            end;
         end loop;
         if Name = "metadata" then
            return;  --  Any content (xs:anyType).
         end if;
         for I in 0 .. DOM.Core.Nodes.Length (Nodes) - 1 loop
            declare
               Child : constant DOM.Core.Node := DOM.Core.Nodes.Item (Nodes, I);
            begin
               if DOM.Core.Nodes.Node_Type (Child) = DOM.Core.Element_Node then
                  if DOM.Core.Nodes.Node_Name (Child) = "xi:include" then
                     Fail (Child, "xi:include is not supported: put the included rules in the"
                           & " profile");
                  elsif not Listed (DOM.Core.Nodes.Node_Name (Child), Children) then
                     Fail (Child, "unknown element '" & DOM.Core.Nodes.Node_Name (Child)
                           & "' in <" & Name & "> (expected " & Alternatives (Children) & ")");
                  end if;
                  Check_Schema (Child);
               end if;
            end;
         end loop;
      end Check_Schema;

      procedure Profile_Rules (Profile : DOM.Core.Node) is
         NS   : constant String := Attribute (Profile, "ns");
         Node : constant String := Attribute (Profile, "node");

         procedure Each
           (Group, Item, Mode_1, Mode_2 : String;
            Action : not null access procedure (Name : String; Mode, Value : String))
         is
            --  Every <Group Mode_1|Mode_2="ALLOW|DENY"> of the profile and
            --  every <Item> in it.
            Groups : constant DOM.Core.Node_List := Elements (Profile, Group);
         begin
            for G in 0 .. DOM.Core.Nodes.Length (Groups) - 1 loop
               declare
                  E     : constant DOM.Core.Node := DOM.Core.Nodes.Item (Groups, G);
                  Items : constant DOM.Core.Node_List := Elements (E, Item);
                  Attrs : constant DOM.Core.Named_Node_Map := DOM.Core.Nodes.Attributes (E);
               begin
                  for A in 0 .. DOM.Core.Nodes.Length (Attrs) - 1 loop
                     declare
                        Mode  : constant String :=
                          DOM.Core.Nodes.Node_Name (DOM.Core.Nodes.Item (Attrs, A));
                        Value : constant String :=
                          DOM.Core.Nodes.Node_Value (DOM.Core.Nodes.Item (Attrs, A));
                     begin
                        if Mode = Mode_1 or else Mode = Mode_2 then
                           --  (Check_Schema refused other names but xml:base and
                           --  xmlns, which give no rule.)
                           if Value not in "ALLOW" | "DENY" then
                              Fail (E, "<" & Group & " " & Mode & "=""" & Value
                                    & """>: expected ALLOW or DENY");
                           end if;
                           for I in 0 .. DOM.Core.Nodes.Length (Items) - 1 loop
                              declare
                                 Name : constant String :=
                                   Text (DOM.Core.Nodes.Item (Items, I));
                              begin
                                 if Name = "" then
                                    Fail (DOM.Core.Nodes.Item (Items, I),
                                          "an empty name in the profile of node " & Node);
                                 end if;
                                 Action (Qualified (Name, NS, Node), Mode, Value);
                              end;
                           end loop;
                        end if;
                     end;
                  end loop;
               end;
            end loop;
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
         Root     : constant DOM.Core.Element := DOM.Core.Documents.Get_Element (Doc);
         Enclaves : constant DOM.Core.Node_List := Elements (Root, "enclave");
      begin
         if DOM.Core.Nodes.Node_Name (Root) /= "policy" then
            Fail (Root, "the root element is <" & DOM.Core.Nodes.Node_Name (Root)
                  & ">, expected <policy>");
         end if;
         Check_Schema (Root);
         for I in 0 .. DOM.Core.Nodes.Length (Enclaves) - 1 loop
            declare
               E        : constant DOM.Core.Node := DOM.Core.Nodes.Item (Enclaves, I);
               Profiles : constant DOM.Core.Node_List := Elements (E, "profile");
            begin
               if Attribute (E, "path") = Enclave then
                  Found := True;
                  for P in 0 .. DOM.Core.Nodes.Length (Profiles) - 1 loop
                     Profile_Rules (DOM.Core.Nodes.Item (Profiles, P));
                  end loop;
               end if;
            end;
         end loop;
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
