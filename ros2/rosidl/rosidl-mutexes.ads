--  A plain mutex for the ROS 2 library's own bookkeeping (loading of
--  interface definitions, the graph, event watches, recorders, typed
--  clients): Seize waits until the mutex is free. Not reentrant; not
--  released by itself when the holder raises (callers release in their
--  exception handlers, or run their work through Run_Locked). It is
--  GNAT's binary semaphore, free at first.
--
--  Example:
--     Lock : Mutex;
--     ...
--     Lock.Seize;
--     Lock.Release;
with GNAT.Semaphores;
with System;

package ROSIDL.Mutexes is

   subtype Mutex is GNAT.Semaphores.Binary_Semaphore
     (Initially_Available => True, Ceiling => System.Priority'Last);
   --  The ceiling of a protected object without a Priority pragma.

   procedure Run_Locked (Lock : in out Mutex; Action : not null access procedure);
   --  Runs Action with Lock seized; releases Lock afterwards, also when
   --  Action raises (the exception goes on). Allocates nothing.

end ROSIDL.Mutexes;
