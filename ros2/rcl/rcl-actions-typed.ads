--  Typed action servers and clients: goals, feedback and results are the
--  generated records of an action (ROSIDL.Static.<Pkg>.Actions.<Act>.Goal,
--  .Result, .Feedback). Instantiate with the action's Handling package,
--  then a Server or Client with the callbacks:
--  Example:
--     package Fib renames ROSIDL.Static.Example_Interfaces.Actions.Fibonacci;
--     package Fibs is new RCL.Actions.Typed (Fib.Handling);
--
--     function On_Goal (Node : in out Nodes.Node'Class; Id : Actions.Goal_Id;
--                       Goal : Fib.Goal.Message) return Actions.Servers.Goal_Response is
--       (if Goal.Order < 0 then Actions.Servers.Reject
--        else Actions.Servers.Accept_And_Execute);
--     procedure On_Accepted (Node : in out Nodes.Node'Class; Goal : Fibs.Goal_Handle) is
--     begin
--        Fibs.Succeed (Goal, (Sequence => Int32_Sequences.To_Sequence ([0, 1])));
--     end On_Accepted;
--     package Fib_Server is new Fibs.Server (On_Goal, On_Accepted);
--     Fib_Server.Init (Node, "fibonacci");
--
--  The wire, the goal state machine, several goals at once, result
--  expiry, cancel handling: those of RCL.Actions.Servers and
--  RCL.Actions.Clients, which this package runs. Their messages are
--  dynamic: a typed goal, feedback or result is converted through its CDR
--  encoding (the generated codec on one side, ROSIDL.CDR on the other),
--  so the action type must be on the interface search path (the bundled
--  ones are) and the typed action path allocates (unlike typed topics and
--  services).
with ROSIDL.Static.Action_Support;
with RCL.Actions.Clients;
with RCL.Actions.Servers;
with RCL.Nodes;

generic
   with package Handling is new ROSIDL.Static.Action_Support (<>);
package RCL.Actions.Typed is

   subtype Goal is Handling.Goal_Message;
   subtype Result is Handling.Result_Message;
   subtype Feedback is Handling.Feedback_Message;

   function Support return Action_Support;
   --  The dynamic layer's support of the action (ROSIDL.Unknown_Type when
   --  it is not on the interface search path).

   ------------
   -- Server --
   ------------

   type Goal_Handle is tagged private;
   --  One goal of a typed server (copies designate the same goal).

   function Id (Handle : Goal_Handle) return Goal_Id;

   function Goal_Of (Handle : Goal_Handle) return Goal;
   --  The goal as the client sent it.

   function Status (Handle : Goal_Handle) return Goal_Status;
   function Is_Active (Handle : Goal_Handle) return Boolean;
   function Is_Canceling (Handle : Goal_Handle) return Boolean;

   procedure Execute (Handle : Goal_Handle);
   procedure Publish_Feedback (Handle : Goal_Handle; Progress : Feedback);
   procedure Succeed (Handle : Goal_Handle; Outcome : Result);
   procedure Abort_Goal (Handle : Goal_Handle; Outcome : Result);
   procedure Canceled (Handle : Goal_Handle; Outcome : Result);
   --  As the operations of RCL.Actions.Servers.Goal_Handle (callable from
   --  any task; ROS_Exception for a transition the state machine refuses).

   function Accept_Every_Cancel
     (Node   : in out RCL.Nodes.Node'Class;
      Handle : Goal_Handle) return Servers.Cancel_Response is (Servers.Accept_Cancel);

   generic
      with function On_Goal
        (Node : in out RCL.Nodes.Node'Class;
         Id   : Goal_Id;
         Item : Goal) return Servers.Goal_Response;
      with procedure On_Accepted
        (Node   : in out RCL.Nodes.Node'Class;
         Handle : Goal_Handle);
      with function On_Cancel
        (Node   : in out RCL.Nodes.Node'Class;
         Handle : Goal_Handle) return Servers.Cancel_Response is Accept_Every_Cancel;
   package Server is
      procedure Init
        (Node           : in out RCL.Nodes.Node'Class;
         Name           : String;
         Result_Timeout : Duration := Servers.Default_Result_Timeout);
      --  Offers action Name (expanded like a service name); the callbacks
      --  run in the task spinning the node. Once per instance; the
      --  instance must live as long as the node.

      function Name return String;
      function Active_Goals return Natural;
      function Kept_Goals return Natural;
      --  As Servers.Active_Goals and Kept_Goals.
   end Server;

   ------------
   -- Client --
   ------------

   procedure Ignore_Feedback
     (Node     : in out RCL.Nodes.Node'Class;
      Id       : Goal_Id;
      Progress : Feedback) is null;

   procedure Ignore_Status
     (Node   : in out RCL.Nodes.Node'Class;
      Id     : Goal_Id;
      Status : Goal_Status) is null;

   generic
      with procedure On_Feedback
        (Node     : in out RCL.Nodes.Node'Class;
         Id       : Goal_Id;
         Progress : Feedback) is Ignore_Feedback;
      with procedure On_Status
        (Node   : in out RCL.Nodes.Node'Class;
         Id     : Goal_Id;
         Status : Goal_Status) is Ignore_Status;
   package Client is
      procedure Init (Node : in out RCL.Nodes.Node'Class; Name : String);
      --  On_Feedback gets the feedback of the goals sent by this client,
      --  On_Status each change of their status on the action's status
      --  topic, while the node spins (as Clients.Init). Once per instance;
      --  the instance must live as long as the node.

      function Status (Id : Goal_Id) return Goal_Status;
      --  As Clients.Status: the goal's status as the status topic last
      --  gave it (Unknown before, and once the goal is no longer followed).

      function Follows (Id : Goal_Id) return Boolean;
      function Followed_Goals return Natural;
      procedure Forget (Id : Goal_Id);
      --  As Clients.Follows, Followed_Goals and Forget (the goal lifetime of
      --  RCL.Actions.Clients).

      function Server_Available return Boolean;
      procedure Wait_For_Server (Timeout : Duration := Clients.Forever);
      --  As Clients.Server_Available and Wait_For_Server: the services,
      --  status and feedback topics matched (RCL_Timeout when not all
      --  within Timeout).

      function Send_Goal (Item : Goal; Timeout : Duration := 10.0) return Goal_Id;
      --  Clients.Goal_Rejected when the server refuses it.

      procedure Get_Result
        (Id      : Goal_Id;
         Status  : out Goal_Status;
         Outcome : out Result;
         Timeout : Duration := Clients.Forever);
      --  Waits for the goal to end (RCL_Timeout after Timeout); Status
      --  Unknown when the server does not know the goal (Outcome is then
      --  the default result). ROS_Exception when the server answers a
      --  status that is no GoalStatus value.

      function Cancel_Goal (Id : Goal_Id; Timeout : Duration := 10.0) return Cancel_Code;
      --  ROS_Exception when the server's return code is no CancelGoal code.
   end Client;

private

   type Goal_Handle is tagged record
      Dynamic : Servers.Goal_Handle;
   end record;

end RCL.Actions.Typed;
