--  Pictures of a loaded configuration's wiring, as "sancta check" prints and
--  writes them.
--
--     Load ("share/config/robot.xml", Config);
--     Put (Rendering.Wiring_Table (Config));
--     Write_File ("wiring.dot", Rendering.To_Dot (Config));
package Sancta.Runtime.Configurations.Rendering is

   function Wiring_Table (This : Configuration) return String;
   --  A text table per agent: component instances (start order) and each
   --  external key with its type, its provider and its consumers.

   function To_Dot (This : Configuration) return String;
   --  A Graphviz picture: a cluster per agent, a box per enabled component,
   --  an edge per connection labelled with its key and type.

end Sancta.Runtime.Configurations.Rendering;
