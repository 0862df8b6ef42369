--  What the interoperability test peers (pubsub_peer, typed_peer) share in
--  their "echo" mode, where each message received is published again: the
--  count of messages echoed and the wait for the last one.
with RCL.Nodes;

package Echo_Peers is

   Echoed : Natural := 0 with Atomic;
   --  Counted by the peer's subscription callback (run by the executor).

   Until_Stopped : constant Natural := 0;
   --  The Count of a peer that echoes until it is stopped (SIGTERM). A test
   --  that needs echoes to come back uses it and feeds the peer until they
   --  do: echoes published before this writer and the test's reader have
   --  matched each other are lost (best effort or volatile), and each side
   --  learns of the other's endpoints on its own schedule.

   procedure Spin_Until_Echoed (Node : in out RCL.Nodes.Node'Class; Count : Natural);
   --  Prints "ready" (the test's cue to publish), spins Node until Count
   --  messages are Echoed (or, Count = Until_Stopped, until shutdown: SIGINT,
   --  SIGTERM), then 0.3 s more: the last echoes leave before the writer
   --  goes away; then prints "echoed N". Shutdown also ends a wait for Count
   --  echoes.

end Echo_Peers;
