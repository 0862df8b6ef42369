--  The switch subtree move (plan trees): choose another alternative at an
--  OR node; the tasks that become inactive leave their tours, those that
--  become active are inserted (cheapest insertion in added length, or at
--  random places). The new tours of all robots are built in a
--  Subtree_Switch record and the touched robots' costs recomputed exactly
--  (integers): the move's sum, completion and makespan are exact;
--  Apply_Switch then installs them and rebuilds only the touched robots.
--
--     D : Switch_Access := New_Switch (P);
--     Propose_Switch (P, S, G, W, Locked, D.all, Mv, Ok);
--     if Ok and then Mv.Value < Current then Apply_Switch (P, S, D.all); end if;
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Annealers.Moves; use Sancta.Allocation.Annealers.Moves;
with Sancta.Allocation.Annealers.Tours; use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Plan_Trees is

   type Subtree_Switch (Robots, Positions, Tasks, Under_Size : Positive) is record
      Task_At     : Position_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      Location_At : Position_Grid (1 .. Robots, 0 .. Positions) := [others => [others => 0]];
      Length      : Count_Array (1 .. Robots) := [others => 0];
      Changed     : Boolean_Array (1 .. Robots) := [others => False];
      Robot_Cost, Robot_Completion : Cost_Array (1 .. Robots) := [others => 0];
      --  The new tours and costs of the robots (those Changed).
      Selection   : Location_Array (1 .. Tasks) := [others => 1];
      Gone        : Boolean_Array (1 .. Tasks) := [others => False];
      Added       : Count_Array (1 .. Tasks) := [others => 0];
      Or_Node     : Natural := 0;
      New_Active  : Natural := 0;
      Under_First : Count_Array (1 .. Positions) := [others => 1];
      Under       : Count_Array (1 .. Under_Size) := [others => 0];
      --  The tasks below each OR ordinal O: Under (Under_First (O) ..
      --  Under_First (O + 1) - 1) (fixed for the run; Positions = Tasks + 1).
   end record;

   type Switch_Access is access Subtree_Switch;
   procedure Free is new Ada.Unchecked_Deallocation (Subtree_Switch, Switch_Access);

   function New_Switch (P : Problem) return Switch_Access;
   --  With the tasks below each OR ordinal of P.

   procedure Propose_Switch
     (P : Problem; S : State; G : in out Generator; W : Weights; Locked : Boolean_Array;
      D : in out Subtree_Switch; Mv : in out Move; Ok : out Boolean);
   --  Draws an OR node (not Locked) and another alternative of it, builds
   --  the new tours in D and evaluates them exactly into Mv.

   procedure Apply_Switch (P : Problem; S : in out State; D : Subtree_Switch);

end Sancta.Allocation.Annealers.Plan_Trees;
