--  Filling dynamic messages from YAML, as "ros2 topic pub" and "ros2
--  service call" read their message argument ("{a: 1, b: 2}", nested
--  mappings for nested messages, sequences for arrays). Fields not given
--  keep their default values. Shared by the rclada tool and parameters.
--  Example:
--     Msg : constant Message := From_YAML (Support, "{data: hello}");
--
--  Errors raise RCL.YAML.Parse_Error with the place and the reason:
--  "<message>:1:2: std_msgs/msg/String has no field 'dat' (fields: data)",
--  "<message>:1:5: field 'a' is int64: 'x' is not an integer",
--  "...: 300 is out of range for uint8 (0 .. 255)".
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

package RCL.YAML.Messages is

   procedure Fill (Msg : ROSIDL.Dynamic.Message; From : Document; N : Node)
     with Pre => ROSIDL.Dynamic.Is_Initialised (Msg);
   --  N: a mapping of field names to values, or null (nothing to set).
   --  Msg is modified in place (a Message designates its storage).

   function From_YAML
     (Support : ROSIDL.Typesupport.Message_Support;
      Text    : String;
      Source  : String := "<message>") return ROSIDL.Dynamic.Message;
   --  Text must be a mapping ("{}": the default message); an empty text (or
   --  only comments) is refused, as ros2 refuses a non-dictionary.

end RCL.YAML.Messages;
