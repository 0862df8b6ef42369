package body ROSIDL.Mutexes is

   protected body Mutex is

      entry Seize when not Busy is
      begin
         Busy := True;
      end Seize;

      procedure Release is
      begin
         Busy := False;
      end Release;

   end Mutex;

end ROSIDL.Mutexes;
