--  Action clients: send goals to an action server (rclcpp, rclpy or
--  RCL.Actions.Servers), follow their feedback, cancel them, get their
--  results. Goals, results and cancel requests are synchronous calls (safe
--  from several tasks at once); feedback and the status changes of the
--  goals (the action's status topic, as rclcpp and rclpy clients follow
--  it) are delivered to callbacks by the executor spinning the node.
--  Example:
--     C : Clients.Client;
--     C.Init (Node, Get_Action_Support ("example_interfaces", "Fibonacci"),
--             "fibonacci", On_Feedback'Access, On_Status'Access);
--     C.Wait_For_Server (Timeout => 5.0);
--     Id := C.Send_Goal (Goal);                 --  Goal_Rejected if refused
--     Status := C.Status (Id);                  --  Executing, while it runs
--     C.Get_Result (Id, Status, Result);        --  waits for the end
--     Code := C.Cancel_Goal (Id);
--
--  Goal lifetime: the client follows each goal it sent (status, feedback)
--  until the goal is done for it, so that a client sending goals for ever
--  keeps a bounded set (as rclcpp drops a goal handle once its result has
--  come, and rclpy once the status topic says it ended):
--  - a goal rejected by the server is never followed;
--  - once Get_Result has returned its result (a terminal status), the goal
--    is dropped when the status topic gives it a terminal status, or
--    Status_Linger after the result if the topic does not (a server that
--    publishes no status, an array lost), or when Get_Result answers
--    Unknown (the server no longer knows it);
--  - a goal the topic said ended is dropped when a later status array no
--    longer lists it: the server has expired its result (its result
--    timeout, 15 min by default), so no result can be taken any more;
--  - Forget drops a goal at once (e.g. one whose result is never wanted,
--    or whose server is gone).
--  A goal no longer followed is as one never sent: Status answers Unknown,
--  its feedback and statuses are ignored. Get_Result and Cancel_Goal ask
--  the server whatever the client follows: Get_Result of a goal the server
--  has expired answers Unknown (and the default result), Cancel_Goal
--  Error_Unknown_Goal_Id; neither raises for that.
with ROSIDL.Dynamic;
with RCL.Nodes;

private with RCL.Clients;
private with RCL.Node_Entities;

