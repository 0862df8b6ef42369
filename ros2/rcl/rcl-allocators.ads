--  Storage pools for the message path (RCLAda's RCL.Allocators, with Ada
--  storage pools in place of rcutils allocators): a node given a pool
--  makes every allocation of its subscriptions' message decoding (the
--  unbounded sequences of generated messages) from it, in whichever
--  executor task runs the callbacks:
--  Example:
--     Pool : aliased GNAT.Debug_Pools.Debug_Pool;
--     Node : Nodes.Node := Nodes.Init
--       ("listener", Options => (Pool => Pool'Unchecked_Access, others => <>));
--     ...
--     GNAT.Debug_Pools.Print_Info_Stdout (Pool);  --  bytes allocated, freed, high water
--
--  Everything else (node and endpoint records, dynamic messages, strings)
--  comes from the standard heap; bounded generated types need no heap on
--  the message path at all (see the README).
with ROSIDL.Static.Storage;

package RCL.Allocators is

   subtype Pool_Access is ROSIDL.Static.Storage.Pool_Access;

   Global_Allocator : constant Pool_Access := null;
   --  The standard heap (the default of every node).

   procedure Set_Task_Pool (Pool : Pool_Access) renames ROSIDL.Static.Storage.Set_Task_Pool;
   --  The pool of the calling task's message allocations outside callbacks
   --  (messages a program builds itself).

end RCL.Allocators;
