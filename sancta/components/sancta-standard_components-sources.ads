--  Component "value": stores a value given in the configuration under its
--  output "output" at start, and again every "period" seconds when period
--  is positive (initial poses, parameters, test inputs).
--
--     <component name="value" type="types.pose" value="1.0 2.0 0.5">
--       <provides data="output" as="initial_pose" type="types.pose"/>
--     </component>
--
--  Options: type (types.real | types.integer | types.boolean |
--  types.string | types.pose; default types.real), value (required; a pose
--  is "x y yaw"), period (seconds, default 0: once). A value that does not
--  parse as its type makes the component fail at start (reported with its
--  name; the node goes on).
package Sancta.Standard_Components.Sources is
   pragma Elaborate_Body;
end Sancta.Standard_Components.Sources;
