--  The parser of the ROS 2 interface language: .msg, .srv and .action text
--  into the definitions of ROSIDL.Definitions, following the rules of the
--  ROS 2 tools (rosidl_adapter): names, types, bounds, constants, default
--  values, the "Header" shorthand and the one-member rule for empty
--  messages.
--
--  Nested types are resolved through a function given by the caller (the
--  cache of ROSIDL.Interfaces, by default), so the parser itself never
--  touches the file system.
--  Example:
--     Def : constant Message_Access :=
--       ROSIDL.Parser.Parse_Message
--         (Package_Name => "my_msgs", Name => "Pose2D",
--          Text         => "float64 x" & LF & "float64 y 0.5" & LF,
--          File         => "my_msgs/msg/Pose2D.msg");
--
--  Every error raises ROSIDL.Definition_Error with a message
--  "file:line:column: expected <what>, found <what>".
with ROSIDL.Definitions;

package ROSIDL.Parser is

   use ROSIDL.Definitions;

   type Resolver is access function
     (Package_Name, Name : String; Where : Source_Position)
      return Message_Access;
   --  Returns the definition of <Package_Name>/msg/<Name>, or null when no
   --  such type exists (the parser then reports "unknown type" at Where).
   --  It may raise Definition_Error itself (a malformed nested file, a
   --  recursive definition).

   function Search_Path_Resolver
     (Package_Name, Name : String; Where : Source_Position)
      return Message_Access;
   --  The default: ROSIDL.Interfaces.Message, null when it is not found.

   function Parse_Message
     (Package_Name, Name, Text : String;
      File    : String := "";
      Resolve : not null Resolver := Search_Path_Resolver'Access)
      return Message_Access;
   --  Parses the text of <Package_Name>/msg/<Name>.msg. File names the text
   --  in error messages (default "<Package_Name>/msg/<Name>.msg"). The
   --  result is allocated and never freed.

   function Parse_Service
     (Package_Name, Name, Text : String;
      File    : String := "";
      Resolve : not null Resolver := Search_Path_Resolver'Access)
      return Service_Access;
   --  Parses a .srv text: request, a line "---", response. The parts are the
   --  messages <Name>_Request and <Name>_Response (Namespace = Srv).

   function Parse_Action
     (Package_Name, Name, Text : String;
      File    : String := "";
      Resolve : not null Resolver := Search_Path_Resolver'Access)
      return Action_Access;
   --  Parses an .action text: goal, "---", result, "---", feedback, and
   --  builds the derived wire types (Namespace = Action):
   --  <Name>_SendGoal_Request (unique_identifier_msgs/UUID goal_id,
   --  <Name>_Goal goal), <Name>_SendGoal_Response (bool accepted,
   --  builtin_interfaces/Time stamp), <Name>_GetResult_Request (goal_id),
   --  <Name>_GetResult_Response (int8 status, <Name>_Result result) and
   --  <Name>_FeedbackMessage (goal_id, <Name>_Feedback feedback).

   Empty_Member_Name : constant String := "structure_needs_at_least_one_member";
   --  The uint8 field ROS 2 gives a message that has no field.

   --  Names, as the ROS 2 tools check them.

   function Is_Valid_Package_Name (Name : String) return Boolean;
   --  [a-z][a-z0-9_]*, without "__" and not ending with "_".

   function Is_Valid_Field_Name (Name : String) return Boolean
     renames Is_Valid_Package_Name;

   function Is_Valid_Type_Name (Name : String) return Boolean;
   --  [A-Z][A-Za-z0-9]*

   function Is_Valid_Constant_Name (Name : String) return Boolean;
   --  [A-Z][A-Z0-9_]*, without "__" and not ending with "_".

   function Is_Reserved_Name (Name : String) return Boolean;
   --  A Python keyword ("from", "class", "lambda", ...): the ROS 2 Python
   --  generator (rosidl_generator_py) refuses them as member names, so an
   --  interface using one cannot be built by ROS 2. Checked on field names
   --  (constants, in upper case, cannot be keywords). IDL keywords are not
   --  reserved: ROS 2 accepts them (example_interfaces/Fibonacci has a
   --  field "sequence").

end ROSIDL.Parser;
