--  The concurrent executor: the spinning task takes the samples and timer
--  expirations and queues them (bounded queue: a full queue blocks the
--  spinning task, never a DDS thread); a pool of Threads Ada tasks runs the
--  callbacks. Callbacks of one node may thus run in parallel: they must
--  protect what they share (as with a ROS 2 reentrant callback group).
--
--  Shutdown (deterministic): Shutdown, or finalization of the executor,
--  waits until every queued callback has run, then stops each pool task and
--  waits for its termination; nothing runs after it returns. The pool is
--  started by the first Spin.
--
--     E : Executors.Concurrent.Executor (Threads => 4);
--     E.Add (Node);
--     E.Spin (During => Executors.Forever);
with System;
with System.Multiprocessors;

package RCL.Executors.Concurrent is

   CPUs : constant Positive := Positive (System.Multiprocessors.Number_Of_CPUs);

   type Executor
     (Max_Nodes  : Positive := Default_Nodes_Per_Executor;
      Queue_Size : Positive := CPUs * 32;
      Threads    : Positive := CPUs;
      Priority   : System.Priority := System.Default_Priority) is
     new Executors.Executor with private;
   --  Threads pool tasks run the callbacks at Priority; the queue holds
   --  Queue_Size pending callbacks (then the spinning task waits).

   overriding procedure Dispatch_Sample
     (This : in out Executor;
      Node : not null Node_Access;
      Sub  : not null RCL.Nodes.Subscription_Access);

   overriding procedure Dispatch_Timer
     (This    : in out Executor;
      Node    : not null Node_Access;
      Timer   : RCL.Nodes.Timer_Entry;
      Elapsed : Duration);

   overriding procedure Flush (This : in out Executor);

   procedure Shutdown (This : in out Executor);
   --  See above; idempotent. The executor may Spin again afterwards (a new
   --  pool is started).

   function Is_Shut_Down (This : Executor) return Boolean;
   --  No pool task exists.

   overriding procedure Finalize (This : in out Executor);

private

   type Work_Queue;
   type Queue_Access is access Work_Queue;
   type Runner;
   type Runner_Access is access Runner;
   type Runner_Array is array (Positive range <>) of Runner_Access;

   type Executor
     (Max_Nodes  : Positive := Default_Nodes_Per_Executor;
      Queue_Size : Positive := CPUs * 32;
      Threads    : Positive := CPUs;
      Priority   : System.Priority := System.Default_Priority) is
     new Executors.Executor (Max_Nodes) with record
      Queue   : Queue_Access;
      Pool    : Runner_Array (1 .. Threads);
      Started : Boolean := False;
   end record;

end RCL.Executors.Concurrent;
