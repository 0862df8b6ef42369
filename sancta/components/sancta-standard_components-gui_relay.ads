--  The GUI relay (the paper's Table 1: "relays information to remote
--  GUIs"): publishes what a live view shows of an agent over DDS, in
--  sancta_msgs types, so that any team can be watched (sancta-view):
--
--     <component name="gui_relay" team="team" period="0.25">
--       <requires data="pose" as="pose" type="types.pose"/>
--       <requires data="status" as="team_status" type="types.string"/>
--     </component>
--
--  Every period:
--  * with a pose (input bound and stored): a sancta_msgs/msg/RobotState on
--    /sancta/<team>/gui/robots (pose, status, the task under way, the
--    tasks it did, its remaining tour and its cost, distance travelled);
--  * when the agent runs a team agent (a team_member or team_operator
--    component of the same agent, started before this one): a
--    sancta_msgs/msg/TeamPlan on /sancta/<team>/gui/plan (transient-local
--    depth 1): the round, the adopted plan's makespan and total cost,
--    the robots of the round and every mission task with its points, its
--    chosen alternative and its state (pending, assigned, active, done,
--    reallocated: planned now for another robot than when first planned).
--  * the same plan for RViz and Foxglove: a visualization_msgs/MarkerArray
--    on /sancta/<team>/markers (transient-local depth 1; a sphere and a
--    label per task coloured by state, a line strip per robot along its
--    tour, frame "map") and, from a robot, a nav_msgs/Path of its remaining
--    tour on /sancta/<team>/paths/<agent>.
--  Costs are straight-line lengths (the view's drawing of the tours). Both
--  inputs are optional: an operator relays the plan only.
package Sancta.Standard_Components.GUI_Relay is
   pragma Elaborate_Body;

   Robots_Topic : constant String := "gui/robots";
   Plan_Topic   : constant String := "gui/plan";
   Markers_Topic : constant String := "markers";
   Paths_Topic  : constant String := "paths";
   --  Under /sancta/<team>/.

end Sancta.Standard_Components.GUI_Relay;
