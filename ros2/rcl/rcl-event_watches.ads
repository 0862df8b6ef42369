--  The endpoints whose QoS events are watched (RCL.Events): every
--  publisher (incompatible QoS is always reported), and the endpoints a
--  program watches with a callback; polled by the executors. A private
--  child of RCL: RCL.Events, RCL.Publishers and the executors use it.
with RCL.Events;
with RCL.Graph;
with RCL.Node_Entities;
with RCL.Nodes;
with RCL.Publishers;

private package RCL.Event_Watches is

   procedure Register_Publisher (Pub : RCL.Publishers.Publisher; Node : RCL.Graph.Node_Id);
   procedure Unregister_Publisher (Pub : RCL.Publishers.Publisher);
   --  By RCL.Publishers: every publisher reports incompatible QoS.

   procedure Watch_Publisher
     (Node     : RCL.Graph.Node_Id;
      Pub      : RCL.Publishers.Publisher;
      On_Event : RCL.Events.Callback);
   procedure Watch_Subscription
     (Node     : RCL.Graph.Node_Id;
      Sub      : not null RCL.Node_Entities.Subscription_Access;
      On_Event : RCL.Events.Callback);
   --  RCL.Events.Watch: On_Event gets the endpoint's events from now on.

   procedure Poll (Node : in out RCL.Nodes.Node'Class);
   --  By the executors, at most every RCL.Events.Poll_Period per node:
   --  warnings logged, callbacks run in the calling task.

end RCL.Event_Watches;
