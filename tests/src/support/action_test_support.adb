package body Action_Test_Support is

   function Accept_Every_Goal
     (Node : in out RCL.Nodes.Node'Class;
      Id   : RCL.Actions.Goal_Id;
      Goal : ROSIDL.Dynamic.Message) return RCL.Actions.Servers.Goal_Response
   is
      pragma Unreferenced (Node, Id, Goal);
   begin
      return RCL.Actions.Servers.Accept_And_Execute;
   end Accept_Every_Goal;

   procedure Succeed_With_Order
     (Support : RCL.Actions.Action_Support;
      Goal    : RCL.Actions.Servers.Goal_Handle)
   is
      Result : constant ROSIDL.Dynamic.Message := RCL.Actions.Result_Message (Support);
   begin
      Result ("sequence").Set_Int32_Array ([RCL.Actions.Servers.Goal (Goal) ("order").As_Int32]);
      RCL.Actions.Servers.Succeed (Goal, Result);
   end Succeed_With_Order;

   task body Spinner is
   begin
      while not Stop.all loop
         Node.Spin (During => 0.05);
      end loop;
   end Spinner;

end Action_Test_Support;
