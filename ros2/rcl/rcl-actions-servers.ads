--  Action servers: accept or reject goals, publish their feedback and
--  status, answer cancel requests and deliver results, with rcl_action's
--  goal state machine:
--
--     accepted --execute--> executing --succeed/abort--> succeeded/aborted
--        |                      |
--        +----cancel----> canceling --succeed/abort/canceled--> ...
--
--  Several goals may be active at once. Results are kept for Result_Timeout
--  after the goal ended (a get_result request for a goal still running is
--  answered when it ends), as rcl_action's result_timeout (15 min by
--  default); then the goal is forgotten: dropped from the server (within a
--  tenth of the timeout, at most 10 s, while the node spins) and from the
--  status array (published again without it), get_result answers it
--  UNKNOWN, cancel_goal ERROR_UNKNOWN_GOAL_ID, Goal_Handle.Status Unknown.
--  A server answering goals at a steady rate thus keeps a bounded number
--  of them (Kept_Goals): those active and those ended within the timeout.
--  Example:
--     function On_Goal (Node : in out Nodes.Node'Class; Id : Goal_Id;
--                       Goal : Message) return Goal_Response is
--       (if Goal ("order").As_Int32.Element.all < 0 then Reject
--        else Accept_And_Execute);
--     procedure On_Accepted (Node : in out Nodes.Node'Class; Goal : Goal_Handle) is
--     begin
--        Pending.Add (Goal);   --  e.g. worked on by a timer or a task
--     end On_Accepted;
--     ...
--     Server.Init (Node, Get_Action_Support ("example_interfaces", "Fibonacci"),
--                  "fibonacci", On_Goal'Access, On_Accepted'Access);
--     --  later, from any task:
--     Goal.Publish_Feedback (Feedback);
--     Goal.Succeed (Result);
--
--  The callbacks run in the task spinning the node; the Goal_Handle
--  operations may be called from any task.
with ROSIDL.Dynamic;
with RCL.Nodes;

package RCL.Actions.Servers is

   type Goal_Response is (Reject, Accept_And_Execute, Accept_And_Defer);
   --  Accept_And_Defer: the goal stays Accepted until Execute.

   type Cancel_Response is (Reject_Cancel, Accept_Cancel);

   type Goal_Handle is tagged private;
   --  One goal of a server (copies designate the same goal).

   type Server is tagged limited private;

   Default_Result_Timeout : constant Duration := 900.0;
   --  rcl_action's default (15 minutes).

   procedure Init
     (This        : in out Server;
      Node        : in out RCL.Nodes.Node'Class;
      Support     : Action_Support;
      Name        : String;
      On_Goal     : not null access function
        (Node : in out RCL.Nodes.Node'Class;
         Id   : Goal_Id;
         Goal : ROSIDL.Dynamic.Message) return Goal_Response;
      On_Accepted : not null access procedure
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Goal_Handle);
      On_Cancel   : access function
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Goal_Handle) return Cancel_Response := null;
      Result_Timeout : Duration := Default_Result_Timeout)
     with Pre => Result_Timeout >= 0.0;
   --  Offers action Name (expanded like a service name). On_Cancel null
   --  accepts every cancel request. The callbacks must stay callable as
   --  long as the node exists (they may be nested in the main subprogram).
   --  Results expire Result_Timeout after their goal ended (on the steady
   --  clock); 0.0 keeps them only for the get_result requests already
   --  waiting when the goal ends.

   function Name (This : Server) return String;
   --  The fully qualified action name.

   function Active_Goals (This : Server) return Natural;
   --  Goals accepted, executing or canceling.

   function Kept_Goals (This : Server) return Natural;
   --  Goals the server holds: the active ones and the ended ones not yet
   --  dropped (their results have not expired, or expired since the last
   --  drop).

   --  Goals ----------------------------------------------------------------

   function Id (Goal : Goal_Handle) return Goal_Id;

   function Goal (Goal : Goal_Handle) return ROSIDL.Dynamic.Message;
   --  The goal message, as sent by the client.

   function Status (Goal : Goal_Handle) return Goal_Status;
   --  Unknown when its result has expired.

   function Is_Active (Goal : Goal_Handle) return Boolean is
     (Status (Goal) in Accepted | Executing | Canceling);

   function Is_Canceling (Goal : Goal_Handle) return Boolean is
     (Status (Goal) = Canceling);

   procedure Execute (Goal : Goal_Handle);
   --  Accepted -> Executing (after Accept_And_Defer).

   procedure Publish_Feedback (Goal : Goal_Handle; Feedback : ROSIDL.Dynamic.Message);
   --  Feedback of the action's feedback type.

   procedure Succeed (Goal : Goal_Handle; Result : ROSIDL.Dynamic.Message);
   procedure Abort_Goal (Goal : Goal_Handle; Result : ROSIDL.Dynamic.Message);
   procedure Canceled (Goal : Goal_Handle; Result : ROSIDL.Dynamic.Message);
   --  End the goal (Canceled only from Canceling); the result goes to the
   --  clients waiting for it. ROS_Exception for a transition the state
   --  machine does not allow (naming the goal and its status).

private

   type Server_State;
   type State_Access is access Server_State;

   type Server is tagged limited record
      State : State_Access;
   end record;

   type Goal_Handle is tagged record
      State : State_Access;
      Id    : Goal_Id := Null_Goal_Id;
   end record;

end RCL.Actions.Servers;
