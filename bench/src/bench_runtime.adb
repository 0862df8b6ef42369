--  Benchmark of the component runtime (run by bench/bench-runtime.sh):
--  1. lateness of a 100 Hz periodic component run by the scheduler task on
--     the real clock (how late each Run starts after its due time);
--  2. database puts per second with 0, 1 and 10 listeners on the key.
--
--     bench_runtime [--seconds S] [--puts N] [--csv FILE]
--
--  Prints a table and, with --csv, writes "metric,value" rows.
with Ada.Command_Line;
with Ada.Containers.Generic_Array_Sort;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Schedulers;
with Sancta.Runtime.Values;
with Bench_Arguments;
with Bench_Runtime_Support;

procedure Bench_Runtime is
   use Ada.Real_Time;
   use Ada.Text_IO;
   use Sancta.Runtime;
   use Bench_Runtime_Support;

   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_runtime [--seconds S] [--puts N] [--csv FILE]" & ASCII.LF
      & "component runtime benchmark (bench/bench-runtime.sh): lateness of a 100 Hz"
      & ASCII.LF & "periodic component, database puts per second with 0, 1, 10 listeners"
      & ASCII.LF
      & "  --seconds S   how long the periodic component runs (default 10)" & ASCII.LF
      & "  --puts N      database puts per listener count (default 200000)" & ASCII.LF
      & "  --csv FILE    also write ""metric,value"" rows there",
      Min => 0, Max => Natural'Last);
   pragma Unreferenced (Read);
   Seconds_Run : Duration := 10.0;
   Puts        : Positive := 200_000;
   CSV_Name    : Ada.Strings.Unbounded.Unbounded_String;

   type Listener_Counts is array (Positive range <>) of Natural;

   procedure Sort is new Ada.Containers.Generic_Array_Sort (Positive, Long_Float, Micros_Array);

   function Image (X : Long_Float) return String is
      Rounded : constant Long_Long_Integer := Long_Long_Integer (X * 10.0);
      Whole   : constant String := Long_Long_Integer'Image (Rounded / 10);
      Tenth   : constant String := Long_Long_Integer'Image (abs Rounded mod 10);
   begin
      return Whole (Whole'First + 1 .. Whole'Last) & "." & Tenth (Tenth'Last .. Tenth'Last);
   end Image;

   CSV : File_Type;

   procedure Row (Metric : String; Value : Long_Float; Unit : String) is
   begin
      Put_Line ("  " & Metric & [1 .. 34 - Metric'Length => ' '] & Image (Value) & " " & Unit);
      if Is_Open (CSV) then
         Put_Line (CSV, Metric & "," & Image (Value));
      end if;
   end Row;

   I : Positive := 1;
begin
   while I <= Ada.Command_Line.Argument_Count loop
      declare
         A : constant String := Ada.Command_Line.Argument (I);
      begin
         if A not in "--seconds" | "--puts" | "--csv" then
            Bench_Arguments.Fail ("unknown option " & A);
         elsif I = Ada.Command_Line.Argument_Count then
            Bench_Arguments.Fail ("option " & A & " needs a value");
         elsif A = "--seconds" then
            Seconds_Run := Bench_Arguments.Seconds (I + 1, "--seconds", Default => 10.0);
         elsif A = "--puts" then
            Puts := Bench_Arguments.Count (I + 1, "--puts", Minimum => 1);
         else
            CSV_Name := Ada.Strings.Unbounded.To_Unbounded_String
              (Ada.Command_Line.Argument (I + 1));
         end if;
         I := I + 2;
      end;
   end loop;
   if Ada.Strings.Unbounded.Length (CSV_Name) > 0 then
      Bench_Arguments.Create_Output (CSV, Ada.Strings.Unbounded.To_String (CSV_Name), "--csv");
      Put_Line (CSV, "metric,value");
   end if;

   --  1. Periodic lateness.
   declare
      Clock : aliased Clocks.Real_Clock;
      DB    : aliased Local_Databases.Database;
      S     : Schedulers.Scheduler;
      C     : constant Components.Component_Access := new Sampler;
   begin
      C.Initialize ((Clock => Clock'Unchecked_Access, Database => DB'Unchecked_Access,
                     Instance_Name => Ada.Strings.Unbounded.To_Unbounded_String ("sampler"),
                     others => <>));
      S.Initialize (Clock'Unchecked_Access, "bench");
      S.Add (C, Clock.Now + Milliseconds (10));
      S.Start;
      delay Seconds_Run;
      S.Stop;
      Sort (Samples (1 .. Samples_Count));
      Put_Line ("periodic 100 Hz component, scheduler task, real clock ("
                & Samples_Count'Image & " activations):");
      Row ("sancta_lateness_median_us", Samples ((Samples_Count + 1) / 2), "us");
      Row ("sancta_lateness_p99_us",
           Samples (Positive'Min (Samples_Count, Positive (Long_Float'Ceiling
             (0.99 * Long_Float (Samples_Count))))), "us");
      Row ("sancta_lateness_max_us", Samples (Samples_Count), "us");
      Row ("sancta_activations", Long_Float (Samples_Count), "");
   end;

   --  2. Database puts per second.
   Put_Line ("database puts (one writer, one key, Real_Value):");
   for Listeners of Listener_Counts'(0, 1, 10) loop
      declare
         DB       : Local_Databases.Database;
         Watchers : array (1 .. 10) of aliased Counting;
         Start    : Time;
         Elapsed  : Duration;
      begin
         for L in 1 .. Listeners loop
            DB.Listen ("k", Watchers (L)'Unchecked_Access);
         end loop;
         Start := Clock;
         for P in 1 .. Puts loop
            DB.Put ("k", Values.Real_Value'(Data => Long_Float (P)));
         end loop;
         Elapsed := To_Duration (Clock - Start);
         for L in 1 .. Listeners loop
            if Watchers (L).N /= Puts then
               raise Program_Error with "listener missed notifications";
            end if;
         end loop;
         declare
            Tag : constant String := Listeners'Image;
         begin
            Row ("db_puts_per_s_" & Tag (Tag'First + 1 .. Tag'Last) & "_listeners",
                 Long_Float (Puts) / Long_Float (Elapsed), "puts/s");
         end;
      end;
   end loop;
   if Is_Open (CSV) then
      Close (CSV);
   end if;
end Bench_Runtime;
