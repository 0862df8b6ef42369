--  The task pool of the concurrent executor (RCL.Executors.Concurrent):
--  a bounded queue of callbacks to run and the tasks that run them, kept
--  in an RCL.Executors.Task_Pool. A private child of RCL.Executors.
with System;
with ROSIDL;
with RCL.DDS;

private package RCL.Executors.Pools is

   procedure Start
     (This       : in out Task_Pool;
      Queue_Size : Positive;
      Threads    : Positive;
      Priority   : System.Priority);
   --  Makes the queue and the tasks unless started.

   function Started (This : Task_Pool) return Boolean;

   procedure Put_Sample
     (This : in out Task_Pool;
      Node : not null Node_Access;
      Sub  : Subscription_Work;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
     with Pre => Started (This);
   --  Queues a copy of Data (waits while the queue is full).

   procedure Put_Timer
     (This    : in out Task_Pool;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration)
     with Pre => Started (This);

   procedure Flush (This : in out Task_Pool);
   --  Waits until every queued callback has run.

   procedure Shutdown (This : in out Task_Pool);
   --  Flush, then stops the tasks and waits for their termination.

private

   type Work_Queue;
   type Queue_Access is access Work_Queue;
   type Runner_Set;
   type Runner_Set_Access is access Runner_Set;

end RCL.Executors.Pools;
