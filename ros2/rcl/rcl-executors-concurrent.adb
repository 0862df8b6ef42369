with RCL.Executors.Pools;

package body RCL.Executors.Concurrent is

   procedure Start (This : in out Tuned_Executor) is
   begin
      Pools.Start (This.Workers, This.Queue_Size, This.Threads, This.Priority);
   end Start;

   overriding procedure Dispatch_Sample
     (This : in out Tuned_Executor;
      Node : not null Node_Access;
      Sub  : Subscription_Work)
   is
      procedure Queue_It (Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info) is
      begin
         Pools.Put_Sample (This.Workers, Node, Sub, Data, Info);
      end Queue_It;
   begin
      Start (This);
      Take_Samples (Sub, Queue_It'Access);
   end Dispatch_Sample;

   overriding procedure Dispatch_Timer
     (This    : in out Tuned_Executor;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration) is
   begin
      Start (This);
      Pools.Put_Timer (This.Workers, Node, Timer, Elapsed);
   end Dispatch_Timer;

   overriding procedure Flush (This : in out Tuned_Executor) is
   begin
      Pools.Flush (This.Workers);
   end Flush;

   procedure Shutdown (This : in out Tuned_Executor) is
   begin
      Pools.Shutdown (This.Workers);
   end Shutdown;

   function Is_Shut_Down (This : Tuned_Executor) return Boolean is
     (not Pools.Started (This.Workers));

   overriding procedure Finalize (This : in out Tuned_Executor) is
   begin
      Shutdown (This);
      Executors.Executor (This).Finalize;
   exception
      when others =>
         null;
   end Finalize;

end RCL.Executors.Concurrent;
