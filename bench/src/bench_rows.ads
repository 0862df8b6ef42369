--  The rows a benchmark prints: each on standard output and, when the
--  command line names a CSV file, in that file too.
--
--     Bench_Rows.Open (CSV_Argument => 2);  --  bench_x [SECONDS] [CSV-FILE]
--     Bench_Rows.Put ("laser_scan_720,encode,ada,...");
--     Bench_Rows.Close;
package Bench_Rows is

   procedure Open (CSV_Argument : Positive);
   --  Creates the CSV file named by command-line argument CSV_Argument when
   --  there are that many arguments (Bench_Arguments.Fail when it cannot).

   procedure Put (Row : String);
   --  Writes Row on standard output and in the CSV file if there is one.

   procedure Close;
   --  Closes the CSV file if there is one.

end Bench_Rows;
