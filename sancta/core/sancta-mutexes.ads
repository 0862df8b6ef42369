--  A plain mutex for work done outside protected actions (log output, team
--  network bookkeeping): Seize waits until the mutex is free. Not
--  reentrant; not released by itself when the holder raises (callers
--  release in their exception handlers).
--
--     Lock : Mutexes.Mutex;
--     Lock.Seize;
--     ...  --  the guarded work, outside any protected action
--     Lock.Release;
package Sancta.Mutexes is

   protected type Mutex is
      entry Seize;
      procedure Release;
   private
      Busy : Boolean := False;
   end Mutex;

end Sancta.Mutexes;
