--  What the interoperability test peers (pubsub_peer, typed_peer) share in
--  their "echo" mode, where each message received is published again: the
--  count of messages echoed and the wait for the last one.
with RCL.Nodes;

package Echo_Peers is

   Echoed : Natural := 0 with Atomic;
   --  Counted by the peer's subscription callback (run by the executor).

   procedure Spin_Until_Echoed (Node : in out RCL.Nodes.Node'Class; Count : Natural);
   --  Prints "ready" (the test's cue to publish), spins Node until Count
   --  messages are Echoed, then 0.3 s more: the last echoes leave before
   --  the writer goes away.

end Echo_Peers;
