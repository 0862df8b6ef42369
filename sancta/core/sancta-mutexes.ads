--  A plain mutex for work done outside protected actions (log output, team
--  network bookkeeping): Seize waits until the mutex is free. Not
--  reentrant; not released by itself when the holder raises (callers
--  release in their exception handlers). It is GNAT's binary semaphore,
--  free at first (the SANCTA core does not use the ROS 2 library's
--  ROSIDL.Mutexes, which is the same).
--
--     Lock : Mutexes.Mutex;
--     Lock.Seize;
--     ...  --  the guarded work, outside any protected action
--     Lock.Release;
with GNAT.Semaphores;
with System;

package Sancta.Mutexes is

   subtype Mutex is GNAT.Semaphores.Binary_Semaphore
     (Initially_Available => True, Ceiling => System.Priority'Last);
   --  The ceiling of a protected object without a Priority pragma.

end Sancta.Mutexes;
