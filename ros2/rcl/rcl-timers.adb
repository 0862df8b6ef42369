package body RCL.Timers is

   use Ada.Real_Time;

   protected body State is

      procedure Start is
      begin
         Last := Clock;
         Next := Last + Nanoseconds (Period_Ns);
         Is_Canceled := False;
      end Start;

      procedure Cancel is
      begin
         Is_Canceled := True;
      end Cancel;

      procedure Reset is
      begin
         Start;
      end Reset;

      function Canceled return Boolean is (Is_Canceled);

      function Due_At return Time is (if Is_Canceled then Time_Last else Next);

      procedure Fire (Now : Time; Fired : out Boolean; Elapsed : out Duration) is
         P : constant Time_Span := Nanoseconds (Period_Ns);
      begin
         Fired := not Is_Canceled and then Now >= Next;
         Elapsed := 0.0;
         if Fired then
            Elapsed := To_Duration (Now - Last);
            Last := Now;
            Next := Next + P;
            if Next <= Now then
               --  Missed periods: jump to the first grid point after Now.
               Next := Next + P * ((Now - Next) / P + 1);
            end if;
         end if;
      end Fire;

   end State;

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

   function Time_Until_Next (This : Timer) return Duration is
     (if This.S.Canceled then Duration'Last else To_Duration (This.S.Due_At - Clock));

   function To_Timer (S : not null State_Access) return Timer is ((S => S));

   function State_Of (This : Timer) return State_Access is (This.S);

end RCL.Timers;
