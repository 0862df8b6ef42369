--  The Fibonacci action with generated types (RCL.Actions.Typed), both
--  sides, as rclpy's and rclcpp's Fibonacci examples:
--     typed_fibonacci server [ACTION_NAME [STEP]]     (default fibonacci 0.1)
--  offers example_interfaces/action/Fibonacci; each accepted goal of order
--  N gets one more number every STEP seconds (feedback: the sequence so
--  far) and succeeds with the N + 1 first numbers; negative orders and
--  orders above 62 are rejected; canceled goals end with the sequence so
--  far; several goals run at once.
--     typed_fibonacci client ORDER [ACTION_NAME [TIMEOUT [cancel]]]
--  sends one goal, prints every feedback and the result; exit status 1 when
--  the goal is rejected or does not succeed within TIMEOUT (default 30 s).
--  With "cancel", asks the server to cancel the goal once it is accepted
--  and prints the server's answer before the result.
with Ada.Command_Line;
with Example_Support; use Example_Support;
with RCL.Actions.Clients;
with RCL.Actions.Servers;
with RCL.Actions.Typed;
with RCL.Logging;
with RCL.Nodes;
with ROSIDL.Static.Example_Interfaces.Actions.Fibonacci;
with ROSIDL.Static.Sequences;
with Stepped_Goals;

