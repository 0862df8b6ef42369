--  Text renderings of interface definitions, as "ros2 interface show" prints
--  them: one line per constant and field in file order, default values and
--  constant values in interface-language syntax, and the definitions of
--  nested messages expanded below their field, indented by one tab per level.
--  Comments are not kept by the parser, so they are not shown; the member
--  ROS 2 adds to an empty message is not shown either.
--  Example:
--     Put (Show (ROSIDL.Interfaces.Message ("geometry_msgs", "Pose").all));
--     --  Point position
--     --  <TAB>float64 x
--     --  ...
package ROSIDL.Definitions.Rendering is

   function Show (M : Message_Definition; Expand : Boolean := True) return String;
   --  M's lines, each ending with LF. Nested types in M's own package are
   --  written without their package ("Point"), others with it
   --  ("std_msgs/Header"). Expand: show nested definitions.

   function Show (S : Service_Definition; Expand : Boolean := True) return String;
   --  Request, a line "---", response.

   function Show (A : Action_Definition; Expand : Boolean := True) return String;
   --  Goal, "---", result, "---", feedback.

   function Value_Image (Kind : Element_Kind; Value : String) return String;
   --  A normalised value (Field.Default element, Constant_Definition.Value)
   --  in interface-language syntax: strings in double quotes with '"' and
   --  '\' escaped, others as they are.

end ROSIDL.Definitions.Rendering;
