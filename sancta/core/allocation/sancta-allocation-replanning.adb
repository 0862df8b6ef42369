with Ada.Real_Time;
with Sancta.Allocation.Budget_Clocks;

package body Sancta.Allocation.Replanning is

   function Remaining_Tasks
     (P : Problem; Current : Assignment; Lost : Positive; Done : Count_Array)
      return Count_Array
   is
      Gone : Boolean_Array (1 .. P.Tasks) := [others => False];
      Count : Natural := 0;
   begin
      for K in 1 .. Done (Lost) loop
         Gone (Current.Tour (Lost, K)) := True;
      end loop;
      for T in Gone'Range loop
         if not Gone (T) then
            Count := Count + 1;
         end if;
      end loop;
      return Kept : Count_Array (1 .. Count) do
         Count := 0;
         for T in Gone'Range loop
            if not Gone (T) then
               Count := Count + 1;
               Kept (Count) := T;
            end if;
         end loop;
      end return;
   end Remaining_Tasks;

   --  The new number of every old task (0: gone).
   function New_Numbers (P : Problem; Kept : Count_Array) return Count_Array is
      Number : Count_Array (1 .. P.Tasks) := [others => 0];
   begin
      for I in Kept'Range loop
         Number (Kept (I)) := I - Kept'First + 1;
      end loop;
      return Number;
   end New_Numbers;

   function Old_Robot (Lost, R : Positive) return Positive is (if R < Lost then R else R + 1);

   function Without_Robot
     (P : Problem; Current : Assignment; Lost : Positive; Done : Count_Array;
      Kept : Count_Array) return Problem_Access
   is
      Extra : Natural := 0;
      Number : constant Count_Array := New_Numbers (P, Kept);
   begin
      for T of Kept loop
         if P.Alt_Count (T) > 1 then
            Extra := Extra + P.Alt_Count (T);
         end if;
      end loop;
      return Q : constant Problem_Access :=
        Create (P.Locations, Kept'Length, P.Robots - 1, Extra)
      do
         Copy_Distances (P, Q.all);
         Q.Min_Tasks := P.Min_Tasks;
         Q.Name := P.Name;
         for I in Kept'Range loop
            declare
               T : constant Positive := Kept (I);
               New_T : constant Positive := I - Kept'First + 1;
            begin
               Set_Task_Alternatives
                 (Q.all, New_T,
                  [for K in 1 .. P.Alt_Count (T) => Location_Of (P, T, K)]);
               if Natural (P.Task_Names.Length) >= T then
                  Q.Task_Names.Append (P.Task_Names (T));
               end if;
            end;
         end loop;
         for R in 1 .. Q.Robots loop
            declare
               From : constant Positive := Old_Robot (Lost, R);
            begin
               Set_Robot (Q.all, R, P.Start (From), Closed => True,
                          Multiplier => P.Multiplier (From));
               Set_Robot_End (Q.all, R, P.Finish (From));
               Q.Own (R) := P.Own (From);
               Q.Own_Factor (R) := P.Own_Factor (From);
               for I in Kept'Range loop
                  if not P.Can_Do (From, Kept (I)) then
                     Forbid (Q.all, R, I - Kept'First + 1);
                  end if;
               end loop;
               Freeze (Q.all, R, [for K in 1 .. Done (From) => Number (Current.Tour (From, K))]);
            end;
         end loop;
      end return;
   end Without_Robot;

   function Carried_Over
     (P, Q : Problem; Current : Assignment; Lost : Positive; Done : Count_Array;
      Kept : Count_Array; C : Criterion) return Assignment
   is
      Number : constant Count_Array := New_Numbers (P, Kept);
      Makespan : constant Boolean := C.Max_Weight > 0.0;
   begin
      return A : Assignment (Q.Robots, Q.Tasks) do
         for I in Kept'Range loop
            A.Choice (I - Kept'First + 1) := Current.Choice (Kept (I));
         end loop;
         for R in 1 .. Q.Robots loop
            declare
               From : constant Positive := Old_Robot (Lost, R);
            begin
               for K in 1 .. Current.Length (From) loop
                  Append (A, R, Number (Current.Tour (From, K)));
               end loop;
            end;
         end loop;
         for K in Done (Lost) + 1 .. Current.Length (Lost) loop
            declare
               T : constant Positive := Number (Current.Tour (Lost, K));
               Here : constant Positive := Location_Of (Q, T, A.Choice (T));
               Best_Robot : Natural := 0;
               Best_After : Natural := 0;
               Best_Key, Best_Added : Cost := Cost'Last;
            begin
               for R in 1 .. Q.Robots loop
                  if Q.Can_Do (R, T) then
                     declare
                        Robot_Cost : constant Cost := Tour_Cost (Q, A, R);
                     begin
                        for After in Q.Frozen_Length (R) .. A.Length (R) loop
                           declare
                              Added : constant Cost := Insertion_Cost (Q, A, R, Here, After);
                              Key : constant Cost :=
                                (if Makespan then Robot_Cost + Added else Added);
                           begin
                              if Key < Best_Key or else (Key = Best_Key and then Added < Best_Added)
                              then
                                 Best_Key := Key;
                                 Best_Added := Added;
                                 Best_Robot := R;
                                 Best_After := After;
                              end if;
                           end;
                        end loop;
                     end;
                  end if;
               end loop;
               if Best_Robot = 0 then
                  raise Constraint_Error with "task" & Kept (Kept'First + T - 1)'Image
                    & " of the lost robot: no other robot can do it";
               end if;
               Insert (A, Best_Robot, T, Best_After);
            end;
         end loop;
      end return;
   end Carried_Over;

   protected Recorder is
      entry Seize;
      procedure Release;
      procedure Start (Capacity : Positive);
      procedure Add (S : Sample);
      function Count return Natural;
      function Get (I : Positive) return Sample;
   private
      Busy : Boolean := False;
      Samples : Sample_Array (1 .. 1_000);
      Limit, Used : Natural := 0;
   end Recorder;

   protected body Recorder is
      entry Seize when not Busy is
      begin
         Busy := True;
      end Seize;

      procedure Release is
      begin
         Busy := False;
      end Release;

      procedure Start (Capacity : Positive) is
      begin
         Limit := Positive'Min (Capacity, Samples'Length);
         Used := 0;
      end Start;

      procedure Add (S : Sample) is
      begin
         if Used < Limit then
            Used := Used + 1;
         end if;
         Samples (Used) := S;   --  when full, the last one is replaced
      end Add;

      function Count return Natural is (Used);
      function Get (I : Positive) return Sample is (Samples (I));
   end Recorder;

   Offset : Duration := 0.0;
   --  Time spent before the annealer's clock started ...
   Current_Problem : access constant Problem;
   Current_Box : access Annealers.Best_Box;
   Current_Criterion : Criterion;
   --  ... and where the running re-plan's best plan is (set under Seize).

   procedure Record_Progress (P : Annealers.Progress) is
   begin
      if Current_Box.Has_Value then
         Recorder.Add ((Offset + P.Elapsed,
                        Evaluate (Current_Problem.all, Current_Box.Best, Current_Criterion).Value));
      end if;
   end Record_Progress;

   procedure Improve
     (Q     : aliased Problem;
      Plan  : in out Assignment;
      Opts  : Annealers.Options;
      Trace : out Quality_Trace)
   is
      use Ada.Real_Time;
      Started : constant Time := Budget_Clocks.Clock (Opts.Budget_Clock);
      O : Annealers.Options := Opts;
      Stats : Annealers.Progress;
      Box : aliased Annealers.Best_Box (Q.Robots, Q.Tasks);
   begin
      Trace.Samples := [others => (others => <>)];
      Recorder.Seize;
      Current_Problem := Q'Unchecked_Access;
      Current_Box := Box'Unchecked_Access;
      Current_Criterion := Opts.Criterion;
      O.Box := Box'Unchecked_Access;
      O.Report := Record_Progress'Access;
      Recorder.Start (Trace.Capacity);
      Recorder.Add ((0.0, Evaluate (Q, Plan, Opts.Criterion).Value));
      O.Initial := True;
      O.Report_Every := Duration'Min (Opts.Report_Every, Opts.Time_Limit / 10);
      Offset := To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started);
      O.Time_Limit := Duration'Max (0.01, Opts.Time_Limit - Offset);
      begin
         Annealers.Solve (Q, O, Plan, Stats);
      exception
         when others =>
            Recorder.Release;
            raise;
      end;
      Recorder.Add ((To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started),
                     Evaluate (Q, Plan, Opts.Criterion).Value));
      Trace.Last := Natural'Min (Recorder.Count, Trace.Capacity);
      for I in 1 .. Trace.Last loop
         Trace.Samples (I) := Recorder.Get (I);
      end loop;
      Recorder.Release;
   end Improve;

end Sancta.Allocation.Replanning;
