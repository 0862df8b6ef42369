with Ada.Containers.Ordered_Maps;
with Ada.Containers.Vectors;
with Interfaces;
with System;
with RCL.DDS;
with RCL.Logging;
with RCL.Publisher_Writers;
with ROSIDL.Mutexes;

package body RCL.Event_Watches is

   use RCL.Events;
   use type System.Address;
   use type RCL.Graph.Node_Id;
   use type Interfaces.Unsigned_32;

   type Writer_Access is access constant RCL.DDS.Writer;

   type Watched is record
      Node      : RCL.Graph.Node_Id := RCL.Graph.No_Node;
      Writer    : Writer_Access;
      --  null for a subscription (found through its node).
      Topic     : RCL.Node_Entities.Name_Access;
      On_Event  : Callback;
      Last      : RCL.DDS.QoS_Events;
   end record;


   package Watch_Maps is new Ada.Containers.Ordered_Maps (System.Address, Watched);

   Lock : ROSIDL.Mutexes.Mutex;

   Table : Watch_Maps.Map;
   --  Guarded by Lock. Keys: a publisher's writer, a subscription record.

   procedure Register_Publisher (Pub : RCL.Publishers.Publisher; Node : RCL.Graph.Node_Id) is
      W : constant Writer_Access := RCL.Publisher_Writers.Writer (Pub).all'Unchecked_Access;

      procedure Register is
      begin
         Table.Include (W.all'Address, (Node     => Node,
                                        Writer   => W,
                                        Topic    => new String'(Pub.Topic),
                                        On_Event => null,
                                        Last     => <>));
      end Register;
   begin
      ROSIDL.Mutexes.Run_Locked (Lock, Register'Access);
   end Register_Publisher;

   procedure Unregister_Publisher (Pub : RCL.Publishers.Publisher) is
   begin
      Lock.Seize;
      Table.Exclude (RCL.Publisher_Writers.Writer (Pub).all'Address);
      Lock.Release;
   end Unregister_Publisher;

   procedure Set_Callback (Key : System.Address; Fresh : Watched; On_Event : Callback) is
   begin
      Lock.Seize;
      if Table.Contains (Key) then
         Table.Reference (Key).On_Event := On_Event;
      else
         Table.Insert (Key, (Fresh with delta On_Event => On_Event));
      end if;
      Lock.Release;
   end Set_Callback;

   procedure Watch_Publisher
     (Node     : RCL.Graph.Node_Id;
      Pub      : RCL.Publishers.Publisher;
      On_Event : RCL.Events.Callback)
   is
      W : constant Writer_Access := RCL.Publisher_Writers.Writer (Pub).all'Unchecked_Access;
   begin
      Set_Callback (W.all'Address,
                    (Node => Node, Writer => W, Topic => new String'(Pub.Topic),
                     On_Event => null, Last => <>),
                    On_Event);
   end Watch_Publisher;

   procedure Watch_Subscription
     (Node     : RCL.Graph.Node_Id;
      Sub      : not null RCL.Node_Entities.Subscription_Access;
      On_Event : RCL.Events.Callback) is
   begin
      Set_Callback (Sub.all'Address,
                    (Node => Node, Writer => null, Topic => Sub.Topic,
                     On_Event => null, Last => <>),
                    On_Event);
   end Watch_Subscription;

   type Pending is record
      On_Event : Callback;
      E        : Event;
   end record;

   package Pending_Vectors is new Ada.Containers.Vectors (Positive, Pending);

   function Grew (Now, Before : Interfaces.Unsigned_32) return Integer is
     (Integer (Now) - Integer (Before));

   --  The events between Before and Now of one endpoint: warnings logged,
   --  callbacks queued.
   procedure Compare
     (Node    : RCL.Nodes.Node'Class;
      Item    : Watched;
      Now     : RCL.DDS.QoS_Events;
      Is_Pub  : Boolean;
      Queue   : in out Pending_Vectors.Vector)
   is
      B : RCL.DDS.QoS_Events renames Item.Last;
      procedure Add (E : Event) is
      begin
         if Item.On_Event /= null then
            Queue.Append (Pending'(Item.On_Event, E));
         end if;
      end Add;
      Base : constant Event :=
        (Kind => Matched, Topic => Name_Access (Item.Topic), Publisher => Is_Pub, others => <>);
   begin
      if Now.Incompatible_Total > B.Incompatible_Total then
         RCL.Logging.Warn
           ((if Is_Pub
             then "New subscription discovered on topic '" & Item.Topic.all
                  & "', requesting incompatible QoS. No messages will be sent to it. "
             else "New publisher discovered on topic '" & Item.Topic.all
                  & "', offering incompatible QoS. No messages will be received from it. ")
            & "Last incompatible policy: " & Policy_Name (Natural (Now.Last_Policy)),
            Logger => Node.Logger_Name);
         Add ((Base with delta Kind => Incompatible_QoS,
               Total => Natural (Now.Incompatible_Total),
               Change => Grew (Now.Incompatible_Total, B.Incompatible_Total),
               Policy => Natural (Now.Last_Policy)));
      end if;
      if Now.Deadline_Total > B.Deadline_Total then
         Add ((Base with delta Kind => Deadline_Missed, Total => Natural (Now.Deadline_Total),
               Change => Grew (Now.Deadline_Total, B.Deadline_Total)));
      end if;
      if Now.Liveliness_Lost_Total > B.Liveliness_Lost_Total then
         Add ((Base with delta Kind => Liveliness_Lost,
               Total => Natural (Now.Liveliness_Lost_Total),
               Change => Grew (Now.Liveliness_Lost_Total, B.Liveliness_Lost_Total)));
      end if;
      if Now.Alive_Count /= B.Alive_Count or else Now.Not_Alive_Count /= B.Not_Alive_Count then
         Add ((Base with delta Kind => Liveliness_Changed, Alive => Natural (Now.Alive_Count),
               Not_Alive => Natural (Now.Not_Alive_Count)));
      end if;
      if Now.Lost_Total > B.Lost_Total then
         Add ((Base with delta Kind => Message_Lost, Total => Natural (Now.Lost_Total),
               Change => Grew (Now.Lost_Total, B.Lost_Total)));
      end if;
      if Now.Matched_Total /= B.Matched_Total or else Now.Matched_Current /= B.Matched_Current
      then
         Add ((Base with delta Kind => Matched, Total => Natural (Now.Matched_Total),
               Change => Grew (Now.Matched_Total, B.Matched_Total),
               Current => Natural (Now.Matched_Current),
               Current_Change => Grew (Now.Matched_Current, B.Matched_Current)));
      end if;
   end Compare;

   procedure Poll (Node : in out RCL.Nodes.Node'Class) is
      Queue : Pending_Vectors.Vector;
      Now   : RCL.DDS.QoS_Events;

      procedure Collect is
      --  The events of Node's entities since the last poll, into Queue.
      begin
         for I in 1 .. RCL.Node_Entities.Subscription_Count (Node) loop
            declare
               S : constant RCL.Node_Entities.Subscription_Access :=
                 RCL.Node_Entities.Get_Subscription (Node, I);
            begin
               if not Table.Contains (S.all'Address) then
                  Table.Insert (S.all'Address, (Node     => RCL.Node_Entities.Graph_Id (Node),
                                                Writer   => null,
                                                Topic    => S.Topic,
                                                On_Event => null,
                                                Last     => <>));
               end if;
               RCL.DDS.Poll_Events (S.Reader, Now);
               Compare (Node, Table (S.all'Address), Now, False, Queue);
               Table.Reference (S.all'Address).Last := Now;
            end;
         end loop;
         for C in Table.Iterate loop
            declare
               W : Watched renames Table.Reference (C);
            begin
               if W.Node = RCL.Node_Entities.Graph_Id (Node) and then W.Writer /= null
               then
                  RCL.DDS.Poll_Events (W.Writer.all, Now);
                  Compare (Node, W, Now, True, Queue);
                  W.Last := Now;
               end if;
            end;
         end loop;
      end Collect;
   begin
      ROSIDL.Mutexes.Run_Locked (Lock, Collect'Access);
      for P of Queue loop
         P.On_Event (Node, P.E);
      end loop;
   end Poll;

end RCL.Event_Watches;
