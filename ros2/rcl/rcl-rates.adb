with RCL.Contexts;

package body RCL.Rates is

   use RCL.Clocks;

   Poll : constant Duration := 0.001;
   --  Simulated time only advances with /clock: it is polled.

   function Create (Hz : Long_Float; Clock : RCL.Clocks.Clock_Kind := RCL.Clocks.Steady)
     return Rate is
     ((Period_Ns => Nanoseconds'Max (1, Nanoseconds (1.0E9 / Hz)),
       Kind      => Clock,
       Last      => Now (Clock)));

   function Sleep (This : in out Rate) return Boolean is
      Start : constant Nanoseconds := Now (This.Kind);
      Next  : Nanoseconds := This.Last + This.Period_Ns;
   begin
      if Start < This.Last then
         Next := Start + This.Period_Ns;  --  The clock went back.
      end if;
      if Next <= Start then
         This.Last := Start;
         return False;
      end if;
      if This.Kind = ROS and then Sim_Time_Enabled then
         while Now (ROS) < Next loop
            if RCL.Contexts.Is_Shutdown then
               return False;
            end if;
            delay Poll;
         end loop;
      else
         while Now (This.Kind) < Next loop
            if RCL.Contexts.Is_Shutdown then
               return False;
            end if;
            delay Duration'Min (0.1, To_Duration (Next - Now (This.Kind)));
         end loop;
      end if;
      This.Last := Next;
      return True;
   end Sleep;

   procedure Sleep (This : in out Rate) is
      Ignored : constant Boolean := This.Sleep;
   begin
      null;
   end Sleep;

   procedure Reset (This : in out Rate) is
   begin
      This.Last := Now (This.Kind);
   end Reset;

   function Period (This : Rate) return Duration is (To_Duration (This.Period_Ns));

   function Clock (This : Rate) return RCL.Clocks.Clock_Kind is (This.Kind);

end RCL.Rates;
