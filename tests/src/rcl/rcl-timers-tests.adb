with AUnit.Assertions; use AUnit.Assertions;
with Ada.Real_Time;
with RCL.Clocks;
with RCL.Timer_States; use RCL.Timer_States;
with Suite_Support; use Suite_Support;

package body RCL.Timers.Tests is

   use RCL.Clocks;
   use type Ada.Real_Time.Time;

   P  : constant Nanoseconds := 100_000_000;
   Ms : constant Nanoseconds := 1_000_000;

   procedure Grid (Unused : in out Fixture) is
      S       : aliased State (Period_Ns => P, Always_Steady => True);
      Fired   : Boolean;
      Elapsed : Duration;
      First   : Nanoseconds;
   begin
      S.Start;
      First := S.Next_Call;
      S.Fire_At (First - 1, False, Fired, Elapsed);
      Assert (not Fired, "not due 1 ns early");
      S.Fire_At (First + 7 * Ms, False, Fired, Elapsed);
      Assert (Fired, "due");
      Assert (S.Next_Call = First + P, "next on the grid despite a late call (no drift)");
      --  A long stall: missed periods are skipped, the grid is kept.
      S.Fire_At (First + P * 4 + 50 * Ms, False, Fired, Elapsed);
      Assert (Fired, "fires after a stall");
      Assert (S.Next_Call = First + P * 5, "skips to the next grid point");
      Assert (abs (Elapsed - 0.443) < 0.000_001, "elapsed since the previous call");
   end Grid;

   procedure Time_Jumps (Unused : in out Fixture) is
      S       : aliased State (Period_Ns => P, Always_Steady => False);
      Fired   : Boolean;
      Elapsed : Duration;
      Sec     : constant Nanoseconds := 1_000_000_000;
   begin
      S.Start;
      --  Simulated time starts (ROS time 0 before the first /clock): a new
      --  epoch, one period from now.
      S.Fire_At (0, True, Fired, Elapsed);
      Assert (not Fired and then S.Next_Call = P, "switch to simulated time restarts");
      S.Fire_At (P, True, Fired, Elapsed);
      Assert (Fired and then S.Next_Call = 2 * P, "ticks on simulated time");
      --  Forward jump (the simulation skipped 100 s): one call, grid kept.
      S.Fire_At (100 * Sec + 5 * Ms, True, Fired, Elapsed);
      Assert (Fired, "fires once after a forward jump");
      Assert (S.Next_Call = 100 * Sec + P, "next grid point after the jump");
      S.Fire_At (100 * Sec + 6 * Ms, True, Fired, Elapsed);
      Assert (not Fired, "no burst of missed calls");
      --  Backward jump (the simulation restarted at 1 s): one period later.
      S.Fire_At (Sec, True, Fired, Elapsed);
      Assert (not Fired and then S.Next_Call = Sec + P, "backward jump restarts the period");
      S.Fire_At (Sec + P, True, Fired, Elapsed);
      Assert (Fired, "ticks again one period after the backward jump");
   end Time_Jumps;

   procedure Cancel_Reset (Unused : in out Fixture) is
      S       : aliased State (Period_Ns => P, Always_Steady => True);
      T       : Timer;
      Fired   : Boolean;
      Elapsed : Duration;
   begin
      S.Start;
      T := To_Timer (S'Unchecked_Access);
      Assert (abs (T.Period - 0.1) < 1.0e-9, "period");
      T.Cancel;
      Assert (T.Is_Canceled, "canceled");
      Assert (S.Due_At = Ada.Real_Time.Time_Last, "a canceled timer is never due");
      S.Fire_At (S.Next_Call + 10 * P, False, Fired, Elapsed);
      Assert (not Fired, "a canceled timer does not fire");
      T.Reset;
      Assert (not T.Is_Canceled, "reset uncancels");
      Assert (T.Time_Until_Next > 0.0 and then T.Time_Until_Next <= 0.1,
              "next call one period from reset");
   end Cancel_Reset;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("timers: drift-free grid", Grid'Access));
      Result.Add_Test (Caller.Create ("timers: time jumps as rcl", Time_Jumps'Access));
      Result.Add_Test (Caller.Create ("timers: cancel and reset", Cancel_Reset'Access));
      return Result;
   end Suite;

end RCL.Timers.Tests;
