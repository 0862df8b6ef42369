--  Node parameters as in ROS 2: declared with a type (that of their
--  default), read, set with validation (read-only flag, type check, the
--  node's validation callback giving a reason), listed and described; the
--  node's services ~/get_parameters, ~/get_parameter_types,
--  ~/set_parameters, ~/set_parameters_atomically, ~/describe_parameters,
--  ~/list_parameters and the topic /parameter_events, so that ROS 2 tools
--  ("ros2 param", "rclada param") read and set them.
--
--  Initial values override the defaults at declaration, from the command
--  line ("--ros-args -p rate:=20 --params-file params.yaml", read by
--  Load_Arguments) or from Load_File: a YAML file in the ROS 2 format
--
--     talker:                     # node name, "/ns/talker" or "/**"
--       ros__parameters:
--         rate: 20                # nested maps give "a.b" names
--         gains: [1.0, 2.5]
--
--  Example:
--     Parameters.Declare_Parameter (Node, "rate", To_Value (10), "publish rate (Hz)");
--     Parameters.On_Set (Node, Check'Access);  --  "" accepts, else a reason
--     Parameters.Serve (Node);                 --  the services, then spin
--     Rate := Parameters.Get (Node, "rate").Int;
--
--  Parameters live per fully qualified node name for the whole process.
--  Not supported: dynamic typing, parameter ranges (descriptors report
--  none), undeclared-parameter acceptance.
with Ada.Containers.Vectors;
with Interfaces;
with Ada.Strings.Unbounded;
with ROSIDL.Dynamic;
with RCL.Nodes;
with RCL.YAML;

package RCL.Parameters is

   use Ada.Strings.Unbounded;

   Parameter_Error : exception;
   --  Undeclared parameter, wrong type, rejected value: the message says
   --  which parameter and why.

   type Parameter_Type is
     (Not_Set, Bool_Type, Integer_Type, Double_Type, String_Type, Byte_Array_Type,
      Bool_Array_Type, Integer_Array_Type, Double_Array_Type, String_Array_Type);
   --  rcl_interfaces/ParameterType: Parameter_Type'Pos is the ROS value.

   function Type_Image (T : Parameter_Type) return String;
   --  "integer", "string array"... as ros2 param describe prints them.

   package Byte_Vectors is new Ada.Containers.Vectors (Positive, Interfaces.Unsigned_8,
                                                       Interfaces."=");
   package Bool_Vectors is new Ada.Containers.Vectors (Positive, Boolean);
   package Integer_Vectors is new Ada.Containers.Vectors (Positive, Long_Long_Integer);
   package Double_Vectors is new Ada.Containers.Vectors (Positive, Long_Float);
   package Text_Vectors is new Ada.Containers.Vectors (Positive, Unbounded_String);

   type Value is record
      Kind    : Parameter_Type := Not_Set;
      Bool    : Boolean := False;
      Int     : Long_Long_Integer := 0;
      Double  : Long_Float := 0.0;
      Text    : Unbounded_String;
      Bytes   : Byte_Vectors.Vector;
      Bools   : Bool_Vectors.Vector;
      Ints    : Integer_Vectors.Vector;
      Doubles : Double_Vectors.Vector;
      Texts   : Text_Vectors.Vector;
   end record;
   --  Only the component(s) of Kind are meaningful.

   function To_Value (B : Boolean) return Value;
   function To_Value (I : Long_Long_Integer) return Value;
   function To_Value (D : Long_Float) return Value;
   function To_Value (S : String) return Value;

   function Image (V : Value) return String;
   --  As "ros2 param get" shows the value: "10", "2.5", "True", "text",
   --  "[1, 2]", "['a', 'b']".

   function YAML_Image (V : Value) return String;
   --  V as a YAML flow value that Parse reads back as V: "true", "10",
   --  "2.5", "'it''s'", "[1, 2]" (strings always quoted: single quotes,
   --  double quotes with escapes when they hold a line break or other
   --  special characters; see ROSIDL.YAML_Strings.Quoted).

   function From_YAML (From : RCL.YAML.Document; N : RCL.YAML.Node) return Value;
   --  A scalar (bool, integer, double, string) or a sequence of one kind
   --  (integers and doubles mixed make a double array). RCL.YAML.Parse_Error
   --  with the position otherwise.

   function Parse (Text : String; Source : String := "<value>") return Value;
   --  A value written in YAML ("20", "[1, 2]", "'20'" is a string).

   procedure Put_Parameter_Value (Ref : ROSIDL.Dynamic.Field_Ref; V : Value);
   function Get_Parameter_Value (Ref : ROSIDL.Dynamic.Field_Ref) return Value;
   --  To / from a field of type rcl_interfaces/ParameterValue (for tools
   --  calling the parameter services). Parameter_Error on an unknown type.

   --  Declaring, reading, setting ------------------------------------------

   procedure Declare_Parameter
     (Node        : RCL.Nodes.Node'Class;
      Name        : String;
      Default     : Value;
      Description : String := "";
      Read_Only   : Boolean := False)
     with Pre => Default.Kind /= Not_Set;
   --  The type is that of Default; an override of another type, or one that the
   --  node's On_Set check (if already given) rejects, raises Parameter_Error
   --  naming its source. Parameter_Error when already declared or Name is empty.

   function Has_Parameter (Node : RCL.Nodes.Node'Class; Name : String) return Boolean;

   function Get (Node : RCL.Nodes.Node'Class; Name : String) return Value;
   --  Parameter_Error when not declared.

   type Validator is access function (Name : String; New_Value : Value) return String;
   --  "" accepts New_Value; anything else is the reason for rejecting it.

   procedure On_Set
     (Node  : RCL.Nodes.Node'Class;
      Check : not null access function (Name : String; New_Value : Value) return String);
   --  The node's validation callback (replaces the previous one). Check may
   --  be nested in the main subprogram: it must stay callable as long as
   --  parameters of the node may be set.

   procedure Set (Node : RCL.Nodes.Node'Class; Name : String; New_Value : Value);
   --  Parameter_Error with the reason when rejected.

   function Try_Set (Node_Name, Name : String; New_Value : Value) return String;
   --  Node_Name fully qualified. "" when set, else the reason (not
   --  declared, read-only, wrong type, rejected by the validator).

   type Assignment is record
      Name      : Unbounded_String;
      New_Value : Value;
   end record;

   type Assignment_Array is array (Positive range <>) of Assignment;

   function Try_Set_Atomically (Node_Name : String; Values : Assignment_Array) return String;
   --  All or none.

   function Names (Node_Name : String) return Text_Vectors.Vector;
   --  Sorted.

   type Descriptor is record
      Name        : Unbounded_String;
      Kind        : Parameter_Type := Not_Set;
      Description : Unbounded_String;
      Read_Only   : Boolean := False;
   end record;

   function Describe (Node_Name, Name : String) return Descriptor;
   --  Kind Not_Set when not declared.

   --  Services -----------------------------------------------------------

   procedure Serve (Node : in out RCL.Nodes.Node'Class);
   --  Offers the six parameter services of Node and publishes its changes
   --  on /parameter_events (answered while the node spins). Declares the
   --  read-only "use_sim_time" (RCL.Clocks) unless declared already.

   --  Initial values ------------------------------------------------------

   procedure Load_Arguments;
   --  Reads the process's "--ros-args ... --" section: "-p name:=value"
   --  (all nodes) and "--params-file FILE". Called by Declare_Parameter
   --  the first time. RCL.YAML.Parse_Error / Parameter_Error naming the
   --  argument or file:line:column.

   procedure Load_File (Path : String);
   --  Overrides from a parameter file (see above).

   procedure Add_Override
     (Node_Pattern, Name : String; New_Value : Value; Origin : String := "");
   --  Node_Pattern: "/**" (every node), a node name or a fully qualified
   --  name. Later overrides win. Origin says where the override was given
   --  ("p.yaml:4:11", "--ros-args -p rate"), for the errors about it.

   procedure Clear_Overrides;

end RCL.Parameters;
