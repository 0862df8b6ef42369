--  A plain mutex for the ROS 2 library's own bookkeeping (loading of
--  interface definitions, the graph, event watches, recorders, typed
--  clients): Seize waits until the mutex is free. Not reentrant; not
--  released by itself when the holder raises (callers release in their
--  exception handlers).
--
--  Example:
--     Lock : Mutex;
--     ...
--     Lock.Seize;
--     Lock.Release;
package ROSIDL.Mutexes is

   protected type Mutex is
      entry Seize;
      procedure Release;
   private
      Busy : Boolean := False;
   end Mutex;

end ROSIDL.Mutexes;
