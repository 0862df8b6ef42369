--  What the action tests and the action_churn test program share: a
--  Fibonacci action server's callbacks that accept every goal and end it
--  with the result [order], and a task spinning a node until told to stop.
--  No AUnit here: the test programs of tests/src/tools use it too.
--
--     Server.Init (Node, Support, "fib", Accept_Every_Goal'Access, On_Accepted'Access);
--     ...
--     procedure On_Accepted (Node : in out RCL.Nodes.Node'Class; Goal : Goal_Handle) is
--     begin
--        Succeed_With_Order (Support, Goal);
--     end On_Accepted;
with ROSIDL.Dynamic;
with RCL.Actions.Servers;
with RCL.Nodes;

package Action_Test_Support is

   function Accept_Every_Goal
     (Node : in out RCL.Nodes.Node'Class;
      Id   : RCL.Actions.Goal_Id;
      Goal : ROSIDL.Dynamic.Message) return RCL.Actions.Servers.Goal_Response;
   --  An On_Goal callback: Accept_And_Execute for every goal.

   procedure Succeed_With_Order
     (Support : RCL.Actions.Action_Support;
      Goal    : RCL.Actions.Servers.Goal_Handle);
   --  Ends Goal (of the Fibonacci action, Support) Succeeded, its result's
   --  sequence holding the goal's order alone.

   type Stop_Flag is new Boolean with Atomic;

   task type Spinner (Node : not null access RCL.Nodes.Node; Stop : not null access Stop_Flag);
   --  Spins Node, 0.05 s at a time, until Stop is True.
   --  Example: S : Spinner (Server_Node'Access, Stop'Access);  --  Stop : aliased Stop_Flag

end Action_Test_Support;
