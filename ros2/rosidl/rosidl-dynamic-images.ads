--  Rendering of dynamic messages as "ros2 topic echo" prints them (YAML as
--  PyYAML dumps the message's ordered dictionary). Users call
--  ROSIDL.Dynamic.Image.
private package ROSIDL.Dynamic.Images is

   function Render (Root : not null Node_Access; Truncate : Natural) return String;
   --  Truncate > 0: arrays and strings longer than it are cut, ending with
   --  "..." as ros2 topic echo --truncate-length does.

   function Float_Image (X : Float64) return String;
   --  Python's repr of X as PyYAML writes it: "1.0", "0.1", "1.0e-05",
   --  ".nan", ".inf", "-.inf".

end ROSIDL.Dynamic.Images;
