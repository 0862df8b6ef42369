--  SANCTA mission files (XML): robots, tasks and OR alternatives, read into
--  an allocation problem with Euclidean costs in fixed point.
--
--     <mission scale="100">
--       <robot id="ari" x="0" y="0" return="true" cost="1"/>
--       <robot id="bo" x="5" y="0" end_x="9" end_y="9"/>  <!-- own end depot -->
--       <task id="t1" x="10" y="5"/>
--       <task id="t2" x="3" y="7" robots="ari"/>   <!-- only these robots -->
--       <or id="door">                             <!-- done at one of -->
--         <at x="1" y="2"/> <at x="3" y="4"/>
--       </or>
--       <done robot="ari" tasks="t1"/>             <!-- frozen prefix -->
--     </mission>
--
--  Plans may nest: <and> (or <plan>) groups children that are all done;
--  an <or> alternative may be an <at>, a <task> (x, y), a nested <or>
--  (its alternatives join the outer ones) or an <and> holding one of those:
--
--     <plan>
--       <task id="t1" x="1" y="0"/>
--       <and>
--         <or id="door" robots="ari">
--           <or> <at x="100" y="100"/> <task x="50" y="50"/> </or>
--           <and> <task x="2" y="0"/> </and>
--         </or>
--       </and>
--     </plan>
--
--  Partial (known limit): such trees are normalised to the problem's
--  one-level model (each outermost <or> is one task with alternative
--  locations). An <or> alternative made of several tasks (an <and> with two
--  leaves: a compound task) is refused with a positioned error, as the
--  model, the annealer's switch move and the exact solver do not handle
--  OR nodes over task sets yet.
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
