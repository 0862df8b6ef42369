--  Actions: long-running goals with feedback, as ROS 2 defines them on the
--  wire (rcl_action / rclpy conventions, so that rclcpp and rclpy clients
--  and servers interoperate). Action "/fibonacci" of type
--  example_interfaces/action/Fibonacci is made of
--
--     services /fibonacci/_action/send_goal   (Fibonacci_SendGoal)
--              /fibonacci/_action/cancel_goal (action_msgs/srv/CancelGoal)
--              /fibonacci/_action/get_result  (Fibonacci_GetResult)
--     topics   /fibonacci/_action/feedback    (Fibonacci_FeedbackMessage)
--              /fibonacci/_action/status      (action_msgs/msg/GoalStatusArray,
--                                              reliable, transient local, depth 1)
--
--  Each goal is named by a random UUID chosen by the client. The server
--  side is RCL.Actions.Servers, the client side RCL.Actions.Clients.
--  Example:
--     Support : constant Action_Support :=
--       Get_Action_Support ("example_interfaces", "Fibonacci");
--     Goal : Message := Goal_Message (Support);
--     Goal ("order").As_Int32 := 10;
with ROSIDL;
with ROSIDL.Definitions;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

package RCL.Actions is

   type Goal_Id is array (1 .. 16) of ROSIDL.UInt8;
   --  unique_identifier_msgs/UUID.

   Null_Goal_Id : constant Goal_Id := [others => 0];

   function New_Goal_Id return Goal_Id;
   --  A random (version 4) UUID.

   function Image (Id : Goal_Id) return String;
   --  32 hex digits, as "ros2 action send_goal" prints ids.

   type Goal_Status is
     (Unknown, Accepted, Executing, Canceling, Succeeded, Canceled, Aborted);
   --  action_msgs/GoalStatus: Goal_Status'Pos is the ROS value.

   subtype Terminal_Status is Goal_Status range Succeeded .. Aborted;

   function Status_Image (S : Goal_Status) return String;
   --  "SUCCEEDED", "CANCELED"... as the ros2 command prints them.

   type Cancel_Code is (Error_None, Error_Rejected, Error_Unknown_Goal_Id, Error_Goal_Terminated);
   --  action_msgs/srv/CancelGoal return codes ('Pos).

   --  Type support ---------------------------------------------------------

   type Action_Support is private;

   function Get_Action_Support (Package_Name, Action_Name : String) return Action_Support;
   --  ROSIDL.Unknown_Type / Definition_Error as for messages.

   function Full_Name (Support : Action_Support) return String;
   --  "example_interfaces/action/Fibonacci"

   function Goal_Support (Support : Action_Support) return ROSIDL.Typesupport.Message_Support;
   function Result_Support (Support : Action_Support) return ROSIDL.Typesupport.Message_Support;
   function Feedback_Support (Support : Action_Support) return ROSIDL.Typesupport.Message_Support;
   function Feedback_Message_Support
     (Support : Action_Support) return ROSIDL.Typesupport.Message_Support;
   function Send_Goal_Support (Support : Action_Support) return ROSIDL.Typesupport.Service_Support;
   function Get_Result_Support
     (Support : Action_Support) return ROSIDL.Typesupport.Service_Support;

   function Cancel_Support return ROSIDL.Typesupport.Service_Support;
   --  action_msgs/srv/CancelGoal.

   function Status_Support return ROSIDL.Typesupport.Message_Support;
   --  action_msgs/msg/GoalStatusArray.

   function Goal_Message (Support : Action_Support) return ROSIDL.Dynamic.Message;
   function Result_Message (Support : Action_Support) return ROSIDL.Dynamic.Message;
   function Feedback_Message (Support : Action_Support) return ROSIDL.Dynamic.Message;
   --  Default-valued messages of the action's goal, result, feedback types.

   --  Names ------------------------------------------------------------------

   Send_Goal_Suffix  : constant String := "/_action/send_goal";
   Cancel_Suffix     : constant String := "/_action/cancel_goal";
   Get_Result_Suffix : constant String := "/_action/get_result";
   Feedback_Suffix   : constant String := "/_action/feedback";
   Status_Suffix     : constant String := "/_action/status";

private

   --  Field helpers of RCL.Actions.Servers and RCL.Actions.Clients.

   procedure Put_Id (Ref : ROSIDL.Dynamic.Field_Ref; Id : Goal_Id);
   function Get_Id (Ref : ROSIDL.Dynamic.Field_Ref) return Goal_Id;
   --  Ref: a field of type unique_identifier_msgs/UUID.

   procedure Put_Stamp (Ref : ROSIDL.Dynamic.Field_Ref; Nanoseconds : Long_Long_Integer);
   function Get_Stamp (Ref : ROSIDL.Dynamic.Field_Ref) return Long_Long_Integer;
   --  Ref: a field of type builtin_interfaces/Time.

   type Action_Support is record
      Definition : ROSIDL.Definitions.Action_Access;
   end record;

end RCL.Actions;
