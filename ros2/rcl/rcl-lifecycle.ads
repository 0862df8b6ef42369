--  Lifecycle (managed) nodes: the ROS 2 state machine of rclcpp_lifecycle
--  on a node, with its services and events, so that "ros2 lifecycle" (and
--  "rclada lifecycle") drive it:
--
--     unconfigured --configure--> inactive --activate--> active
--          ^    <---cleanup----     |   <--deactivate--    |
--          +------ shutdown (from each) ---> finalized <---+
--
--  Each transition runs through its transition state (configuring,
--  activating...) and the node's callback, whose answer (Success, Failure,
--  Error) decides the goal: Failure goes back, Error goes to
--  errorprocessing (On_Error: Success -> unconfigured, else finalized).
--  Services ~/change_state, ~/get_state, ~/get_available_states,
--  ~/get_available_transitions, ~/get_transition_graph (lifecycle_msgs)
--  and the topic ~/transition_event (lifecycle_msgs/TransitionEvent, one
--  event per step).
--  Example:
--     function On_Activate (Node : in out Nodes.Node'Class; Previous : State_Id)
--       return Callback_Return is (Success);
--     ...
--     Node    : Nodes.Node := Nodes.Init ("lc_talker");
--     Managed : Lifecycle.Managed_Node;
--     Managed.Init (Node, On_Activate => On_Activate'Access);
--     Pub : Lifecycle.Lifecycle_Publisher := Managed.Publish (Support, "chatter");
--     Pub.Publish (Msg);   --  dropped unless the node is active
--     Node.Spin;
--
--  A null callback answers Success.
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;

package RCL.Lifecycle is

   type State_Id is
     (Unknown, Unconfigured, Inactive, Active, Finalized,
      Configuring, Cleaning_Up, Shutting_Down, Activating, Deactivating, Error_Processing);

   function Id (S : State_Id) return Natural;
   --  lifecycle_msgs/State id: 0 .. 4, then 10 .. 15.

   function Label (S : State_Id) return String;
   --  "unconfigured", "cleaningup"... as ROS 2 names them.

   subtype Primary_State is State_Id range Unconfigured .. Finalized;

   type Transition_Id is (Configure, Cleanup, Activate, Deactivate, Shutdown);
   --  The transitions a user requests (lifecycle_msgs/Transition ids 1 .. 4,
   --  shutdown 5, 6 or 7 from unconfigured, inactive or active).

   function Label (T : Transition_Id) return String;

   type Callback_Return is (Success, Failure, Error);
   --  lifecycle_msgs/Transition TRANSITION_CALLBACK_SUCCESS (97) ...

   type Transition_Callback is access function
     (Node     : in out RCL.Nodes.Node'Class;
      Previous : State_Id) return Callback_Return;
   --  Previous: the primary state the transition started from.

   type Managed_Node is tagged limited private;

   procedure Init
     (This          : in out Managed_Node;
      Node          : in out RCL.Nodes.Node'Class;
      On_Configure  : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Activate   : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Deactivate : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Cleanup    : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Shutdown   : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Error      : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null);
   --  Node becomes managed, in state Unconfigured. The callbacks may be
   --  nested in the main subprogram (they must stay callable while the node
   --  exists).

   function Current_State (This : Managed_Node) return State_Id;

   function Trigger (This : in out Managed_Node; Transition : Transition_Id) return Boolean;
   --  Runs Transition from the current state (as ~/change_state does):
   --  False when not allowed here or when the callback did not answer
   --  Success. Not from within a transition callback.

   --  Lifecycle publishers ------------------------------------------------

   type Lifecycle_Publisher is tagged limited private;
   --  Publishes only while its node is active (else drops the message, with
   --  one warning per inactive period, as rclcpp).

   function Publish
     (This    : in out Managed_Node'Class;
      Support : ROSIDL.Typesupport.Message_Support;
      Topic   : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Default) return Lifecycle_Publisher;

   procedure Publish (This : in out Lifecycle_Publisher; Msg : ROSIDL.Dynamic.Message);

   function Is_Activated (This : Lifecycle_Publisher) return Boolean;

private

   type Callbacks is record
      On_Configure, On_Cleanup, On_Activate, On_Deactivate, On_Shutdown, On_Error :
        Transition_Callback;
   end record;

   type Machine;
   type Machine_Access is access Machine;

   type Managed_Node is tagged limited record
      M : Machine_Access;
   end record;

   type Publisher_Access is access RCL.Publishers.Publisher;

   type Lifecycle_Publisher is tagged limited record
      M      : Machine_Access;
      Pub    : Publisher_Access;
      Warned : Boolean := False;
   end record;

end RCL.Lifecycle;
