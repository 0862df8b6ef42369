with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Streams;
with AUnit.Assertions; use AUnit.Assertions;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.DDS;
with RCL.Graph.Queries;
with RCL.YAML.Messages;
with Suite_Support; use Suite_Support;

package body RCL.YAML.Tests is

   use type ROSIDL.Float64;
   use type ROSIDL.UInt8;
   use type ROSIDL.Int32;

   LF : constant Character := ASCII.LF;

   function Parse_Error_Of (Parsing : not null access procedure) return String is
      --  The message of the Parse_Error that Parsing raises, "" when none.
   begin
      Parsing.all;
      return "";
   exception
      when E : Parse_Error =>
         return Ada.Exceptions.Exception_Message (E);
   end Parse_Error_Of;

   function Error_Of (Text : String) return String is
      --  The Parse_Error message for Text, "" when it parses.
      procedure Parse_Text is
         D : constant Document := Parse (Text, "t.yaml");
         pragma Unreferenced (D);
      begin
         null;
      end Parse_Text;
   begin
      return Parse_Error_Of (Parse_Text'Access);
   end Error_Of;

   procedure Block_Structures (Unused : in out Fixture) is
      D : constant Document := Parse
        ("# parameters" & LF
         & "talker:" & LF
         & "  ros__parameters:   # comment" & LF
         & "    rate: 10" & LF
         & "    name: 'my node'" & LF
         & "    gains: [1.5, -2, .5e1]" & LF
         & "    flags:" & LF
         & "    - true" & LF
         & "    - False" & LF
         & "    points:" & LF
         & "      - x: 1" & LF
         & "        y: 2" & LF
         & "      - {x: 3, y: 4}" & LF
         & "    empty:" & LF
         & "    text: ""tab\there \u00e9""" & LF, "p.yaml");
      P : constant Natural := D.Find (D.Find (D.Root, "talker"), "ros__parameters");
   begin
      Assert (D.Kind (D.Root) = Mapping and then P /= 0, "nested mappings");
      Assert (D.Length (P) = 7, "seven parameters:" & D.Length (P)'Image);
      Assert (D.Text (D.Find (P, "rate")) = "10"
              and then D.Scalar_Type (D.Find (P, "rate")) = Int_Scalar, "int");
      Assert (D.Text (D.Find (P, "name")) = "my node"
              and then D.Scalar_Type (D.Find (P, "name")) = String_Scalar, "quoted string");
      declare
         G : constant Node := D.Find (P, "gains");
      begin
         Assert (D.Kind (G) = Sequence and then D.Length (G) = 3, "flow sequence");
         Assert (D.Scalar_Type (D.Item (G, 1)) = Float_Scalar
                 and then D.Scalar_Type (D.Item (G, 2)) = Int_Scalar
                 and then D.Scalar_Type (D.Item (G, 3)) = Float_Scalar, "number kinds");
      end;
      Assert (D.Length (D.Find (P, "flags")) = 2
              and then D.Scalar_Type (D.Item (D.Find (P, "flags"), 2)) = Bool_Scalar,
              "block sequence at the key's indentation");
      declare
         Pts : constant Node := D.Find (P, "points");
      begin
         Assert (D.Length (Pts) = 2, "two points");
         Assert (D.Text (D.Find (D.Item (Pts, 1), "y")) = "2", "compact '- key' mapping");
         Assert (D.Text (D.Find (D.Item (Pts, 2), "x")) = "3", "flow mapping item");
      end;
      Assert (D.Kind (D.Find (P, "empty")) = Null_Value, "empty value is null");
      Assert (D.Text (D.Find (P, "text")) = "tab" & ASCII.HT & "here "
              & Character'Val (16#C3#) & Character'Val (16#A9#), "escapes and UTF-8");
      Assert (D.Where (D.Find (P, "rate")) = "p.yaml:4:11",
              "position " & D.Where (D.Find (P, "rate")));
      Assert (D.Key_Where (P, 2) = "p.yaml:5:5", "key position");
      Assert (D.Image (D.Find (P, "gains")) = "[1.5, -2, .5e1]", "flow image");
      Assert (Parse ("").Kind (Parse ("").Root) = Null_Value, "empty document");
      Assert (Parse ("--- # doc" & LF & "a: 1").Length (1) = 1, "document marker");
   end Block_Structures;

   procedure Classification (Unused : in out Fixture) is
   begin
      Assert (Classify ("42") = Int_Scalar and Classify ("-7") = Int_Scalar
              and Classify ("0x1F") = Int_Scalar, "integers");
      Assert (Classify ("1.0") = Float_Scalar and Classify ("1e3") = Float_Scalar
              and Classify (".inf") = Float_Scalar and Classify ("-.inf") = Float_Scalar
              and Classify (".nan") = Float_Scalar and Classify ("2.") = Float_Scalar,
              "floats");
      Assert (Classify ("true") = Bool_Scalar and Classify ("False") = Bool_Scalar, "bools");
      Assert (Classify ("~") = Null_Scalar and Classify ("null") = Null_Scalar, "nulls");
      Assert (Classify ("1.2.3") = String_Scalar and Classify ("yes") = String_Scalar
              and Classify ("e3") = String_Scalar and Classify ("-") = String_Scalar,
              "strings");
   end Classification;

   procedure Errors (Unused : in out Fixture) is
      procedure Expect (Text, Part : String) is
         Msg : constant String := Error_Of (Text);
      begin
         Assert (Contains (Msg, Part),
                 "for " & Text & ": expected '" & Part & "' in '" & Msg & "'");
      end Expect;
   begin
      Expect ("a: [1, 2", "t.yaml:1:4: '[' is never closed");
      Expect ("a: {x: 1,, y}", "t.yaml:1:");
      Expect ("a: 'open", "t.yaml:1:4: unterminated single-quoted");
      Expect ("a: 1" & LF & "a: 2", "t.yaml:2:1: duplicate key ""a""");
      Expect ("a:" & LF & "  b: 1" & LF & "   c: 2", "t.yaml:3:4: bad indentation");
      Expect ("a: b: c", "t.yaml:1:5: a mapping cannot start on the line");
      Expect ("a: &x 1", "anchors and aliases are not supported");
      Expect ("a: |" & LF & "  text", "block scalars");
      Expect ("a:" & LF & ASCII.HT & "b: 1", "t.yaml:2:1: tab character in indentation");
      Expect ("a: ""\q""", "t.yaml:1:5: unknown escape sequence \q");
      Expect ("a: 1" & LF & "- b", "t.yaml:2:1: expected a 'key: value'");
      Expect ("[1, 2] x", "t.yaml:1:8: unexpected text after a flow collection");
      Expect ("a: 1" & LF & "---" & LF & "b: 2", "only one document");
      Expect ("a: ""x\", "t.yaml:1:4: unterminated double-quoted string");
      --  A backslash as the very last byte (read past the end before).
      Expect ("- ""\", "t.yaml:1:3: unterminated double-quoted string");
      Expect ("a: ""x\" & LF & "b: 1", "t.yaml:1:4: unterminated double-quoted string");
      Assert (Error_Of ("a: http://x.y/z") = "", "':' inside a plain scalar is fine");
   end Errors;

   procedure Hostile_Input (Unused : in out Fixture) is
      --  Bounded nesting (no stack overflow), files that are not files, slices.
      Deep  : constant String := [1 .. 5_000 => '['] & [1 .. 5_000 => ']'];
      Fine  : constant String := [1 .. 90 => '['] & [1 .. 90 => ']'];
      Text  : constant String := "xxa: [1, 2]";
   begin
      Assert (Contains (Error_Of (Deep), "t.yaml:1:" & Ada.Strings.Fixed.Trim
                (Natural'Image (Max_Depth), Ada.Strings.Left) & ": collections nested deeper"),
              "deep nesting: " & Error_Of (Deep));
      Assert (Error_Of (Fine) = "", "90 levels are fine: " & Error_Of (Fine));
      declare
         D : constant Document := Parse (Text (3 .. Text'Last), "s.yaml");
      begin
         Assert (D.Length (D.Find (D.Root, "a")) = 2 and then D.Where (D.Root) = "s.yaml:1:1",
                 "a slice not indexed from 1 parses the same");
      end;
      begin
         declare
            D : constant Document := Parse_File (".");
            pragma Unreferenced (D);
         begin
            Assert (False, "a directory parsed");
         end;
      exception
         when E : Parse_Error =>
            Assert (Ada.Exceptions.Exception_Message (E) = ".: not a regular file",
                    Ada.Exceptions.Exception_Message (E));
      end;
   end Hostile_Input;

   procedure Messages_From_YAML (Unused : in out Fixture) is
      use ROSIDL.Typesupport;
      Odom : constant ROSIDL.Dynamic.Message := RCL.YAML.Messages.From_YAML
        (Get_Message_Support ("nav_msgs", "Odometry"),
         "{header: {frame_id: odom, stamp: {sec: 3}}, "
         & "pose: {pose: {position: {x: 1.5, y: -2}}, covariance: ["
         & "1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, "
         & "0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 2.5]}}");
      function Error_Of (Type_Pkg, Type_Name, Text : String) return String is
         procedure Read_Message is
            M : constant ROSIDL.Dynamic.Message := RCL.YAML.Messages.From_YAML
              (Get_Message_Support (Type_Pkg, Type_Name), Text);
            pragma Unreferenced (M);
         begin
            null;
         end Read_Message;
      begin
         return Parse_Error_Of (Read_Message'Access);
      end Error_Of;
   begin
      Assert (Odom ("header")("frame_id").Get_String = "odom", "nested string");
      Assert (Odom ("header")("stamp")("sec").As_Int32.Element.all = 3, "nested int32");
      Assert (Odom ("pose")("pose")("position")("y").As_Float64.Element.all = -2.0,
              "integer into float64");
      Assert (Odom ("pose")("covariance").As_Array (36).As_Float64.Element.all = 2.5,
              "fixed array");
      declare
         Multi : constant ROSIDL.Dynamic.Message := RCL.YAML.Messages.From_YAML
           (Get_Message_Support ("std_msgs", "UInt8MultiArray"), "data: [1, 2, 255]");
      begin
         Assert (Multi ("data").As_Array.Length = 3
                 and then Multi ("data").As_Array (3).As_UInt8.Element.all = 255,
                 "block-style message with a sequence");
      end;
      Assert (Contains (Error_Of ("std_msgs", "String", "{dat: x}"),
                        "<message>:1:2: std_msgs/msg/String has no field 'dat' (fields: data)"),
              Error_Of ("std_msgs", "String", "{dat: x}"));
      Assert (Contains (Error_Of ("std_msgs", "UInt8", "{data: 256}"),
                        "<message>:1:8: 256 is out of range for uint8"),
              Error_Of ("std_msgs", "UInt8", "{data: 256}"));
      Assert (Contains (Error_Of ("std_msgs", "Int32", "{data: x}"),
                        "field 'data' is int32: 'x' is not an integer"), "not an integer");
      Assert (Contains (Error_Of ("std_msgs", "Bool", "{data: 1}"), "is not true or false"),
              "bool");
      Assert (Contains (Error_Of ("nav_msgs", "Odometry", "{pose: {covariance: [1, 2]}}"),
                        "expected 36 elements, found 2"), "fixed array size");
      Assert (Contains (Error_Of ("std_msgs", "Header", "{stamp: 5}"),
                        "builtin_interfaces/msg/Time is a message"), "message vs scalar");
      --  ros2 refuses a message argument that is not a dictionary: nothing,
      --  only a comment, a scalar, a sequence; '{}' is the default message.
      Assert (Contains (Error_Of ("std_msgs", "String", ""),
                        "<message>:1:1: std_msgs/msg/String is a message: expected a mapping"
                        & " of its fields ({data}), found nothing"),
              Error_Of ("std_msgs", "String", ""));
      Assert (Contains (Error_Of ("std_msgs", "String", "  # no message" & ASCII.LF),
                        "found nothing"), "comment only");
      Assert (Contains (Error_Of ("std_msgs", "String", "null"), "found 'null'"), "null");
      Assert (Contains (Error_Of ("std_msgs", "String", "[x]"), "expected a mapping"),
              "sequence");
      Assert (RCL.YAML.Messages.From_YAML (Get_Message_Support ("std_msgs", "String"), "{}")
                ("data").Get_String = "", "'{}' is the default message");
   end Messages_From_YAML;

   procedure Mangling (Unused : in out Fixture) is
      use RCL.Graph.Queries;
      K : Name_Kind;
      N : Unbounded_String;
   begin
      Demangle_Topic ("rt/ns/chatter", K, N);
      Assert (K = Topic and then N = "/ns/chatter", "topic");
      Demangle_Topic ("rq/add_two_intsRequest", K, N);
      Assert (K = Request and then N = "/add_two_ints", "request");
      Demangle_Topic ("rr/robot/getReply", K, N);
      Assert (K = Reply and then N = "/robot/get", "reply");
      Demangle_Topic ("ros_discovery_info", K, N);
      Assert (K = Other, "not a ROS name");
      Demangle_Topic ("rq/Request", K, N);
      Assert (K = Other, "no service name");
      Assert (Demangle_Type ("std_msgs::msg::dds_::String_") = "std_msgs/msg/String", "msg");
      Assert (Demangle_Type ("example_interfaces::srv::dds_::AddTwoInts_Request_")
              = "example_interfaces/srv/AddTwoInts", "srv request");
      Assert (Demangle_Type ("example_interfaces::srv::dds_::AddTwoInts_Response_")
              = "example_interfaces/srv/AddTwoInts", "srv response");
      Assert (Demangle_Type ("plain") = "plain", "other types unchanged");
      Assert (Mangle_Type ("geometry_msgs/msg/Twist") = "geometry_msgs::msg::dds_::Twist_",
              "mangle");
   end Mangling;

   procedure Discovery_Info (Unused : in out Fixture) is
      use Ada.Streams;
      use RCL.Graph.Queries;

      function Build (Gid_Size : Stream_Element_Offset) return Stream_Element_Array is
         --  One participant, one node "/ns" "n" with one reader and no
         --  writer, little-endian.
         Data : Stream_Element_Array (1 .. 4 + Gid_Size + 4 + 4 + 4 + 4 + 2 + 2 + 4
                                      + Gid_Size + 4) := [others => 0];
         Pos  : Stream_Element_Offset := 5;
         procedure Put32 (V : Stream_Element) is
         begin
            Data (Pos) := V;
            Pos := Pos + 4;
         end Put32;
      begin
         Data (2) := 1;
         Data (5) := 16#AA#;             --  participant gid
         Pos := 5 + Gid_Size;
         Put32 (1);                      --  one node
         Put32 (4);                      --  "/ns" + NUL
         Data (Pos .. Pos + 3) := [Character'Pos ('/'), Character'Pos ('n'),
                                   Character'Pos ('s'), 0];
         Pos := Pos + 4;
         Put32 (2);                      --  "n" + NUL
         Data (Pos .. Pos + 1) := [Character'Pos ('n'), 0];
         Pos := Pos + 4;                 --  two bytes and padding
         Put32 (1);                      --  one reader gid
         Data (Pos) := 16#BB#;
         Pos := Pos + Gid_Size;
         Put32 (0);                      --  no writer
         return Data (1 .. Pos - 1);
      end Build;

      Data : constant Stream_Element_Array := Build (24);
   begin
      for Size in Stream_Element_Offset range 16 .. 24 loop
         if Size in 16 | 24 then
            declare
               P : constant Participant_Info := Decode_Participant_Info (Build (Size));
               Layout : constant String := Size'Image & "-byte gids";
            begin
               Assert (P.Count = 1 and then P.Participant (1) = 16#AA#, "one node" & Layout);
               Assert (P.Nodes (1).Id.Name = "n" and then P.Nodes (1).Id.Namespace = "/ns",
                       "names" & Layout);
               Assert (Contains (To_String (P.Nodes (1).Readers), "bb.00"),
                       "reader gid" & Layout);
               Assert (Length (P.Nodes (1).Writers) = 0, "no writer" & Layout);
            end;
         end if;
      end loop;
      declare
         function Truncated_Error return String is
         begin
            declare
               P : constant Participant_Info := Decode_Participant_Info (Data (1 .. 40));
               pragma Unreferenced (P);
            begin
               return "";
            end;
         exception
            when E : ROS_Exception =>
               return Ada.Exceptions.Exception_Message (E);
         end Truncated_Error;
      begin
         Assert (Contains (Truncated_Error, "byte"),
                 "truncated sample: error naming a byte offset: " & Truncated_Error);
      end;
      Assert (RCL.DDS.Image (RCL.DDS.Null_GUID)'Length = 47, "GUID image length");
   end Discovery_Info;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("yaml: block and flow structures", Block_Structures'Access));
      Result.Add_Test (Caller.Create ("yaml: scalar resolution", Classification'Access));
      Result.Add_Test (Caller.Create ("yaml: errors with positions", Errors'Access));
      Result.Add_Test (Caller.Create ("yaml: hostile input", Hostile_Input'Access));
      Result.Add_Test (Caller.Create ("yaml: messages from YAML", Messages_From_YAML'Access));
      Result.Add_Test (Caller.Create ("graph: name mangling", Mangling'Access));
      Result.Add_Test (Caller.Create ("graph: ros_discovery_info decoding",
                                      Discovery_Info'Access));
      return Result;
   end Suite;

end RCL.YAML.Tests;
