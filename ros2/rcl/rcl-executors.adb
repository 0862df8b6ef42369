with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with RCL.Allocators;
with RCL.Contexts;
with RCL.Event_Watches;
with RCL.Events;
with RCL.Logging;
with RCL.Timer_States;
with RCL.Timers;
with ROSIDL.Static.Storage;

package body RCL.Executors is

   use Ada.Real_Time;
   use type RCL.Process_Context.Waitset_Access;

   procedure Add (This : in out Executor; Node : in out RCL.Nodes.Node'Class) is
   begin
      if This.N_Nodes = This.Max_Nodes then
         raise ROS_Exception with "executor full: it takes at most" & This.Max_Nodes'Image
           & " nodes";
      end if;
      This.N_Nodes := This.N_Nodes + 1;
      This.Nodes (This.N_Nodes) := Node'Unchecked_Access;
   end Add;

   procedure Stop (This : in out Executor) is
   begin
      This.Stopping := True;
      if This.Set /= null then
         RCL.DDS.Wake (This.Set.all);
      end if;
   end Stop;

   procedure Take_Samples
     (Sub     : Subscription_Work;
      Process : not null access procedure
        (Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info))
   is
      procedure Take_One (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info) is
      begin
         Process (Data, RCL.Node_Entities.To_Info (Info));
      end Take_One;
      Count : Natural;
   begin
      loop
         RCL.DDS.Take_Many (Sub.Reader, Take_One'Access, Count);
         exit when Count = 0;
      end loop;
   end Take_Samples;

   procedure Run_Subscription
     (Node : not null Node_Access;
      Sub  : Subscription_Work;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      Outer : constant RCL.Allocators.Pool_Access := ROSIDL.Static.Storage.Task_Pool;
      --  Decoding allocates from the node's pool (RCL.Allocators).
   begin
      ROSIDL.Static.Storage.Set_Task_Pool (Node.Pool);
      Sub.Handle.Deliver (Node.all, Data, Info);
      ROSIDL.Static.Storage.Set_Task_Pool (Outer);
   exception
      when E : ROSIDL.Decode_Error =>
         ROSIDL.Static.Storage.Set_Task_Pool (Outer);
         RCL.Logging.Error
           ("dropped a malformed sample on " & Sub.Topic.all & ": "
            & Ada.Exceptions.Exception_Message (E), Logger => Node.Logger_Name);
      when E : others =>
         ROSIDL.Static.Storage.Set_Task_Pool (Outer);
         RCL.Logging.Error
           ("exception in the callback of subscription " & Sub.Topic.all & ": "
            & Ada.Exceptions.Exception_Name (E) & ": " & Ada.Exceptions.Exception_Message (E),
            Logger => Node.Logger_Name);
   end Run_Subscription;

   procedure Run_Timer
     (Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration)
   is
      T : RCL.Timers.Timer := RCL.Timer_States.To_Timer (Timer.State);
   begin
      Timer.Callback (Node.all, T, Elapsed);
   exception
      when E : others =>
         RCL.Logging.Error
           ("exception in a timer callback (period" & RCL.Timers.Period (T)'Image & " s): "
            & Ada.Exceptions.Exception_Name (E) & ": " & Ada.Exceptions.Exception_Message (E),
            Logger => Node.Logger_Name);
   end Run_Timer;

   --  Re-attaches the readers of all nodes when any node changed.
   procedure Refresh (This : in out Executor'Class) is
      Changed : Boolean := False;
   begin
      for I in 1 .. This.N_Nodes loop
         if This.Versions (I) /= RCL.Node_Entities.Version (This.Nodes (I).all) then
            Changed := True;
         end if;
      end loop;
      if not Changed then
         return;
      end if;
      for I in 1 .. This.N_Attached loop
         RCL.DDS.Detach (This.Set.all, This.Attached (I).Sub.Reader);
      end loop;
      This.N_Attached := 0;
      for I in 1 .. This.N_Nodes loop
         This.Versions (I) := RCL.Node_Entities.Version (This.Nodes (I).all);
         for J in 1 .. RCL.Node_Entities.Subscription_Count (This.Nodes (I).all) loop
            if This.N_Attached = Max_Attached then
               raise ROS_Exception with "executor: more than" & Max_Attached'Image
                 & " subscriptions";
            end if;
            This.N_Attached := This.N_Attached + 1;
            This.Attached (This.N_Attached) :=
              (This.Nodes (I), RCL.Node_Entities.Get_Subscription (This.Nodes (I).all, J));
            RCL.DDS.Attach (This.Set.all, This.Attached (This.N_Attached).Sub.Reader,
                            This.N_Attached);
         end loop;
      end loop;
   end Refresh;

   procedure Spin
     (This   : in out Executor'Class;
      During : Duration := Forever;
      Once   : Boolean := False)
   is
      Deadline : constant Time :=
        (if During >= Forever then Time_Last else Clock + To_Time_Span (During));
      Waker    : Positive;
      Last_Events : Time := Clock;
      Ready    : RCL.DDS.Key_Array (1 .. Max_Attached);
      Last     : Natural;
   begin
      RCL.Contexts.Install_Signal_Handlers;
      if This.Set = null then
         This.Set := new RCL.DDS.Waitset;
         RCL.DDS.Create (This.Set.all, RCL.Process_Context.Participant.all);
      end if;
      This.Stopping := False;
      RCL.Process_Context.Register_Waker (This.Set, Waker);
      loop
         exit when RCL.Contexts.Is_Shutdown or else This.Stopping;
         Refresh (This);
         declare
            Wake_At : Time := Deadline;
            Now     : constant Time := Clock;
            Worked  : Boolean := False;
         begin
            for I in 1 .. This.N_Nodes loop
               declare
                  Due : constant Time := RCL.Node_Entities.Next_Timer_Due (This.Nodes (I).all);
               begin
                  if Due < Wake_At then
                     Wake_At := Due;
                  end if;
               end;
            end loop;
            RCL.DDS.Wait
              (This.Set.all,
               Duration'Min (RCL.Events.Poll_Period,
                             (if Wake_At = Time_Last then Forever
                              else To_Duration (Wake_At - Now))),
               Ready, Last);
            exit when RCL.Contexts.Is_Shutdown or else This.Stopping;
            for K in Ready'First .. Last loop
               if Ready (K) <= This.N_Attached then
                  This.Dispatch_Sample
                    (This.Attached (Ready (K)).Node,
                     Subscription_Work (This.Attached (Ready (K)).Sub));
                  Worked := True;
               end if;
            end loop;
            for I in 1 .. This.N_Nodes loop
               for J in 1 .. RCL.Node_Entities.Timer_Count (This.Nodes (I).all) loop
                  declare
                     T       : constant Timer_Work :=
                       Timer_Work (RCL.Node_Entities.Get_Timer (This.Nodes (I).all, J));
                     Fired   : Boolean;
                     Elapsed : Duration;
                  begin
                     T.State.Fire (Fired, Elapsed);
                     if Fired then
                        This.Dispatch_Timer (This.Nodes (I), T, Elapsed);
                        Worked := True;
                     end if;
                  end;
               end loop;
            end loop;
            if Clock - Last_Events >= To_Time_Span (RCL.Events.Poll_Period) then
               Last_Events := Clock;
               for I in 1 .. This.N_Nodes loop
                  RCL.Event_Watches.Poll (This.Nodes (I).all);
               end loop;
            end if;
            exit when Once and then Worked;
            exit when Clock >= Deadline;
         end;
      end loop;
      RCL.Process_Context.Unregister_Waker (Waker);
      This.Flush;
   exception
      when others =>
         RCL.Process_Context.Unregister_Waker (Waker);
         raise;
   end Spin;

   overriding procedure Finalize (This : in out Executor) is
      procedure Free is new Ada.Unchecked_Deallocation
        (RCL.DDS.Waitset, RCL.Process_Context.Waitset_Access);
   begin
      if This.Set /= null then
         for I in 1 .. This.N_Attached loop
            begin
               RCL.DDS.Detach (This.Set.all, This.Attached (I).Sub.Reader);
            exception
               when others =>
                  null;
            end;
         end loop;
         Free (This.Set);
      end if;
   exception
      when others =>
         null;
   end Finalize;

end RCL.Executors;
