--  Counts the Ada heap allocations of one task: linked with
--  -Wl,--wrap=__gnat_malloc, every call of __gnat_malloc from the
--  program's own objects (allocators "new", including the library's
--  storage pools, controlled objects) goes through Counting_Malloc.
--  Limit: Debian links the GNAT run time as a shared library, whose
--  internal calls (Unbounded_String storage, secondary-stack chunks) are
--  not wrapped. Used by the zero-allocation check only.
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
