--  QoS events of publishers and subscriptions, as rclcpp reports them:
--  deadline missed (offered / requested), incompatible QoS (offered /
--  requested, naming the policy), liveliness lost (a publisher that did
--  not assert itself within its lease) and changed (the publishers a
--  subscription hears), messages lost, and matched (counterparts found or
--  gone).
--
--  Every publisher and subscription reports an incompatible QoS as rclcpp
--  does, with a warning naming the policy:
--
--     [WARN] [...] [listener]: New publisher discovered on topic '/chatter',
--     offering incompatible QoS. No messages will be received from it. Last
--     incompatible policy: RELIABILITY_QOS_POLICY
--
--  Callbacks get every event of one publisher or subscription:
--  Example:
--     procedure On_Event (Node : in out Nodes.Node'Class; E : Events.Event) is
--     begin
--        if E.Kind in Events.Deadline_Missed then
--           Put_Line ("deadline missed on " & E.Topic.all & E.Total'Image & " times");
--        end if;
--     end On_Event;
--     Events.Watch (Node, Pub, On_Event'Access);           --  a publisher
--     Events.Watch (Node, "scan", On_Event'Access);        --  a subscription
--
--  The executor spinning the node polls the statuses (every Poll_Period)
--  and runs the callbacks in its spinning task.
with RCL.Nodes;
with RCL.Publishers;

package RCL.Events is

   Poll_Period : constant Duration := 0.1;

   type Event_Kind is
     (Deadline_Missed, Incompatible_QoS, Liveliness_Lost, Liveliness_Changed, Message_Lost,
      Matched);

   type Name_Access is access constant String;

   type Event is record
      Kind          : Event_Kind;
      Topic         : Name_Access;
      --  Fully qualified; valid during the callback.
      Publisher     : Boolean;
      --  Of a publisher (offered, lost, matched readers) or a subscription.
      Total         : Natural := 0;
      --  Deadline_Missed, Incompatible_QoS, Liveliness_Lost, Message_Lost,
      --  Matched: the cumulative count.
      Change        : Integer := 0;
      --  ... and by how much it grew since the previous event.
      Policy        : Natural := 0;
      --  Incompatible_QoS: the last incompatible DDS policy id.
      Alive         : Natural := 0;
      Not_Alive     : Natural := 0;
      --  Liveliness_Changed: publishers alive and not alive now.
      Current       : Natural := 0;
      Current_Change : Integer := 0;
      --  Matched: counterparts matched now, and the change.
   end record;

   function Policy_Name (Policy : Natural) return String;
   --  As rclcpp names them: "RELIABILITY_QOS_POLICY", "DURABILITY_QOS_POLICY",
   --  "DEADLINE_QOS_POLICY", "LIVELINESS_QOS_POLICY", "HISTORY_QOS_POLICY",
   --  "LIFESPAN_QOS_POLICY", "DESTINATION_ORDER_QOS_POLICY" (not in rmw: see
   --  RCL.QoS.Destination_Order_Policy); "UNKNOWN_QOS_POLICY" for others.

   type Callback is access procedure (Node : in out RCL.Nodes.Node'Class; E : Event);

   procedure Watch
     (Node     : in out RCL.Nodes.Node'Class;
      Pub      : RCL.Publishers.Publisher;
      On_Event : not null access procedure (Node : in out RCL.Nodes.Node'Class; E : Event));
   --  Pub must have been made by Node and live as long as it is watched
   --  (until it is finalized). On_Event may be nested in the main
   --  subprogram: it must stay callable while the node exists.

   procedure Watch
     (Node     : in out RCL.Nodes.Node'Class;
      Topic    : String;
      On_Event : not null access procedure (Node : in out RCL.Nodes.Node'Class; E : Event));
   --  The node's (first) subscription on Topic; ROS_Exception when it has
   --  none.

end RCL.Events;