package RCL.Actions.Clients is

   Goal_Rejected : exception;

   Forever : constant Duration := RCL.Nodes.Forever;

   Status_Linger : constant Duration := 2.0;
   --  How long a goal whose result was taken stays followed, waiting for
   --  the status topic's terminal status (see Goal lifetime above).

   type Client is tagged limited private;

   type Feedback_Callback is access procedure
     (Node     : in out RCL.Nodes.Node'Class;
      Goal     : Goal_Id;
      Feedback : ROSIDL.Dynamic.Message);

   type Status_Callback is access procedure
     (Node   : in out RCL.Nodes.Node'Class;
      Goal   : Goal_Id;
      Status : Goal_Status);

   procedure Init
     (This        : in out Client;
      Node        : in out RCL.Nodes.Node'Class;
      Support     : Action_Support;
      Name        : String;
      On_Feedback : access procedure
        (Node     : in out RCL.Nodes.Node'Class;
         Goal     : Goal_Id;
         Feedback : ROSIDL.Dynamic.Message) := null;
      On_Status   : access procedure
        (Node   : in out RCL.Nodes.Node'Class;
         Goal   : Goal_Id;
         Status : Goal_Status) := null);
   --  Name is expanded like a service name. On_Feedback (if given) gets the
   --  feedback of the goals this client sent, while the node spins (the
   --  feedback of other goals is dropped undecoded). The client follows
   --  the action's status topic (<name>/_action/status, QoS
   --  RCL.QoS.Action_Status) while the node spins: On_Status (if given)
   --  gets each change of status of the goals this client sent, in the
   --  order of the server's status arrays; the statuses of other clients'
   --  goals are ignored. The topic keeps only the last array: a status
   --  the server replaced before the node spun is not seen. A status
   --  array that does not decode is logged and dropped (as any malformed
   --  sample); an entry about one of this client's goals whose status is
   --  no GoalStatus value is logged (the value, the goal) and ignored, the
   --  other entries applied.

   function Name (This : Client) return String;

   function Status (This : Client; Id : Goal_Id) return Goal_Status;
   --  The status of goal Id (sent by this client) as the status topic last
   --  gave it: Unknown until the topic names the goal, and for a goal that
   --  is not this client's, was rejected or is no longer followed (see
   --  Goal lifetime). Callable from any task.

   function Follows (This : Client; Id : Goal_Id) return Boolean;
   --  Goal Id was sent by this client and is still followed.

   function Followed_Goals (This : Client) return Natural;
   --  How many goals the client follows (the size of its goal set).

   procedure Forget (This : in out Client; Id : Goal_Id);
   --  Stop following goal Id: no more status or feedback of it; Status
   --  answers Unknown. Nothing happens for a goal not followed. The server
   --  is not told (it keeps the goal, which may still be canceled and its
   --  result taken until the server expires it).

   function Server_Available (This : Client) return Boolean;
   --  As rcl_action_server_is_available: the three services of the action
   --  are available, and the client's status subscription (and feedback
   --  subscription, when Init had an On_Feedback) has matched a writer, so
   --  that a goal sent now does not lose its first feedback (volatile) and
   --  statuses to subscriptions not matched yet. False before Init; the
   --  node of Init must still exist.

   procedure Wait_For_Server (This : Client; Timeout : Duration := Forever);
   --  Waits until Server_Available, all of it within Timeout (one
   --  deadline); RCL_Timeout naming what is missing otherwise, or at
   --  shutdown. ROS_Exception before Init.

   procedure Send_Goal
     (This     : in out Client;
      Goal     : ROSIDL.Dynamic.Message;
      Id       : out Goal_Id;
      Accepted : out Boolean;
      Timeout  : Duration := 10.0);
   --  Sends Goal (of the action's goal type) under a new random Id.

   function Send_Goal
     (This    : in out Client;
      Goal    : ROSIDL.Dynamic.Message;
      Timeout : Duration := 10.0) return Goal_Id;
   --  Goal_Rejected when the server refuses it.

   procedure Get_Result
     (This    : in out Client;
      Id      : Goal_Id;
      Status  : out Goal_Status;
      Result  : out ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever);
   --  Waits for the goal to end (RCL_Timeout after Timeout). Status Unknown
   --  (and the action's default result) when the server does not know the
   --  goal: never accepted, or its result expired. ROS_Exception when the
   --  server answers a status that is no GoalStatus value. The result may
   --  be asked again while the server keeps it; the client stops following
   --  the goal (see Goal lifetime).

   function Cancel_Goal
     (This    : in out Client;
      Id      : Goal_Id;
      Timeout : Duration := 10.0) return Cancel_Code;
   --  The server's answer; ROS_Exception when its return code is no
   --  CancelGoal code.

   function Cancel_All_Goals
     (This    : in out Client;
      Timeout : Duration := 10.0) return Cancel_Code;
   --  Every goal of the server (rclcpp's async_cancel_all_goals).

private

   type Goal_Set;
   type Goal_Set_Access is access Goal_Set;

   type Client is tagged limited record
      Support    : Action_Support;
      Send       : RCL.Clients.Client;
      Cancel     : RCL.Clients.Client;
      Results    : RCL.Clients.Client;
      Mine       : Goal_Set_Access;
      --  The goals sent and their statuses (feedback and statuses of
      --  other goals are ignored).
      Feedback   : RCL.Node_Entities.Subscription_Access;
      --  Null without On_Feedback.
      Statuses   : RCL.Node_Entities.Subscription_Access;
      --  The node's (owned by it); Server_Available asks their matches.
   end record;

end RCL.Actions.Clients;
