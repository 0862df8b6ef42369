--  CDR encode/decode throughput of the Ada codec (the Ada side of
--  bench/bench-cdr.sh): sensor_msgs/LaserScan with 720 ranges and
--  nav_msgs/OccupancyGrid of 1000 x 1000 cells, encoded to a new buffer and
--  decoded to a new message each time (as the Python peer does).
--     bench_cdr [SECONDS] [CSV-FILE]
--  prints "case,op,impl,bytes,iterations,seconds,msgs_per_s,mb_per_s" lines.
with Ada.Real_Time;
with Ada.Streams;
with Bench_Arguments;
with Bench_Rows;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

procedure Bench_CDR is
   use Ada.Real_Time;
   use Ada.Streams;
   use ROSIDL;
   use ROSIDL.Dynamic;
   use ROSIDL.Typesupport;
   use type ROSIDL.Float32;

   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_cdr [SECONDS] [CSV-FILE]" & ASCII.LF
      & "CDR encode/decode throughput of the Ada codec (bench/bench-cdr.sh), LaserScan"
      & ASCII.LF & "with 720 ranges and OccupancyGrid 1000 x 1000; prints CSV rows" & ASCII.LF
      & "  SECONDS    time per case and operation (default 1)" & ASCII.LF
      & "  CSV-FILE   also write the rows there",
      Min => 0, Max => 2);
   pragma Unreferenced (Read);
   Budget : constant Duration := Bench_Arguments.Seconds (1, "SECONDS", Default => 1.0);

   Sink : Stream_Element := 0 with Volatile;
   --  Keeps the encoded bytes observable.

   function Laser_Scan return Message is
      Ranges : Float32_Array (1 .. 720);
   begin
      return M : constant Message :=
        Init (Get_Message_Support ("sensor_msgs", "LaserScan"))
      do
         M ("header")("stamp")("sec").As_Int32 := 1_700_000_000;
         M ("header")("frame_id").Set_String ("base_scan");
         M ("angle_min").As_Float32 := -3.14159;
         M ("angle_max").As_Float32 := 3.14159;
         M ("angle_increment").As_Float32 := 2.0 * 3.14159 / 720.0;
         M ("range_max").As_Float32 := 30.0;
         for I in Ranges'Range loop
            Ranges (I) := 0.5 + Float32 (I mod 97) * 0.25;
         end loop;
         M ("ranges").Set_Float32_Array (Ranges);
      end return;
   end Laser_Scan;

   function Occupancy_Grid return Message is
      Cells : Int8_Array (1 .. 1_000 * 1_000);
   begin
      return M : constant Message :=
        Init (Get_Message_Support ("nav_msgs", "OccupancyGrid"))
      do
         M ("header")("frame_id").Set_String ("map");
         M ("info")("resolution").As_Float32 := 0.05;
         M ("info")("width").As_UInt32 := 1_000;
         M ("info")("height").As_UInt32 := 1_000;
         for I in Cells'Range loop
            Cells (I) := Int8 ((I mod 3) * 50 - 1);
         end loop;
         M ("data").Set_Int8_Array (Cells);
      end return;
   end Occupancy_Grid;

   procedure Report (Case_Name, Op : String; Bytes, Iterations : Natural;
                     Seconds : Duration) is
      Rate : constant Long_Float := Long_Float (Iterations) / Long_Float (Seconds);
      Line : constant String :=
        Case_Name & "," & Op & ",ada," & Bytes'Image (2 .. Bytes'Image'Last) & ","
        & Iterations'Image (2 .. Iterations'Image'Last) & "," & Seconds'Image (2 .. 9)
        & "," & Long_Float'Image (Rate) & ","
        & Long_Float'Image (Rate * Long_Float (Bytes) / 1.0E6);
   begin
      Bench_Rows.Put (Line);
   end Report;

   procedure Measure (Case_Name : String; Msg : Message) is
      Data      : constant Stream_Element_Array := ROSIDL.CDR.Encode (Msg);
      Support_M : constant Message_Support := Support (Msg);
      Count     : Natural;
      Start     : Time;
      Elapsed   : Duration;
   begin
      --  Encode: a new buffer per message.
      Count := 0;
      Start := Clock;
      loop
         declare
            Bytes : constant Stream_Element_Array := ROSIDL.CDR.Encode (Msg);
         begin
            Sink := Bytes (Bytes'Last - 7);
         end;
         Count := Count + 1;
         Elapsed := To_Duration (Clock - Start);
         exit when Elapsed >= Budget and then Count >= 3;
      end loop;
      Report (Case_Name, "encode", Data'Length, Count, Elapsed);
      --  Decode: a new message per buffer.
      Count := 0;
      Start := Clock;
      loop
         declare
            Back : constant Message := ROSIDL.CDR.Decode (Support_M, Data);
         begin
            if Count = 0 and then Back /= Msg then
               raise Program_Error with Case_Name & ": decoded message differs";
            end if;
         end;
         Count := Count + 1;
         Elapsed := To_Duration (Clock - Start);
         exit when Elapsed >= Budget and then Count >= 3;
      end loop;
      Report (Case_Name, "decode", Data'Length, Count, Elapsed);
   end Measure;

begin
   Bench_Rows.Open (CSV_Argument => 2);
   Measure ("laser_scan_720", Laser_Scan);
   Measure ("occupancy_grid_1000x1000", Occupancy_Grid);
   Bench_Rows.Close;
end Bench_CDR;
