--  Counts the Ada heap allocations of one task: linked with
--  -Wl,--wrap=__gnat_malloc, every call of __gnat_malloc (allocators,
--  controlled objects, unbounded strings, secondary-stack chunks: all of
--  the GNAT run time's heap use) goes through Counting_Malloc. Used by the
--  zero-allocation check (typed_alloc_check.adb) only.
with System;
with Interfaces.C;

package Heap_Counters is

   procedure Start (Watched : System.Address);
   --  From now on, count the allocations made while the calling task is
   --  the task whose identity is Watched (Ada.Task_Identification), and all
   --  allocations of the process separately.

   function Task_Allocations return Natural;
   function All_Allocations return Natural;

   function Counting_Malloc (Size : Interfaces.C.size_t) return System.Address
     with Export, Convention => C, External_Name => "__wrap___gnat_malloc";

end Heap_Counters;
