--  Executors: run the callbacks (subscriptions, timers) of their nodes.
--
--  The spinning task waits on a DDS waitset (never on a DDS thread), takes
--  the samples and hands each callback to the executor's Dispatch: the
--  sequential executor runs it at once in the spinning task, the concurrent
--  one queues it for a pool of tasks. An exception in a user callback is
--  logged with the callback's topic; the node keeps running.
--  Example:
--     E : Executors.Sequential.Executor;
--     E.Add (Node_1);  E.Add (Node_2);
--     E.Spin (During => Executors.Forever);
--
--  Nodes must outlive the executors they are added to.
with Ada.Finalization;
with ROSIDL;
with RCL.DDS;
with RCL.Nodes;

private with RCL.Node_Entities;
private with RCL.Process_Context;

package RCL.Executors is

   Forever : constant Duration := RCL.Nodes.Forever;

   Default_Nodes_Per_Executor : constant := 16;

   type Executor (Max_Nodes : Positive) is abstract
     new Ada.Finalization.Limited_Controlled with private;

   procedure Add (This : in out Executor; Node : in out RCL.Nodes.Node'Class);
   --  Raises ROS_Exception when Max_Nodes are already added.

   procedure Spin
     (This   : in out Executor'Class;
      During : Duration := Forever;
      Once   : Boolean := False);
   --  Runs callbacks in the calling task for During, or until one batch of
   --  ready work was dispatched (Once), or until Stop or shutdown (Ctrl-C,
   --  SIGTERM, Contexts.Shutdown). Returns once dispatched work is done.

   procedure Stop (This : in out Executor);
   --  Makes a Spin of This (in another task) return soon.

   --  For executor implementations ----------------------------------------
   --  Spin finds the work -- a subscription whose reader holds samples, a
   --  timer due -- and hands it to the executor's Dispatch_Sample or
   --  Dispatch_Timer, which have it run at once (Take_Samples then
   --  Run_Subscription; Run_Timer) or later in another task (the concurrent
   --  executor queues it for its pool).
   --  Example:
   --     type Counting is new Executors.Executor (Max_Nodes => 4) with record
   --        Samples : Natural := 0;
   --     end record;
   --     overriding procedure Dispatch_Sample
   --       (This : in out Counting; Node : not null Executors.Node_Access;
   --        Sub  : Executors.Subscription_Work);
   --     overriding procedure Dispatch_Timer
   --       (This  : in out Counting; Node : not null Executors.Node_Access;
   --        Timer : Executors.Timer_Work; Elapsed : Duration);
   --     overriding procedure Dispatch_Sample
   --       (This : in out Counting; Node : not null Executors.Node_Access;
   --        Sub  : Executors.Subscription_Work) is
   --        procedure Run (Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info) is
   --        begin
   --           This.Samples := This.Samples + 1;
   --           Executors.Run_Subscription (Node, Sub, Data, Info);
   --        end Run;
   --     begin
   --        Executors.Take_Samples (Sub, Run'Access);
   --     end Dispatch_Sample;
   --     overriding procedure Dispatch_Timer
   --       (This  : in out Counting; Node : not null Executors.Node_Access;
   --        Timer : Executors.Timer_Work; Elapsed : Duration) is
   --     begin
   --        Executors.Run_Timer (Node, Timer, Elapsed);  --  at once, in Spin's task
   --     end Dispatch_Timer;

   type Node_Access is access all RCL.Nodes.Node'Class;

   type Subscription_Work is private;
   --  A subscription of a node, whose reader holds samples.

   type Timer_Work is private;
   --  A timer of a node, due.

   procedure Dispatch_Sample
     (This : in out Executor;
      Node : not null Node_Access;
      Sub  : Subscription_Work) is abstract;
   --  Sub's reader has data: take it all and have the callbacks run.

   procedure Dispatch_Timer
     (This    : in out Executor;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration) is abstract;
   --  Have the timer's callback run (Elapsed: since its previous call).

   procedure Flush (This : in out Executor) is null;
   --  Waits until dispatched work has run (end of Spin).

   procedure Take_Samples
     (Sub     : Subscription_Work;
      Process : not null access procedure
        (Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info));
   --  Takes every sample Sub's reader holds, calling Process on each in
   --  the calling task (Data: valid during the call only).

   procedure Run_Subscription
     (Node : not null Node_Access;
      Sub  : Subscription_Work;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info);
   --  Calls the subscription's callback (decoding allocates from the node's
   --  pool); logs its exceptions.

   procedure Run_Timer
     (Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration);
   --  Calls the timer's callback; logs its exceptions.

   overriding procedure Finalize (This : in out Executor);

   type Task_Pool is limited private;
   --  The queue and tasks of a concurrent executor (the Workers of
   --  RCL.Executors.Concurrent.Tuned_Executor): opaque, started by its
   --  first Spin, stopped by its Shutdown or finalization.

private

   type Subscription_Work is new RCL.Node_Entities.Subscription_Access;
   type Timer_Work is new RCL.Node_Entities.Timer_Entry;

   type Task_Pool_State is abstract tagged limited null record;
   --  Extended by the private child RCL.Executors.Pools (queue and tasks).
   type Task_Pool_State_Access is access Task_Pool_State'Class;

   type Task_Pool is limited record
      State : Task_Pool_State_Access;
   end record;

   type Node_Array is array (Positive range <>) of Node_Access;

   Max_Attached : constant := 256;

   type Attached_Entry is record
      Node : Node_Access;
      Sub  : RCL.Node_Entities.Subscription_Access;
   end record;
   type Attached_Array is array (1 .. Max_Attached) of Attached_Entry;
   type Version_Array is array (Positive range <>) of Integer;

   type Executor (Max_Nodes : Positive) is abstract
     new Ada.Finalization.Limited_Controlled with record
      Nodes      : Node_Array (1 .. Max_Nodes) := [others => null];
      N_Nodes    : Natural := 0;
      Versions   : Version_Array (1 .. Max_Nodes) := [others => -1];
      Set        : RCL.Process_Context.Waitset_Access;
      Attached   : Attached_Array;
      N_Attached : Natural := 0;
      Stopping   : Boolean := False with Atomic;
   end record;

end RCL.Executors;
