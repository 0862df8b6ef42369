with RCL.Timers;

package body RCL.Timer_States is

   use RCL.Clocks;

   --  The time a timer reads now, and whether it is simulated time.
   procedure Read_Clock
     (Always_Steady : Boolean; Now : out Nanoseconds; Simulated : out Boolean) is
   begin
      Simulated := not Always_Steady and then Sim_Time_Enabled;
      Now := RCL.Clocks.Now (if Simulated then ROS else Steady);
   end Read_Clock;

   function To_Real_Time (Steady_Time : Nanoseconds) return Ada.Real_Time.Time is
     (Ada.Real_Time.Time_Of
        (Ada.Real_Time.Seconds_Count (Steady_Time / 1_000_000_000),
         Ada.Real_Time.Nanoseconds (Integer (Steady_Time mod 1_000_000_000))));

   protected body State is

      procedure Start is
      begin
         Read_Clock (Always_Steady, Last, Simulated);
         Next := Last + Period_Ns;
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

      function Due_At return Ada.Real_Time.Time is
        (if Is_Canceled or else Simulated or else (not Always_Steady and then Sim_Time_Enabled)
         then Ada.Real_Time.Time_Last
         else To_Real_Time (Next));

      function Until_Next return Duration is
         Now : Nanoseconds;
         Sim : Boolean;
      begin
         if Is_Canceled then
            return Duration'Last;
         end if;
         Read_Clock (Always_Steady, Now, Sim);
         return To_Duration (Next - Now);
      end Until_Next;

      procedure Fire (Fired : out Boolean; Elapsed : out Duration) is
         Now : Nanoseconds;
         Sim : Boolean;
      begin
         Read_Clock (Always_Steady, Now, Sim);
         Fire_At (Now, Sim, Fired, Elapsed);
      end Fire;

      function Next_Call return Nanoseconds is (Next);

      procedure Fire_At
        (Now : Nanoseconds; Simulated : Boolean; Fired : out Boolean; Elapsed : out Duration)
      is
         P   : constant Nanoseconds := Period_Ns;
         Sim : Boolean renames Fire_At.Simulated;
      begin
         Fired := False;
         Elapsed := 0.0;
         if Is_Canceled then
            return;
         end if;
         if Sim /= State.Simulated then
            --  The clock switched (simulated time enabled): a new epoch.
            State.Simulated := Sim;
            Last := Now;
            Next := Now + P;
         elsif Now < Last then
            --  Backward jump behind the last call (a simulation restarted).
            Last := Now;
            Next := Now + P;
         elsif Now >= Next then
            Fired := True;
            Elapsed := To_Duration (Now - Last);
            Last := Now;
            Next := Next + P;
            if Next <= Now then
               --  Missed periods (or a forward jump): the first grid point
               --  after Now.
               Next := Next + P * ((Now - Next) / P + 1);
            end if;
         end if;
      end Fire_At;

   end State;

   --  Every timer handle is a Handle (the full view of RCL.Timers.Timer
   --  extends it); Controlled is the ancestor both views show.
   function To_Timer (S : not null State_Access) return RCL.Timers.Timer is
   begin
      return T : RCL.Timers.Timer do
         Handle'Class (Ada.Finalization.Controlled'Class (T)).S := S;
      end return;
   end To_Timer;

   function State_Of (This : RCL.Timers.Timer) return State_Access is
     (Handle'Class (Ada.Finalization.Controlled'Class (This)).S);

end RCL.Timer_States;
