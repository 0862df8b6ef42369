--  The concurrent executor: the spinning task takes the samples and timer
--  expirations and queues them (bounded queue: a full queue blocks the
--  spinning task, never a DDS thread); a pool of Threads Ada tasks runs the
--  callbacks, in parallel as their callback groups allow (RCL.Nodes,
--  Callback_Group): by default every callback of a node is in the node's
--  mutually exclusive default group, as in rclcpp, so one node's callbacks
--  run one at a time while different nodes' run in parallel; callbacks put
--  in a Reentrant group run in parallel and must protect what they share.
--
--  Shutdown (deterministic): Shutdown, or finalization of the executor,
--  waits until every queued callback has run, then stops each pool task and
--  waits for its termination; nothing runs after it returns. The pool is
--  started by the first Spin.
--  Example:
--     E : Executors.Concurrent.Executor (Threads => 4);
--     E.Add (Node);
--     E.Spin (During => Executors.Forever);
with System;
with System.Multiprocessors;

package RCL.Executors.Concurrent is

   CPUs : constant Positive := Positive (System.Multiprocessors.Number_Of_CPUs);

   type Tuned_Executor
     (Max_Nodes  : Positive;
      Queue_Size : Positive;
      Threads    : Positive;
      Priority   : System.Priority) is
     new Executors.Executor (Max_Nodes) with record
      Workers : Task_Pool;
   end record;
   --  Threads pool tasks run the callbacks at Priority; the queue holds
   --  Queue_Size pending callbacks (then the spinning task waits).

   overriding procedure Dispatch_Sample
     (This : in out Tuned_Executor;
      Node : not null Node_Access;
      Sub  : Subscription_Work);

   overriding procedure Dispatch_Timer
     (This    : in out Tuned_Executor;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration);

   overriding procedure Flush (This : in out Tuned_Executor);

   procedure Shutdown (This : in out Tuned_Executor);
   --  See above; idempotent. The executor may Spin again afterwards (a new
   --  pool is started).

   function Is_Shut_Down (This : Tuned_Executor) return Boolean;
   --  No pool task exists.

   overriding procedure Finalize (This : in out Tuned_Executor);

   type Executor (Threads : Positive := CPUs) is new Tuned_Executor
     (Max_Nodes  => Default_Nodes_Per_Executor,
      Queue_Size => CPUs * 32,
      Threads    => Threads,
      Priority   => System.Default_Priority) with null record;
   --  The usual one: Threads tasks; Tuned_Executor gives every setting (an
   --  Ada constraint names all discriminants, so this type keeps one).

end RCL.Executors.Concurrent;
