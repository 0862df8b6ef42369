--  ROS 2 names: validation of node names and namespaces, expansion of
--  topic names to fully qualified names (rcl's rules), and the DDS topic
--  names derived from them.
--  Example:
--     pragma Assert (Expand_Topic_Name ("chatter", Node => "talker", Namespace => "/ns")
--                      = "/ns/chatter");
--     pragma Assert (Expand_Topic_Name ("~/status", "talker", "/ns") = "/ns/talker/status");
--     pragma Assert (DDS_Topic_Name ("/ns/chatter") = "rt/ns/chatter");
--     pragma Assert (Name_Token ("robot-1.base") = "robot_1_base");
package RCL.Names is

   Name_Error : exception;
   --  An invalid name; the message quotes the name and names the offending
   --  character and its position (1-based).

   Node_Name_Limit  : constant := 255;
   Topic_Name_Limit : constant := 247;
   Namespace_Limit  : constant := Topic_Name_Limit - 2;
   --  The longest names rmw accepts (a topic keeps 8 characters for the
   --  DDS prefixes, a namespace 2 more for the shortest name "/x" in it).

   function Node_Name_Problem (Name : String) return String;
   --  "" when Name is a valid node name (letters, digits, underscores, not
   --  starting with a digit, not empty, at most Node_Name_Limit
   --  characters), else what is wrong with it.

   procedure Validate_Node_Name (Name : String);
   --  Raises Name_Error with Node_Name_Problem.

   function Namespace_Problem (Namespace : String) return String;
   --  "" when Namespace is a valid absolute namespace ("/" or "/a/b") of at
   --  most Namespace_Limit characters.

   function Normalize_Namespace (Namespace : String) return String;
   --  "" -> "/", "ns" -> "/ns", "/ns/" -> "/ns"; then validated (Name_Error).

   function Topic_Problem (Name : String) return String;
   --  "" when Name is a valid fully qualified topic name of at most
   --  Topic_Name_Limit characters.

   function Parameter_Name_Problem (Name : String) return String;
   --  "" when Name is a valid parameter name as a command line gives it
   --  (rcl's rule: parts of letters, digits, '_' and '/' joined by single
   --  dots: "gain", "pid.p", "limits/max"), else what is wrong with it.

   function Shortened
     (Text : String; Longest : Positive := 40; Tail : Natural := 7) return String
     with Pre  => Tail + 3 < Longest,
          Post => Shortened'Result'Length <= Longest;
   --  Text, its middle replaced by "..." when it is longer than Longest
   --  characters (its last Tail characters kept): a name, an argument or a
   --  path quoted in a message leaves room for the reason within GNAT's 200
   --  characters of exception message.
   --  Example:
   --     pragma Assert (Shortened ((1 .. 100 => 'a'))'Length = 40);
   --     pragma Assert (Shortened ("/tmp/" & (1 .. 90 => 'd') & "/p.yaml", 80, 57)'Length = 80);

   function Name_Token (Text : String) return String is
     [for I in Text'Range =>
        (if Text (I) in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_' then Text (I) else '_')];
   --  Text with every character other than a letter, a digit or '_'
   --  replaced by '_', as a token of a node or topic name: "r-1.b" -> "r_1_b".

   subtype Node_Name is String
     with Dynamic_Predicate => Node_Name_Problem (Node_Name) = ""
       or else raise Name_Error with Node_Name_Problem (Node_Name);
   --  A valid node name: "talker", "robot_1".

   subtype Namespace_Name is String
     with Dynamic_Predicate => Namespace_Problem (Namespace_Name) = ""
       or else raise Name_Error with Namespace_Problem (Namespace_Name);
   --  A valid absolute namespace: "/", "/team/r1".

   subtype Topic_Name is String
     with Dynamic_Predicate => Topic_Problem (Topic_Name) = ""
       or else raise Name_Error with Topic_Problem (Topic_Name);
   --  A valid fully qualified topic name: "/ns/chatter".

   function Expand_Topic_Name
     (Name : String; Node : Node_Name; Namespace : Namespace_Name) return Topic_Name;
   --  Relative names get the namespace, "~" the node's fully qualified
   --  name, "{node}" and "{ns}" / "{namespace}" are substituted; the result
   --  is validated (Name_Error naming the offending character).

   function Fully_Qualified_Node_Name (Node : String; Namespace : String) return String;
   --  "/ns/node" ("/node" in the root namespace).

   function DDS_Topic_Name (Fully_Qualified : String) return String
     with Pre => Fully_Qualified'Length > 1
                 and then Fully_Qualified (Fully_Qualified'First) = '/';
   --  "rt" & Fully_Qualified.

end RCL.Names;
