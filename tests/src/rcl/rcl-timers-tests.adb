with AUnit.Assertions; use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body RCL.Timers.Tests is

   use Ada.Real_Time;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;
   package Caller is new AUnit.Test_Caller (Fixture);

   P : constant Time_Span := Milliseconds (100);

   procedure Grid (Unused : in out Fixture) is
      S       : aliased State (Period_Ns => 100_000_000);
      Fired   : Boolean;
      Elapsed : Duration;
      First   : Time;
   begin
      S.Start;
      First := S.Due_At;
      S.Fire (First - Nanoseconds (1), Fired, Elapsed);
      Assert (not Fired, "not due 1 ns early");
      S.Fire (First + Milliseconds (7), Fired, Elapsed);
      Assert (Fired, "due");
      Assert (S.Due_At = First + P, "next on the grid despite a late call (no drift)");
      --  A long stall: missed periods are skipped, the grid is kept.
      S.Fire (First + P * 4 + Milliseconds (50), Fired, Elapsed);
      Assert (Fired, "fires after a stall");
      Assert (S.Due_At = First + P * 5, "skips to the next grid point");
      Assert (abs (Elapsed - 0.443) < 0.000_001, "elapsed since the previous call");
   end Grid;

   procedure Cancel_Reset (Unused : in out Fixture) is
      S       : aliased State (Period_Ns => 100_000_000);
      T       : Timer;
      Fired   : Boolean;
      Elapsed : Duration;
   begin
      S.Start;
      T := To_Timer (S'Unchecked_Access);
      Assert (abs (T.Period - 0.1) < 1.0e-9, "period");
      T.Cancel;
      Assert (T.Is_Canceled, "canceled");
      Assert (S.Due_At = Time_Last, "a canceled timer is never due");
      S.Fire (Clock + Seconds (10), Fired, Elapsed);
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
      Result.Add_Test (Caller.Create ("timers: cancel and reset", Cancel_Reset'Access));
      return Result;
   end Suite;

end RCL.Timers.Tests;
