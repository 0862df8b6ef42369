package body RCL.Executors.Sequential is

   overriding procedure Dispatch_Sample
     (This : in out Executor;
      Node : not null Node_Access;
      Sub  : not null RCL.Nodes.Subscription_Access)
   is
      pragma Unreferenced (This);
      procedure Process (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info) is
      begin
         Run_Subscription (Node, Sub, Data, To_Info (Info));
      end Process;
      Count : Natural;
   begin
      loop
         RCL.DDS.Take_Many (Sub.Reader, Process'Access, Count);
         exit when Count = 0;
      end loop;
   end Dispatch_Sample;

   overriding procedure Dispatch_Timer
     (This    : in out Executor;
      Node    : not null Node_Access;
      Timer   : RCL.Nodes.Timer_Entry;
      Elapsed : Duration)
   is
      pragma Unreferenced (This);
   begin
      Run_Timer (Node, Timer, Elapsed);
   end Dispatch_Timer;

end RCL.Executors.Sequential;
