--  An action server, as rclpy's and rclcpp's Fibonacci examples: offers
--  example_interfaces/action/Fibonacci as "fibonacci"; each accepted goal
--  of order N gets one more number every STEP seconds (feedback: the
--  sequence so far) and succeeds with the N + 1 first Fibonacci numbers.
--  Negative orders are rejected; canceled goals end with the sequence so
--  far. Several goals run at once.
--     fibonacci_server [ACTION_NAME [STEP]]     (default fibonacci 0.1)
with Example_Support; use Example_Support;
with ROSIDL.Dynamic;
with RCL.Actions.Servers;
with RCL.Arguments;
with RCL.Logging;
with RCL.Nodes;
with Stepped_Goals;

procedure Fibonacci_Server is

   use RCL;
   use RCL.Actions;
   use RCL.Actions.Servers;
   use type ROSIDL.Int32;

   Support : constant Action_Support := Get_Action_Support ("example_interfaces", "Fibonacci");

   type Work is record
      Goal     : Goal_Handle;
      Order    : Natural;
      Sequence : ROSIDL.Dynamic.Int32_Array (1 .. 64);
      Length   : Natural;
   end record;

   function On_Goal
     (Node : in out Nodes.Node'Class;
      Id   : Goal_Id;
      Goal : ROSIDL.Dynamic.Message) return Goal_Response
   is
      Order : constant ROSIDL.Int32 := Goal ("order").As_Int32.Element.all;
   begin
      Logging.Info ("goal " & Image (Id) & ": order" & Order'Image, Node.Logger_Name);
      return (if Order in 0 .. 62 then Accept_And_Execute else Reject);
   end On_Goal;

   function Result_Of (W : Work) return ROSIDL.Dynamic.Message is
      Result : constant ROSIDL.Dynamic.Message := Result_Message (Support);
   begin
      Result ("sequence").Set_Int32_Array (W.Sequence (1 .. Natural'Min (W.Length, W.Order + 1)));
      return Result;
   end Result_Of;

   --  One more number for W's goal (feedback), or its end (Done).
   procedure Advance (Node : in out Nodes.Node'Class; W : in out Work; Done : out Boolean) is
   begin
      Done := True;
      if Is_Canceling (W.Goal) then
         Canceled (W.Goal, Result_Of (W));
         Logging.Info ("goal " & Image (Id (W.Goal)) & " canceled", Node.Logger_Name);
      elsif W.Length < W.Order + 1 then
         W.Length := W.Length + 1;
         W.Sequence (W.Length) := W.Sequence (W.Length - 1) + W.Sequence (W.Length - 2);
         declare
            Feedback : constant ROSIDL.Dynamic.Message := Feedback_Message (Support);
         begin
            Feedback ("sequence").Set_Int32_Array (W.Sequence (1 .. W.Length));
            Publish_Feedback (W.Goal, Feedback);
         end;
         Done := False;
      else
         Succeed (W.Goal, Result_Of (W));
         Logging.Info ("goal " & Image (Id (W.Goal)) & " succeeded", Node.Logger_Name);
      end if;
   end Advance;

   package Running is new Stepped_Goals (Work, Advance);

   procedure On_Accepted (Node : in out Nodes.Node'Class; Goal : Goal_Handle) is
      pragma Unreferenced (Node);
   begin
      Running.Add
        (Work'(Goal     => Goal,
               Order    => Natural (Servers.Goal (Goal) ("order").As_Int32.Element.all),
               Sequence => [1 => 0, 2 => 1, others => 0],
               Length   => 2));
   end On_Accepted;

begin
   RCL.Arguments.Load;
   declare
      Name   : constant String := Argument (1, "fibonacci");
      Period : constant Duration := Duration'Value (Argument (2, "0.1"));
      Node   : Nodes.Node := Nodes.Init ("fibonacci_server");
      Server : Servers.Server;
   begin
      Server.Init (Node, Support, Name, On_Goal'Access, On_Accepted'Access);
      Node.Timer_Add (Period, Running.Step'Access);
      Logging.Info ("action " & Server.Name & " ready", Node.Logger_Name);
      Node.Spin;
   end;
exception
   when E : RCL.Arguments.Argument_Error | Constraint_Error =>
      Fail (E);
end Fibonacci_Server;
