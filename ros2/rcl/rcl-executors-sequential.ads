--  The sequential executor: callbacks run one at a time in the task that
--  calls Spin, in the order their work was found (readers, then timers).
package RCL.Executors.Sequential is

   type Executor (Max_Nodes : Positive := Default_Nodes_Per_Executor) is
     new Executors.Executor (Max_Nodes) with null record;

   overriding procedure Dispatch_Sample
     (This : in out Executor;
      Node : not null Node_Access;
      Sub  : Subscription_Work);

   overriding procedure Dispatch_Timer
     (This    : in out Executor;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration);

end RCL.Executors.Sequential;
