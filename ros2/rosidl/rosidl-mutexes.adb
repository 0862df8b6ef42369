package body ROSIDL.Mutexes is

   procedure Run_Locked (Lock : in out Mutex; Action : not null access procedure) is
   begin
      Lock.Seize;
      begin
         Action.all;
      exception
         when others =>
            Lock.Release;
            raise;
      end;
      Lock.Release;
   end Run_Locked;

end ROSIDL.Mutexes;
