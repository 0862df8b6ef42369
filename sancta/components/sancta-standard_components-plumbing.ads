--  Plumbing components, all event-driven:
--
--  "copy": input "input", output "output" (any type): stores every value
--  of its input under its output key.
--
--  "merge": any number of inputs (any data names), output "output":
--  forwards whichever input was stored last.
--
--  "switch": input "select" (types.string) names which of its other
--  inputs (any data names) is forwarded to "output"; option "initial"
--  (a data name, default: none until "select" is stored). On a change of
--  "select" the chosen input's current value (if any) is forwarded at once.
--
--     <component name="switch" initial="odometry">
--       <requires data="select" as="pose_source"/>
--       <requires data="odometry" as="odometric_pose"/>
--       <requires data="gps" as="gps_pose"/>
--       <provides data="output" as="pose"/>
--     </component>
package Sancta.Standard_Components.Plumbing is
   pragma Elaborate_Body;
end Sancta.Standard_Components.Plumbing;