procedure Typed_Fibonacci is

   use RCL;
   use RCL.Actions;
   use type ROSIDL.Int32;

   package CL renames Ada.Command_Line;
   package Fib renames ROSIDL.Static.Example_Interfaces.Actions.Fibonacci;
   package Fibs is new RCL.Actions.Typed (Fib.Handling);
   package Int32_Sequences renames ROSIDL.Static.Sequences.Int32_Sequences;

   function Image (S : Int32_Sequences.Sequence) return String is
      function From (I : Natural) return String is
        (if I >= S.Length then ""
         else (if I > 0 then "," else "") & ROSIDL.Int32'Image (S (I)) & From (I + 1));
   begin
      return "[" & From (0) & " ]";
   end Image;

   ------------
   -- Server --
   ------------

   type Work is record
      Goal     : Fibs.Goal_Handle;
      Order    : Natural;
      Sequence : Int32_Sequences.Sequence;
   end record;

   function On_Goal
     (Node : in out Nodes.Node'Class;
      Id   : Goal_Id;
      Item : Fib.Goal.Message) return Servers.Goal_Response is
   begin
      Logging.Info ("goal " & Image (Id) & ": order" & Item.Order'Image, Node.Logger_Name);
      return (if Item.Order in 0 .. 62 then Servers.Accept_And_Execute else Servers.Reject);
   end On_Goal;

   function Result_Of (W : Work) return Fib.Result.Message is
      Sequence : Int32_Sequences.Sequence := W.Sequence;
   begin
      Sequence.Set_Length (Natural'Min (Sequence.Length, W.Order + 1));
      return (Sequence => Sequence);
   end Result_Of;

   procedure Advance (Node : in out Nodes.Node'Class; W : in out Work; Done : out Boolean) is
      N : constant Natural := W.Sequence.Length;
   begin
      Done := True;
      if Fibs.Is_Canceling (W.Goal) then
         Fibs.Canceled (W.Goal, Result_Of (W));
         Logging.Info ("goal " & Image (Fibs.Id (W.Goal)) & " canceled", Node.Logger_Name);
      elsif N < W.Order + 1 then
         W.Sequence.Append (W.Sequence (N - 1) + W.Sequence (N - 2));
         Fibs.Publish_Feedback (W.Goal, (Sequence => W.Sequence));
         Done := False;
      else
         Fibs.Succeed (W.Goal, Result_Of (W));
         Logging.Info ("goal " & Image (Fibs.Id (W.Goal)) & " succeeded", Node.Logger_Name);
      end if;
   end Advance;

   package Running is new Stepped_Goals (Work, Advance);

   procedure On_Accepted (Node : in out Nodes.Node'Class; Handle : Fibs.Goal_Handle) is
      pragma Unreferenced (Node);
   begin
      Running.Add (Work'(Goal     => Handle,
                         Order    => Natural (Fibs.Goal_Of (Handle).Order),
                         Sequence => Int32_Sequences.To_Sequence ([0, 1])));
   end On_Accepted;

   package Fib_Server is new Fibs.Server (On_Goal, On_Accepted);

   procedure Serve is
      Node : Nodes.Node := Nodes.Init ("typed_fibonacci_server");
   begin
      Fib_Server.Init (Node, Argument (2, "fibonacci"));
      Node.Timer_Add (Duration'Value (Argument (3, "0.1")), Running.Step'Access);
      Logging.Info ("action " & Fib_Server.Name & " ready", Node.Logger_Name);
      Node.Spin;
   end Serve;

   ------------
   -- Client --
   ------------

   procedure On_Feedback
     (Node     : in out Nodes.Node'Class;
      Id       : Goal_Id;
      Progress : Fib.Feedback.Message) is
   begin
      Logging.Info ("feedback of " & Image (Id) & ": " & Image (Progress.Sequence),
                    Node.Logger_Name);
   end On_Feedback;

   procedure On_Status
     (Node   : in out Nodes.Node'Class;
      Id     : Goal_Id;
      Status : Goal_Status) is
   begin
      Logging.Info ("status of " & Image (Id) & ": " & Status_Image (Status), Node.Logger_Name);
   end On_Status;

   package Fib_Client is new Fibs.Client (On_Feedback, On_Status);

   Finished : Boolean := False with Atomic;

   task type Spinner (Node : not null access Nodes.Node);
   --  Spins the client's node (feedback) while the main task waits for
   --  the result, until Finished.
   task body Spinner is
   begin
      while not Finished loop
         Node.Spin (During => 0.05);
      end loop;
   end Spinner;

   procedure Ask is
      Node    : aliased Nodes.Node := Nodes.Init ("typed_fibonacci_client");
      Order   : constant ROSIDL.Int32 := ROSIDL.Int32'Value (Argument (2, "10"));
      Timeout : constant Duration := Duration'Value (Argument (4, "30.0"));
      Cancel  : constant Boolean :=
        (if Argument (5, "") in "" | "cancel" then Argument (5, "") = "cancel"
         else raise Constraint_Error with "typed_fibonacci client: the fifth argument is"
                    & " 'cancel' or nothing, not '" & Argument (5, "") & "'");
      Id      : Goal_Id;
      Status  : Goal_Status;
      Outcome : Fib.Result.Message;
   begin
      Fib_Client.Init (Node, Argument (3, "fibonacci"));
      Fib_Client.Wait_For_Server (Timeout);
      declare
         Feedback_Spinner : Spinner (Node'Access);
      begin
         Id := Fib_Client.Send_Goal ((Order => Order));
         Logging.Info ("goal " & Image (Id) & " accepted", Node.Logger_Name);
         if Cancel then
            Logging.Info ("cancel: " & Cancel_Code'Image (Fib_Client.Cancel_Goal (Id, Timeout)),
                          Node.Logger_Name);
         end if;
         Fib_Client.Get_Result (Id, Status, Outcome, Timeout);
         Logging.Info ("result (" & Status_Image (Status) & "): " & Image (Outcome.Sequence),
                       Node.Logger_Name);
         if Status /= Succeeded then
            CL.Set_Exit_Status (1);
         end if;
         Finished := True;
      exception
         when others =>
            Finished := True;
            raise;
      end;
   exception
      when Clients.Goal_Rejected =>
         Logging.Error ("goal of order" & Order'Image & " rejected", Node.Logger_Name);
         CL.Set_Exit_Status (1);
   end Ask;

begin
   if Argument (1, "") = "server" then
      Serve;
   elsif Argument (1, "") = "client" then
      Ask;
   else
      Logging.Error ("usage: typed_fibonacci server [NAME [STEP]]"
                     & " | client ORDER [NAME [TIMEOUT [cancel]]]");
      CL.Set_Exit_Status (2);
   end if;
exception
   when E : RCL.RCL_Timeout | RCL.ROS_Exception | Constraint_Error =>
      Fail (E, Status => 1);
end Typed_Fibonacci;
