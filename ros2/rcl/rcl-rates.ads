--  A Rate keeps a loop at a frequency, as rclcpp::Rate: Sleep waits until
--  one period after the previous wake-up, on the steady clock or on ROS
--  time (which follows /clock under use_sim_time).
--  Example:
--     R : Rates.Rate := Rates.Create (Hz => 10.0);
--     loop
--        Publish_Pose;
--        R.Sleep;   --  or "if not R.Sleep then" (the period was missed)
--     end loop;
with RCL.Clocks;

package RCL.Rates is

   type Rate is tagged private;

   function Create (Hz : Long_Float; Clock : RCL.Clocks.Clock_Kind := RCL.Clocks.Steady)
     return Rate
     with Pre => Hz > 0.0;
   --  The first period starts now.

   function Sleep (This : in out Rate) return Boolean;
   --  Waits for the end of the current period; False when it had already
   --  passed (the loop is late: the next period then starts now). Returns
   --  at once, False, after shutdown (Ctrl-C). A backward jump of the clock
   --  restarts the period from the new time.

   procedure Sleep (This : in out Rate);
   --  The same, ignoring lateness.

   procedure Reset (This : in out Rate);
   --  The next period starts now.

   function Period (This : Rate) return Duration;

   function Clock (This : Rate) return RCL.Clocks.Clock_Kind;

private

   type Rate is tagged record
      Period_Ns : RCL.Clocks.Nanoseconds := 1;
      Kind      : RCL.Clocks.Clock_Kind := RCL.Clocks.Steady;
      Last      : RCL.Clocks.Nanoseconds := 0;
   end record;

end RCL.Rates;
