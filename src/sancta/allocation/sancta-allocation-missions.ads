--  SANCTA mission files (XML): robots, tasks and OR alternatives, read into
--  an allocation problem with Euclidean costs in fixed point.
--
--     <mission scale="100">
--       <robot id="ari" x="0" y="0" return="true" cost="1"/>
--       <task id="t1" x="10" y="5"/>
--       <task id="t2" x="3" y="7" robots="ari"/>   <!-- only these robots -->
--       <or id="door">                             <!-- done at one of -->
--         <at x="1" y="2"/> <at x="3" y="4"/>
--       </or>
--       <done robot="ari" tasks="t1"/>             <!-- frozen prefix -->
--     </mission>
--
--  Distances are nint (scale * Euclidean distance); scale defaults to 100
--  (centimetres for metres). A robot's cost multiplies its distances
--  (heterogeneous teams). Errors raise Format_Error "file:line: reason".
with Sancta.Allocation.Problems;

package Sancta.Allocation.Missions is

   function Read (File : String; Scale : Long_Float := 0.0)
     return Sancta.Allocation.Problems.Problem_Access;
   --  Scale > 0 overrides the file's scale.

end Sancta.Allocation.Missions;
