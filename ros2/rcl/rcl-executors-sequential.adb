package body RCL.Executors.Sequential is

   overriding procedure Dispatch_Sample
     (This : in out Executor;
      Node : not null Node_Access;
      Sub  : Subscription_Work)
   is
      pragma Unreferenced (This);
      procedure Process (Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info) is
      begin
         Run_Subscription (Node, Sub, Data, Info);
      end Process;
   begin
      Take_Samples (Sub, Process'Access);
   end Dispatch_Sample;

   overriding procedure Dispatch_Timer
     (This    : in out Executor;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration)
   is
      pragma Unreferenced (This);
   begin
      Run_Timer (Node, Timer, Elapsed);
   end Dispatch_Timer;

end RCL.Executors.Sequential;
