package body RCL.Timers is

   procedure Cancel (This : in out Timer) is
   begin
      This.S.Cancel;
   end Cancel;

   procedure Reset (This : in out Timer) is
   begin
      This.S.Reset;
   end Reset;

   function Is_Canceled (This : Timer) return Boolean is (This.S.Canceled);

   function Period (This : Timer) return Duration is
     (Duration (This.S.Period_Ns) / 1_000_000_000);

   function Time_Until_Next (This : Timer) return Duration is (This.S.Until_Next);

   function Clock (This : Timer) return Timer_Clock is
     (if This.S.Always_Steady then Steady_Clock else Node_Clock);

end RCL.Timers;
