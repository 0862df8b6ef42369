with RCL.Event_Watches;
with RCL.Node_Entities;

package body RCL.Events is

   function Policy_Name (Policy : Natural) return String is
     (case Policy is
         when 2      => "DURABILITY_QOS_POLICY",
         when 4      => "DEADLINE_QOS_POLICY",
         when 8      => "LIVELINESS_QOS_POLICY",
         when 11     => "RELIABILITY_QOS_POLICY",
         when 12     => "DESTINATION_ORDER_QOS_POLICY",
         when 13     => "HISTORY_QOS_POLICY",
         when 21     => "LIFESPAN_QOS_POLICY",
         when others => "UNKNOWN_QOS_POLICY");

   procedure Watch
     (Node     : in out RCL.Nodes.Node'Class;
      Pub      : RCL.Publishers.Publisher;
      On_Event : not null access procedure (Node : in out RCL.Nodes.Node'Class; E : Event))
   is
      Stored : constant Callback with Import, Address => On_Event'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
   begin
      RCL.Event_Watches.Watch_Publisher (RCL.Node_Entities.Graph_Id (Node), Pub, Stored);
   end Watch;

   procedure Watch
     (Node     : in out RCL.Nodes.Node'Class;
      Topic    : String;
      On_Event : not null access procedure (Node : in out RCL.Nodes.Node'Class; E : Event))
   is
      use type RCL.Node_Entities.Subscription_Access;
      Stored : constant Callback with Import, Address => On_Event'Address;
      FQ     : constant String := Node.Expand (Topic);
      S      : constant RCL.Node_Entities.Subscription_Access :=
        RCL.Node_Entities.Find_Subscription (Node, FQ);
   begin
      if S = null then
         raise ROS_Exception with "node " & Node.Name & " has no subscription on " & FQ;
      end if;
      RCL.Event_Watches.Watch_Subscription (RCL.Node_Entities.Graph_Id (Node), S, Stored);
   end Watch;

   --  Polling ------------------------------------------------------------------

end RCL.Events;
