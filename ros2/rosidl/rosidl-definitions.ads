--  The in-memory model of ROS 2 interface definitions: a message is a list
--  of typed fields and constants; a service is a request and a response
--  message; an action is a goal, a result and a feedback message plus the
--  derived messages ROS 2 puts on the wire.
--
--  Definitions are produced by ROSIDL.Parser, cached by ROSIDL.Interfaces
--  and never freed, so Message_Access values stay valid for the life of the
--  program.
--  Example:
--     Def : constant Message_Access :=
--       ROSIDL.Interfaces.Message ("std_msgs", "String");
--     for F of Def.Fields loop
--        Put_Line (To_String (F.Name) & " : " & Image (F.Of_Type));
--     end loop;
with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;

package ROSIDL.Definitions is

   use Ada.Strings.Unbounded;

   type Element_Kind is
     (Bool_Kind, Byte_Kind, Char_Kind,
      Float32_Kind, Float64_Kind,
      Int8_Kind, UInt8_Kind, Int16_Kind, UInt16_Kind,
      Int32_Kind, UInt32_Kind, Int64_Kind, UInt64_Kind,
      String_Kind, WString_Kind,
      Message_Kind);
   --  The type of one element of a field: a primitive, a (w)string, or a
   --  nested message.

   subtype Primitive_Kind is Element_Kind range Bool_Kind .. UInt64_Kind;
   subtype Integer_Kind is Element_Kind range Int8_Kind .. UInt64_Kind;
   subtype Float_Kind is Element_Kind range Float32_Kind .. Float64_Kind;
   subtype Text_Kind is Element_Kind range String_Kind .. WString_Kind;

   function Primitive_Size (Kind : Primitive_Kind) return Positive is
     (case Kind is
         when Bool_Kind | Byte_Kind | Char_Kind | Int8_Kind | UInt8_Kind => 1,
         when Int16_Kind | UInt16_Kind => 2,
         when Int32_Kind | UInt32_Kind | Float32_Kind => 4,
         when Int64_Kind | UInt64_Kind | Float64_Kind => 8);
   --  Size in bytes on the wire, which is also the CDR alignment.

   function Type_Name (Kind : Primitive_Kind) return String;
   --  The interface-language spelling: "bool", "uint8", "float64", ...

   type Collection_Kind is
     (Single, Fixed_Array, Bounded_Sequence, Unbounded_Sequence);
   --  T, T[N], T[<=N], T[].

   type Message_Definition;
   type Message_Access is access constant Message_Definition;

   type Field_Type is record
      Kind         : Element_Kind := Bool_Kind;
      String_Bound : Natural := 0;
      --  For String_Kind / WString_Kind: N of string<=N, 0 when unbounded.
      Nested       : Message_Access;
      --  For Message_Kind: the nested message's definition.
      Collection   : Collection_Kind := Single;
      Size         : Natural := 0;
      --  N of T[N] (Fixed_Array) or T[<=N] (Bounded_Sequence).
   end record
     with Dynamic_Predicate =>
       (Field_Type.Kind = Message_Kind) = (Field_Type.Nested /= null)
       and then (Field_Type.Collection in Fixed_Array | Bounded_Sequence)
                = (Field_Type.Size > 0)
       and then (Field_Type.Kind in Text_Kind or else Field_Type.String_Bound = 0);

   function Image (T : Field_Type) return String;
   --  The interface-language spelling: "string<=10", "geometry_msgs/Point[]",
   --  "float64[36]", "uint8[<=4]".

   package String_Vectors is new Ada.Containers.Indefinite_Vectors
     (Positive, String);

   type Source_Position is record
      File   : Unbounded_String;
      Line   : Natural := 0;
      Column : Natural := 0;
   end record;
   --  Where something was defined (for error messages); Line = 0 when built
   --  in code rather than parsed.

   function Image (P : Source_Position) return String;
   --  "file:line:column"

   type Field is record
      Name     : Unbounded_String;
      Of_Type  : Field_Type;
      Default  : String_Vectors.Vector;
      --  The default value, already validated against Of_Type, one element
      --  per array element (one for a single value, none when there is no
      --  default). Normalised: integers in decimal ("-5", "255"), floats as
      --  written but in a form Float'Value reads ("[-]D.D[eX]": "1" is
      --  "1.0", ".5" is "0.5", "1e3" is "1.0e3"; or "inf", "-inf", "nan"),
      --  booleans "true"/"false", strings unquoted with escapes resolved.
      Position : Source_Position;
   end record;

   function Has_Default (F : Field) return Boolean is
     (not F.Default.Is_Empty);

   type Constant_Definition is record
      Name     : Unbounded_String;
      Kind     : Element_Kind;
      --  A primitive or String_Kind / WString_Kind (constants are scalars).
      Value    : Unbounded_String;
      --  Validated and normalised as Field.Default.
      Position : Source_Position;
   end record;

   package Field_Vectors is new Ada.Containers.Vectors (Positive, Field);
   package Constant_Vectors is new Ada.Containers.Vectors
     (Positive, Constant_Definition);

   type Interface_Kind is (Msg, Srv, Action);
   --  The subfolder a definition comes from (and the "::msg::" part of its
   --  DDS type name).

   type Message_Definition is record
      Package_Name : Unbounded_String;
      --  "std_msgs"
      Name         : Unbounded_String;
      --  "String"; for a service part "AddTwoInts_Request", for an action
      --  part "Fibonacci_Goal", "Fibonacci_SendGoal_Request", ...
      Namespace    : Interface_Kind := Msg;
      Fields       : Field_Vectors.Vector;
      --  Never empty once built: an empty .msg gets the one field
      --  "uint8 structure_needs_at_least_one_member" as ROS 2 does.
      Constants    : Constant_Vectors.Vector;
      Position     : Source_Position;
   end record;

   function Full_Name (M : Message_Definition) return String;
   --  "std_msgs/msg/String"

   function DDS_Type_Name (M : Message_Definition) return String;
   --  "std_msgs::msg::dds_::String_"

   function Field_Index (M : Message_Definition; Name : String) return Natural;
   --  Index of the named field in M.Fields, 0 when there is none.

   function Field_Names (M : Message_Definition) return String;
   --  "a, b, c": the valid field names, for error messages.

   type Service_Definition is record
      Package_Name : Unbounded_String;
      Name         : Unbounded_String;
      Request      : Message_Access;
      Response     : Message_Access;
   end record;

   type Service_Access is access constant Service_Definition;

   type Action_Definition is record
      Package_Name : Unbounded_String;
      Name         : Unbounded_String;
      Goal, Result, Feedback : Message_Access;
      Send_Goal    : Service_Access;
      --  <Name>_SendGoal: request (goal_id, goal), response (accepted, stamp).
      Get_Result   : Service_Access;
      --  <Name>_GetResult: request (goal_id), response (status, result).
      Feedback_Message : Message_Access;
      --  <Name>_FeedbackMessage: goal_id, feedback.
   end record;

   type Action_Access is access constant Action_Definition;

   function Min_Element_Size (T : Field_Type) return Long_Long_Integer;
   --  A lower bound of the CDR size of one element of type T (a string:
   --  its length word and NUL, 5).

   function Min_Size (Def : Message_Access) return Long_Long_Integer;
   --  A lower bound (at least 1) of the CDR size of a message of type Def,
   --  used by the decoders to refuse a sequence count that the remaining
   --  bytes cannot hold: Min_Size (geometry_msgs/Point) = 24.

end ROSIDL.Definitions;
