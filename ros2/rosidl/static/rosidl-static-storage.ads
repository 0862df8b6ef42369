--  Where generated messages keep their unbounded sequences: Message_Pool,
--  the storage pool of every ROSIDL.Static.Unbounded_Sequences instance,
--  forwards each allocation to the pool the calling task has selected
--  (Set_Task_Pool; the standard heap when none), and each deallocation to
--  the pool that made the storage, whichever task frees it. RCL selects a
--  node's pool (RCL.Allocators, Node_Options.Pool) while the node's
--  subscription callbacks run, so what decoding allocates comes from it:
--  Example:
--     Set_Task_Pool (My_Pool'Unchecked_Access);
--     Scan.Ranges.Set_Length (720);      --  from My_Pool
--     Set_Task_Pool (null);
with System.Storage_Elements;
with System.Storage_Pools;

package ROSIDL.Static.Storage is

   type Pool_Access is access all System.Storage_Pools.Root_Storage_Pool'Class;

   procedure Set_Task_Pool (Pool : Pool_Access);
   --  The pool of the calling task's next allocations; null: the heap.

   function Task_Pool return Pool_Access;

   type Forwarding_Pool is new System.Storage_Pools.Root_Storage_Pool with null record;

   overriding procedure Allocate
     (Pool      : in out Forwarding_Pool;
      Address   : out System.Address;
      Size      : System.Storage_Elements.Storage_Count;
      Alignment : System.Storage_Elements.Storage_Count);

   overriding procedure Deallocate
     (Pool      : in out Forwarding_Pool;
      Address   : System.Address;
      Size      : System.Storage_Elements.Storage_Count;
      Alignment : System.Storage_Elements.Storage_Count);

   overriding function Storage_Size
     (Pool : Forwarding_Pool) return System.Storage_Elements.Storage_Count;

   Message_Pool : Forwarding_Pool;

end ROSIDL.Static.Storage;
