--  Allocation problem files (XML, root <mission>; not the team missions of
--  Sancta.Team.Missions): robots, tasks and OR alternatives, read into an
--  allocation problem with Euclidean costs in fixed point.
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
--  Plans nest to any depth: <and> (or <plan>) groups children that are
--  all done; <or> children are its alternatives (exactly one is done): an
--  <at>, a <task> (x, y; id optional inside an <or>), a nested <or>, or an
--  <and> of several of those (a compound alternative):
--
--     <plan>
--       <task id="t1" x="1" y="0"/>
--       <or id="survey" robots="ari,bo">         <!-- robots: whole subtree -->
--         <and> <task x="10" y="0"/> <task x="10" y="5"/> </and>
--         <or> <at x="30" y="0"/> <at x="0" y="30"/> </or>
--       </or>
--     </plan>
--
--  An <or> (or an <and> of one element) whose alternatives are all single
--  places is one task with alternative locations (the one-level model:
--  "door" above is task "door" with two locations). Other <or>s are OR
--  nodes of the problem's plan tree; their tasks without an id are named
--  after the outermost id and their position ("survey.1.2": alternative 1,
--  second task). Empty <or>s or alternatives are errors (file:line).
--
--  Per-robot cost functions: <robot ... factor="1.5" metric="manhattan"/>
--  gives that robot its own costs, nint (scale * factor * distance) with
--  the Euclidean (default) or Manhattan distance (a slow robot, one moving
--  along the axes); cost="N" still multiplies them.
--
--  Distances are nint (scale * Euclidean distance); scale defaults to 100
--  (centimetres for metres). A robot's cost multiplies its distances
--  (heterogeneous teams). Errors raise Format_Error "file:line: reason".
with Sancta.Allocation.Problems;

package Sancta.Allocation.Problem_Files is

   function Read (File : String; Scale : Long_Float := 0.0)
     return Sancta.Allocation.Problems.Problem_Access;
   --  Scale > 0 overrides the file's scale.

end Sancta.Allocation.Problem_Files;
