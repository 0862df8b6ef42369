with Ada.Real_Time;           use Ada.Real_Time;
with AUnit.Assertions;        use AUnit.Assertions;
with Sancta.Allocation.Budget_Clocks;
with Sancta.Allocation.Local_Search;
with Sancta.Allocation.Test_Support; use Sancta.Allocation.Test_Support;
with Suite_Support; use Suite_Support;

package body Sancta.Allocation.Replanning.Tests is

   --  Old task numbers of robot R's tour in A, mapped to Q's numbers.
   function In_Order (Sub : Count_Array; A : Assignment; R : Positive) return Boolean is
      K : Natural := Sub'First;
   begin
      for I in 1 .. A.Length (R) loop
         if K <= Sub'Last and then A.Tour (R, I) = Sub (K) then
            K := K + 1;
         end if;
      end loop;
      return K > Sub'Last;
   end In_Order;

   procedure Loss_Starts_From_Current_Plan (Unused : in out Fixture) is
      P : constant Problem_Access := Scattered (40, Seed => 7, Robots => 3);
      Current : Assignment (3, 40);
      Stats : Annealers.Progress;
   begin
      Annealers.Solve (P.all, (Criterion => Min_Max, Seed => 1, Time_Limit => 0.0,
                               Iterations => 20_000, others => <>), Current, Stats);
      declare
         Done : constant Count_Array := [for R in 1 .. 3 => Natural'Min (2, Current.Length (R))];
         Kept : constant Count_Array := Remaining_Tasks (P.all, Current, 2, Done);
         Q : constant Problem_Access := Without_Robot (P.all, Current, 2, Done, Kept);
         Start : Assignment := Carried_Over (P.all, Q.all, Current, 2, Done, Kept, Min_Max);
         Trace : Quality_Trace (Capacity => 100);
         Number : Count_Array (1 .. 40) := [others => 0];
         Began : constant Time := Clock;
         Took : Duration;
      begin
         Assert (Kept'Length = 40 - Done (2), "the lost robot's done tasks leave");
         Assert (Q.Robots = 2, "two survivors");
         Assert (Validate (Q.all, Start) = "", "start: " & Validate (Q.all, Start));
         for I in Kept'Range loop
            Number (Kept (I)) := I;
         end loop;
         --  The survivors' tours are kept in order (old robots 1 and 3).
         for New_R in 1 .. 2 loop
            declare
               Old_R : constant Positive := (if New_R = 1 then 1 else 3);
            begin
               Assert (In_Order ([for I in 1 .. Current.Length (Old_R) =>
                                    Number (Current.Tour (Old_R, I))], Start, New_R),
                       "survivor" & Old_R'Image & "'s tour is not kept in the start");
            end;
         end loop;
         Improve (Q.all, Start, (Criterion => Min_Max, Seed => 2, Time_Limit => 0.05,
                                 others => <>), Trace);
         Took := To_Duration (Clock - Began);
         Assert (Validate (Q.all, Start) = "", "re-plan: " & Validate (Q.all, Start));
         for R in 1 .. 2 loop
            Assert (Start.Tour (R, 1) = Q.Frozen (R, 1)
                    and then Start.Tour (R, 2) = Q.Frozen (R, 2), "a frozen prefix moved");
         end loop;
         Assert (Trace.Last >= 2, "no trace");
         Assert (Trace.Samples (1).Elapsed = 0.0, "the trace starts at 0 s");
         for I in 2 .. Trace.Last loop
            Assert (Trace.Samples (I).Elapsed >= Trace.Samples (I - 1).Elapsed,
                    "the samples' times go back at sample" & I'Image);
         end loop;
         Assert (Trace.Samples (Trace.Last).Value <= Trace.Samples (1).Value,
                 "the re-plan is worse than its start");
         Assert (Trace.Samples (Trace.Last).Value = Evaluate (Q.all, Start, Min_Max).Value,
                 "the last sample is not the plan's value");
         Assert (Took < 1.0, "a 50 ms re-plan took" & Took'Image & " s");
      end;
   end Loss_Starts_From_Current_Plan;

   procedure Budgets_From_50_Ms (Unused : in out Fixture) is
      use Budget_Clocks;
   begin
      --  A team and a large single tour (the search alone from a
      --  nearest-neighbour tour): the time used stays near the budget. On
      --  the CPU clock (the test task's CPU time), so that the check does
      --  not depend on the machine's load.
      for Robots in 1 .. 2 loop
         declare
            Tasks : constant Positive := (if Robots = 1 then 1_100 else 150);
            P : constant Problem_Access :=
              Scattered (Tasks, Seed => 3, Robots => (if Robots = 1 then 1 else 5));
            A : Assignment (P.Robots, Tasks);
            Stats : Annealers.Progress;
            Began : constant Time := Clock (CPU_Time);
            Took : Duration;
            Budget : constant Duration := (if Robots = 1 then 0.5 else 0.05);
         begin
            Annealers.Solve (P.all, (Criterion => Min_Max, Seed => 1, Time_Limit => Budget,
                                     Budget_Clock => CPU_Time, Local_Search => 0.8,
                                     others => <>), A, Stats);
            Took := To_Duration (Clock (CPU_Time) - Began);
            Assert (Validate (P.all, A) = "", Validate (P.all, A));
            Assert (Took < Budget + 0.5, Tasks'Image & " tasks: budget" & Budget'Image
                    & " s of CPU, took" & Took'Image & " s");
            Assert (Stats.Elapsed >= Budget * 0.5, "stopped early:" & Stats.Elapsed'Image);
            if Robots = 1 then
               Assert (Evaluate (P.all, A, Min_Sum).Sum
                       < Evaluate (P.all, Local_Search.Nearest_Neighbour_Tour (P.all), Min_Sum).Sum,
                       "not shorter than the nearest-neighbour tour");
            end if;
         end;
      end loop;
   end Budgets_From_50_Ms;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
      procedure Add (Name : String; Proc : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("re-planning: " & Name, Proc));
      end Add;
   begin
      Add ("a robot loss starts from the current plan; quality over time",
           Loss_Starts_From_Current_Plan'Access);
      Add ("budgets from 50 ms", Budgets_From_50_Ms'Access);
      return Result;
   end Suite;

end Sancta.Allocation.Replanning.Tests;
