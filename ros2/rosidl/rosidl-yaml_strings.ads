--  Strings as YAML scalars, quoted the way PyYAML writes them (what
--  ros2 topic echo prints, what ros2 param and rosbag2 files hold), so that
--  any YAML reader gives the string back.
--  Example:
--     Put_Line (ROSIDL.YAML_Strings.Quoted ("it's"));        --  'it''s'
--     Put_Line (ROSIDL.YAML_Strings.Quoted ("two" & ASCII.LF & "lines"));
--     --  "two\nlines"
package ROSIDL.YAML_Strings is

   function Single_Quoted (Text : String) return String;
   --  Text between single quotes, each ' doubled.

   function Needs_Double_Quotes (Text : String) return Boolean;
   --  PyYAML's "special characters": anything but printable ASCII, NEL and
   --  printable Unicode (U+A0..U+D7FF, U+E000..U+FFFD but the BOM,
   --  U+10000..U+10FFFE); also invalid UTF-8, and (approximation) every
   --  line break (PyYAML folds such a string into a multi-line
   --  single-quoted scalar unless a space borders a break).

   function Double_Quoted (Text : String) return String;
   --  PyYAML's double-quoted style with allow_unicode: printable text as it
   --  is, everything else escaped (\n, \e, \N, \x7F, \u2028 as \L,
   --  \U0001F600...). Text is UTF-8; when it is not valid UTF-8, bytes from
   --  16#80# on are escaped one by one (\xC3).

   function Quoted (Text : String) return String is
     (if Needs_Double_Quotes (Text) then Double_Quoted (Text) else Single_Quoted (Text));
   --  Single-quoted when that shows Text as it is, else double-quoted.

end ROSIDL.YAML_Strings;
