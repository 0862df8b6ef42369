with AUnit.Assertions;
with Sancta.Logging;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Values;
with Suite_Support; use Suite_Support;

package body Sancta.Runtime.Schedulers.Tests is

   use AUnit.Assertions;
   use Ada.Strings.Unbounded;
   use type Clocks.Time;

   Trace : Unbounded_String;
   --  "A@0 B@0 ..." : component name and milliseconds since the epoch.

   function Millis (T : Clocks.Time) return String is
      S : constant String := Long_Long_Integer'Image
        (Long_Long_Integer (To_Duration (T - Clocks.Epoch) * 1000.0));
   begin
      return S (S'First + 1 .. S'Last);
   end Millis;

   --  A periodic component that records its calls, "works" for Cost on
   --  the manual clock, and raises in its first Fail_Calls calls.
   type Recorder is new Components.Component with record
      Label      : Unbounded_String;
      Period     : Time_Span;
      Cost       : Time_Span := Time_Span_Zero;
      Fail_Calls : Natural := 0;
      Calls      : Natural := 0;
   end record;

   overriding procedure Run (This : in out Recorder; Next : in out Clocks.Time);

   type Recorder_Access is access all Recorder;

   overriding procedure Run (This : in out Recorder; Next : in out Clocks.Time) is
   begin
      This.Calls := This.Calls + 1;
      Append (Trace, (if Length (Trace) > 0 then " " else "") & This.Label & "@"
              & Millis (This.Now));
      Clocks.Manual_Clock (This.Ctx.Clock.all).Advance (This.Cost);
      if This.Calls <= This.Fail_Calls then
         raise Constraint_Error with "failure" & This.Calls'Image;
      end if;
      Next := Next + This.Period;
   end Run;

   function New_Recorder
     (Clock      : Clocks.Clock_Access;
      DB         : Local_Databases.Database_Access;
      Label      : String;
      Period_Ms  : Natural;
      Cost_Ms    : Natural := 0;
      Fail_Calls : Natural := 0;
      Policy     : Components.Error_Policy := Components.Retry)
      return Components.Component_Access
   is
      Result : constant Recorder_Access := new Recorder;
   begin
      Result.Initialize
        ((Agent_Id => To_Unbounded_String ("Test"), Instance_Name => To_Unbounded_String (Label),
          Database => DB, Clock => Clock, Policy => Policy, Retry_After => Milliseconds (500),
          others => <>));
      Result.Label := To_Unbounded_String (Label);
      Result.Period := Milliseconds (Period_Ms);
      Result.Cost := Milliseconds (Cost_Ms);
      Result.Fail_Calls := Fail_Calls;
      return Components.Component_Access (Result);
   end New_Recorder;

   procedure Run_Until (S : in out Scheduler; Limit_Ms : Natural) is
      --  Steps while a call is due at or before Epoch + Limit_Ms.
   begin
      while S.Next_Due <= Clocks.Epoch + Milliseconds (Limit_Ms) loop
         S.Step;
      end loop;
   end Run_Until;

   --  Three periods; ties are served in the order the calls were queued.
   procedure Order_And_Periods (Unused : in out Fixture) is
      Clock : aliased Clocks.Manual_Clock;
      DB    : aliased Local_Databases.Database;
      S     : Scheduler;
   begin
      Trace := Null_Unbounded_String;
      S.Initialize (Clock'Unchecked_Access, "test");
      S.Add (New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "A", 10), Clock.Now);
      S.Add (New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "B", 20), Clock.Now);
      S.Add (New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "C", 30), Clock.Now);
      Run_Until (S, 60);
      Assert (To_String (Trace) =
                "A@0 B@0 C@0 A@10 B@20 A@20 C@30 A@30 B@40 A@40 A@50 C@60 B@60 A@60",
              "trace: " & To_String (Trace));
   end Order_And_Periods;

   --  A component that works 3 ms of its 10 ms period is still called at
   --  0, 10, 20, ... (next = previous due + period, not now + period).
   procedure Drift_Free (Unused : in out Fixture) is
      Clock : aliased Clocks.Manual_Clock;
      DB    : aliased Local_Databases.Database;
      S     : Scheduler;
      C     : constant Components.Component_Access :=
        New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "A", 10, Cost_Ms => 3);
   begin
      Trace := Null_Unbounded_String;
      S.Initialize (Clock'Unchecked_Access, "test");
      S.Add (C, Clock.Now);
      Run_Until (S, 50);
      Assert (To_String (Trace) = "A@0 A@10 A@20 A@30 A@40 A@50", "trace: " & To_String (Trace));
      Assert (S.Stats (C).Calls = 6, "calls");
      Assert (S.Stats (C).Overruns = 0, "no overrun");
      Assert (S.Stats (C).Max_Run = Milliseconds (3), "run time measured on the clock");
      Assert (S.Stats (C).Max_Lateness = Time_Span_Zero, "never late");
   end Drift_Free;

   --  15 ms of work every 10 ms: every call overruns, lateness grows, and
   --  the "cannot keep up" warning comes once the lateness passes the limit.
   procedure Overruns (Unused : in out Fixture) is
      Clock  : aliased Clocks.Manual_Clock;
      DB     : aliased Local_Databases.Database;
      S      : Scheduler;
      C      : constant Components.Component_Access :=
        New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "A", 10, Cost_Ms => 15);
      Warned : Natural;
   begin
      Trace := Null_Unbounded_String;
      Logging.Set_Console (False);
      Warned := Logging.Printed (Logging.Warning);
      S.Initialize (Clock'Unchecked_Access, "test", Keep_Up_Limit => Milliseconds (15));
      S.Add (C, Clock.Now);
      for I in 1 .. 4 loop
         S.Step;
      end loop;
      Logging.Set_Console (True);
      --  Due 0, 10, 20, 30, 40, 50, 60; started 0, 15, 30, 45, 60, 75, 90.
      --  Step 3 (entered at 30) runs the calls due at 20 and 30; step 4
      --  (entered at 60) those due at 40, 50 and 60: the periods keep their
      --  phase and the missed activations are caught up.
      Assert (To_String (Trace) = "A@0 A@15 A@30 A@45 A@60 A@75 A@90",
              "trace: " & To_String (Trace));
      Assert (S.Stats (C).Overruns = 7, "overruns:" & S.Stats (C).Overruns'Image);
      Assert (S.Stats (C).Max_Lateness = Milliseconds (30), "max lateness");
      Assert (S.Stats (C).Late_Calls = 3, "calls more than 15 ms late (due 40, 50, 60)");
      Assert (Logging.Printed (Logging.Warning) >= Warned + 2, "overrun and keep-up warnings");
   end Overruns;

   --  Retry: two failures, each retried 500 ms later, then normal periods;
   --  Stop: one failure and no more calls. The other component goes on.
   procedure Failure_Policies (Unused : in out Fixture) is
      Clock   : aliased Clocks.Manual_Clock;
      DB      : aliased Local_Databases.Database;
      S       : Scheduler;
      Retried : constant Components.Component_Access :=
        New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "R", 100, Fail_Calls => 2);
      Stopped : constant Components.Component_Access :=
        New_Recorder (Clock'Unchecked_Access, DB'Unchecked_Access, "S", 100, Fail_Calls => 1,
                      Policy => Components.Stop);
      Errors  : Natural;
   begin
      Trace := Null_Unbounded_String;
      Logging.Set_Console (False);
      Errors := Logging.Printed (Logging.Error);
      S.Initialize (Clock'Unchecked_Access, "test");
      S.Add (Retried, Clock.Now);
      S.Add (Stopped, Clock.Now);
      Run_Until (S, 1200);
      Logging.Set_Console (True);
      Assert (To_String (Trace) = "R@0 S@0 R@500 R@1000 R@1100 R@1200",
              "trace: " & To_String (Trace));
      Assert (S.Stats (Retried).Failures = 2, "two failures");
      Assert (not Retried.Failed and then Stopped.Failed, "policies");
      Assert (Logging.Printed (Logging.Error) = Errors + 3, "each failure logged");
      Assert (Contains (Logging.Last_Message, "component R of agent Test failed"),
              Logging.Last_Message);
   end Failure_Policies;

   --  An event-driven component: doubles each stored input.
   type Doubler is new Components.Base_Component with record
      Seen : Natural := 0;
   end record;

   overriding procedure Start (This : in out Doubler);

   type Doubler_Access is access all Doubler;
   overriding procedure On_Input
     (This : in out Doubler; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Doubler) is
   begin
      This.Subscribe ("input");
   end Start;

   overriding procedure On_Input
     (This : in out Doubler; Data : String; Item : Values.Value'Class) is
   begin
      This.Seen := This.Seen + 1;
      if Values.Real_Value (Item).Data < 0.0 then
         raise Constraint_Error with "negative " & Data;
      end if;
      This.Output ("output", Values.Real_Value'(Data => 2.0 * Values.Real_Value (Item).Data));
   end On_Input;

   procedure Event_Driven (Unused : in out Fixture) is
      Clock : aliased Clocks.Manual_Clock;
      DB    : aliased Local_Databases.Database;
      D     : constant Doubler_Access := new Doubler;
      E     : constant Doubler_Access := new Doubler;
      Ctx   : Components.Context :=
        (Agent_Id => To_Unbounded_String ("Test"), Instance_Name => To_Unbounded_String ("dbl"),
         Database => DB'Unchecked_Access, Clock => Clock'Unchecked_Access,
         Policy => Components.Retry, others => <>);
   begin
      Ctx.Inputs.Include ("input", "x");
      Ctx.Outputs.Include ("output", "y");
      D.Initialize (Ctx);
      D.Start;
      DB.Put ("x", Values.Real_Value'(Data => 1.5));
      Assert (Values.Real_Value (DB.Get ("y")).Data = 3.0, "doubled");
      Logging.Set_Console (False);
      DB.Put ("x", Values.Real_Value'(Data => -1.0));
      Logging.Set_Console (True);
      Assert (D.Failures = 1 and then not D.Failed, "failure reported, retry policy");
      DB.Put ("x", Values.Real_Value'(Data => 2.0));
      Assert (Values.Real_Value (DB.Get ("y")).Data = 4.0, "still working");
      D.Stop;
      DB.Put ("x", Values.Real_Value'(Data => 5.0));
      Assert (D.Seen = 3, "no calls after Stop");

      --  An output checked as types.integer refuses the doubler's reals.
      Ctx.Output_Types.Include ("output", "types.integer");
      Ctx.Policy := Components.Stop;
      Ctx.Instance_Name := To_Unbounded_String ("typed");
      E.Initialize (Ctx);
      E.Start;
      Logging.Set_Console (False);
      DB.Put ("x", Values.Real_Value'(Data => 1.0));
      Logging.Set_Console (True);
      Assert (E.Failed, "wrong output type is a failure of the component");
      Assert (Values.Real_Value (DB.Get ("y")).Data = 4.0, "nothing stored");
      Assert (Contains
                (Logging.Last_Message,
                 "output 'output' of typed is of type types.integer, but a value of type "
                 & "types.real was written"), Logging.Last_Message);
   end Event_Driven;

   --  A component counting its inputs without protection of its own: the
   --  component's lock must serialise the calls made by several writers.
   type Counter_Component is new Components.Base_Component with record
      Count   : Natural := 0;
      Inside  : Boolean := False;
      Overlap : Boolean := False;
   end record;

   overriding procedure Start (This : in out Counter_Component);
   overriding procedure On_Input
     (This : in out Counter_Component; Data : String; Item : Values.Value'Class);

   type Counter_Access is access all Counter_Component;

   overriding procedure Start (This : in out Counter_Component) is
   begin
      This.Subscribe ("a");
      This.Subscribe ("b");
   end Start;

   overriding procedure On_Input
     (This : in out Counter_Component; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data, Item);
      Seen : constant Natural := This.Count;
   begin
      if This.Inside then
         This.Overlap := True;
      end if;
      This.Inside := True;
      delay 0.0;
      --  Yield: without the component's lock another writer's call would
      --  now run and one of the two counts would be lost.
      This.Count := Seen + 1;
      This.Inside := False;
   end On_Input;

   procedure Serialised_Inputs (Unused : in out Fixture) is
      Clock : aliased Clocks.Manual_Clock;
      DB    : aliased Local_Databases.Database;
      C     : constant Counter_Access := new Counter_Component;
      Ctx   : Components.Context :=
        (Agent_Id => To_Unbounded_String ("Test"), Instance_Name => To_Unbounded_String ("cnt"),
         Database => DB'Unchecked_Access, Clock => Clock'Unchecked_Access, others => <>);
      Rounds : constant := 500;
   begin
      Ctx.Inputs.Include ("a", "key_a");
      Ctx.Inputs.Include ("b", "key_b");
      C.Initialize (Ctx);
      C.Start;
      declare
         task type Writer (Key : access constant String);
         task body Writer is
         begin
            for I in 1 .. Rounds loop
               DB.Put (Key.all, Values.Integer_Value'(Data => Long_Long_Integer (I)));
            end loop;
         end Writer;
         A1 : aliased constant String := "key_a";
         B1 : aliased constant String := "key_b";
         W1 : Writer (A1'Access);
         W2 : Writer (B1'Access);
         W3 : Writer (A1'Access);
         W4 : Writer (B1'Access);
      begin
         null;
      end;
      Assert (not C.Overlap, "On_Input calls overlapped");
      Assert (C.Count = 4 * Rounds, "count:" & C.Count'Image);
   end Serialised_Inputs;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("scheduler: order and periods", Order_And_Periods'Access));
      Result.Add_Test (Caller.Create ("scheduler: drift-free periods", Drift_Free'Access));
      Result.Add_Test (Caller.Create ("scheduler: overruns and cannot keep up", Overruns'Access));
      Result.Add_Test (Caller.Create ("scheduler: retry and stop policies",
                                      Failure_Policies'Access));
      Result.Add_Test (Caller.Create ("components: event-driven base component",
                                      Event_Driven'Access));
      Result.Add_Test (Caller.Create ("components: concurrent inputs are serialised",
                                      Serialised_Inputs'Access));
      return Result;
   end Suite;

end Sancta.Runtime.Schedulers.Tests;
