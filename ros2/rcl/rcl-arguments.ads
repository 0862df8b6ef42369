--  The ROS 2 command line, as rcl reads it: everything between
--  "--ros-args" and "--" (or the end; several sections may be given) is for
--  the library, the rest for the program.
--
--     talker --ros-args -r chatter:=news -r __ns:=/robot1 -r __node:=speaker
--            -r talker:rate:=hz  --log-level debug  --log-level talker:=warn
--            -p rate:=20 --params-file params.yaml -e /robot1 --
--
--  -r/--remap [node:]from:=to   topic and service remapping ("from" and
--                               "to" expanded like names of the node;
--                               rostopic:// and rosservice:// prefixes
--                               restrict a rule to topics or services),
--                               __node:=name, __ns:=/namespace
--  --log-level [logger:=]level  debug, info, warn, error, fatal
--  -e/--enclave /path           the security enclave (participant USER_DATA)
--  -p/--param [node:]name:=value, --params-file FILE   (read by
--                               RCL.Parameters; "node:" for that node only)
--  --enable/--disable-rosout-logs, --enable/--disable-stdout-logs
--
--  Anything else after --ros-args is an Argument_Error naming it: nothing
--  is silently skipped. The process's arguments are read by the first node
--  (RCL.Nodes.Init calls Load).
with Ada.Containers.Indefinite_Vectors;
with RCL.Logging;

package RCL.Arguments is

   Argument_Error : exception;
   --  The message names the argument and its position:
   --  "--ros-args: unknown argument '--foo' (argument 3)".

   package String_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);
   subtype Argument_List is String_Vectors.Vector;

   procedure Load;
   --  Parses the process's command line once (later calls do nothing).

   procedure Parse (Arguments : Argument_List);
   --  Parses Arguments (as Ada.Command_Line gives them, without the program
   --  name) and replaces what Load or an earlier Parse found. For tests and
   --  programs that build their own argument list.

   function Loaded return Boolean;

   --  What the command line says -------------------------------------------

   function Node_Name (Original : String) return String;
   --  The name a node created as Original gets ("__node" rules; Original
   --  when none applies).

   function Namespace (Node_Name : String; Original : String) return String;
   --  The namespace of node Node_Name (its original name) created in
   --  Original ("__ns" rules; Original when none applies).

   type Name_Kind is (Topic, Service);

   function Remap
     (Name      : String;
      Kind      : Name_Kind;
      Node_Name : String;
      Namespace : String) return String;
   --  The fully qualified Name after the first rule that matches it (rules
   --  in command-line order; node-specific rules only for Node_Name, the
   --  node's original name), or Name itself. The rule's "to" is expanded
   --  for the node (relative names get the namespace).

   function Enclave return String;
   --  "/" unless -e / --enclave said.

   procedure For_Each_Parameter_Argument
     (Process : not null access procedure (Flag, Value : String));
   --  Loads the command line (Load), then calls Process with each -p and
   --  --params-file argument and its value, in order (Flag "-p", Value
   --  "rate:=20"; Flag "--params-file", Value "p.yaml"); RCL.Parameters
   --  reads them.

   type Parameter_Override (Node_Length, Name_Length, Value_Length : Natural) is record
      Node  : String (1 .. Node_Length);
      --  "" for every node.
      Name  : String (1 .. Name_Length);
      Value : String (1 .. Value_Length);
      --  YAML text, read by RCL.Parameters.
   end record;

   function Parameter_Override_Of (Text : String) return Parameter_Override;
   --  A -p value "[node:]name:=value" split and checked (rcl's form: node
   --  and parameter names); Argument_Error saying what is wrong otherwise.
   --  Example:
   --     pragma Assert (Parameter_Override_Of ("talker:gain:=2").Node = "talker");

   function Rosout_Enabled return Boolean;
   function Stdout_Enabled return Boolean;

   procedure Apply_Log_Levels;
   --  Sets the --log-level levels (RCL.Logging); done by Load / Parse.

   function Parse_Severity (Image : String) return RCL.Logging.Severity;
   --  "debug", "INFO"...; Argument_Error otherwise.

end RCL.Arguments;
