--  CDR encode/decode time per message of the generated (typed) codec
--  against the dynamic one, same messages, same run (the Ada side of
--  bench/bench-typed.sh): sensor_msgs/LaserScan with 720 ranges,
--  nav_msgs/Odometry, nav_msgs/OccupancyGrid of 1000 x 1000 cells. Encode
--  into a buffer kept across messages, decode into a message kept across
--  messages (the steady state of a publisher and a subscription).
--     bench_typed_cdr [SECONDS] [CSV-FILE] [DUMP-FOLDER]
--  prints "case,op,impl,bytes,iterations,ns_per_msg" lines; with a
--  DUMP-FOLDER, writes each case's typed encoding there as <case>.cdr (the
--  bench script compares them with the C encodings byte for byte).
with Ada.Command_Line;
with Ada.Real_Time;
with Ada.Streams;
with Ada.Streams.Stream_IO;
with Ada.Strings.Unbounded;
with Bench_Arguments;
with Bench_Rows;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Interfaces;
with ROSIDL.Typesupport;
with ROSIDL.Static.Message_Support;
with ROSIDL.Static.Nav_Msgs.Messages.OccupancyGrid;
with ROSIDL.Static.Nav_Msgs.Messages.Odometry;
with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;

procedure Bench_Typed_CDR is
   use Ada.Real_Time;
   use Ada.Streams;
   use type ROSIDL.Float32;
   use type ROSIDL.Float64;

   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_typed_cdr [SECONDS] [CSV-FILE] [DUMP-FOLDER]" & ASCII.LF
      & "time per message of the generated (typed) CDR codec against the dynamic one"
      & ASCII.LF & "(bench/bench-typed.sh); prints CSV rows" & ASCII.LF
      & "  SECONDS       time per case, operation and codec (default 1)" & ASCII.LF
      & "  CSV-FILE      also write the rows there" & ASCII.LF
      & "  DUMP-FOLDER   write each case's typed encoding there as <case>.cdr",
      Min => 0, Max => 3);
   pragma Unreferenced (Read);
   Budget : constant Duration := Bench_Arguments.Seconds (1, "SECONDS", Default => 1.0);
   Dumps   : constant String :=
     (if Ada.Command_Line.Argument_Count >= 3 then Ada.Command_Line.Argument (3) else "");
   Sink    : Stream_Element := 0 with Volatile;

   package Scans renames ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
   package Odometries renames ROSIDL.Static.Nav_Msgs.Messages.Odometry;
   package Grids renames ROSIDL.Static.Nav_Msgs.Messages.OccupancyGrid;

   function Scan return Scans.Message is
   begin
      return M : Scans.Message do
         M.Header.Stamp.Sec := 1_700_000_000;
         M.Header.Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("base_scan");
         M.Angle_Min := -3.14159;
         M.Angle_Max := 3.14159;
         M.Angle_Increment := 0.008_726_638_9;  --  as the C side (bench/typed_cdr_c.c)
         M.Range_Max := 30.0;
         M.Ranges.Set_Length (720);
         for I in 0 .. 719 loop
            M.Ranges (I) := 0.5 + ROSIDL.Float32 ((I + 1) mod 97) * 0.25;
         end loop;
      end return;
   end Scan;

   function Odometry return Odometries.Message is
   begin
      return M : Odometries.Message do
         M.Header.Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("odom");
         M.Child_Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("base_link");
         M.Pose.Pose.Position := (1.0, 2.0, 0.0);
         M.Pose.Pose.Orientation.W := 1.0;
         M.Pose.Covariance := [for I in 0 .. 35 => ROSIDL.Float64 (I) * 0.01];
         M.Twist.Twist.Linear.X := 0.5;
      end return;
   end Odometry;

   function Grid return Grids.Message is
   begin
      return M : Grids.Message do
         M.Header.Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("map");
         M.Info.Resolution := 0.05;
         M.Info.Width := 1_000;
         M.Info.Height := 1_000;
         M.Data.Set_Length (1_000_000);
         for I in 0 .. 999_999 loop
            M.Data (I) := ROSIDL.Int8 (((I + 1) mod 3) * 50 - 1);
         end loop;
      end return;
   end Grid;

   procedure Report (Case_Name, Op, Impl : String; Bytes, Iterations : Natural;
                     Seconds : Duration) is
      Ns   : constant Long_Float := Long_Float (Seconds) * 1.0E9 / Long_Float (Iterations);
      Line : constant String :=
        Case_Name & "," & Op & "," & Impl & "," & Bytes'Image (2 .. Bytes'Image'Last) & ","
        & Iterations'Image (2 .. Iterations'Image'Last) & ","
        & Long_Long_Integer'Image (Long_Long_Integer (Ns)) (2 .. Long_Long_Integer'Image
                                                                 (Long_Long_Integer (Ns))'Last);
   begin
      Bench_Rows.Put (Line);
   end Report;

   procedure Dump (Case_Name : String; Data : Stream_Element_Array) is
      use Ada.Streams.Stream_IO;
      File : Ada.Streams.Stream_IO.File_Type;
   begin
      if Dumps /= "" then
         Create (File, Out_File, Dumps & "/" & Case_Name & ".cdr");
         Write (File, Data);
         Close (File);
      end if;
   end Dump;

   generic
      with package Handling is new ROSIDL.Static.Message_Support (<>);
   procedure Measure (Case_Name : String; Typed_Msg : Handling.Message);

   procedure Measure (Case_Name : String; Typed_Msg : Handling.Message) is
      Data    : constant Stream_Element_Array := Handling.Encode (Typed_Msg);
      Dynamic : ROSIDL.Dynamic.Message :=
        ROSIDL.CDR.Decode (ROSIDL.Typesupport.To_Support
                             (ROSIDL.Interfaces.Message_By_DDS_Name (Handling.DDS_Type_Name)),
                           Data);
      Buffer  : Stream_Element_Array (1 .. Data'Length);
      Last    : Stream_Element_Offset;
      Kept    : Handling.Message;
      Count   : Natural;
      Start   : Time;
      Elapsed : Duration;

      procedure Run (Op, Impl : String; Step : not null access procedure) is
      begin
         Count := 0;
         Start := Clock;
         loop
            for Unused in 1 .. 10 loop
               Step.all;
            end loop;
            Count := Count + 10;
            Elapsed := To_Duration (Clock - Start);
            exit when Elapsed >= Budget;
         end loop;
         Report (Case_Name, Op, Impl, Data'Length, Count, Elapsed);
      end Run;

      procedure Typed_Encode is
      begin
         Handling.Encode (Typed_Msg, Buffer, Last);
         Sink := Buffer (Last);
      end Typed_Encode;

      procedure Dynamic_Encode is
      begin
         ROSIDL.CDR.Encode (Dynamic, Buffer, Last);
         Sink := Buffer (Last);
      end Dynamic_Encode;

      procedure Typed_Decode is
      begin
         Handling.Decode (Data, Kept);
      end Typed_Decode;

      procedure Dynamic_Decode is
      begin
         ROSIDL.CDR.Decode (Data, Dynamic);
      end Dynamic_Decode;

   begin
      if ROSIDL.CDR.Encode (Dynamic) /= Data then
         raise Program_Error with Case_Name & ": typed and dynamic encodings differ";
      end if;
      Dump (Case_Name, Data);
      Run ("encode", "typed", Typed_Encode'Access);
      Run ("encode", "dynamic", Dynamic_Encode'Access);
      Run ("decode", "typed", Typed_Decode'Access);
      Run ("decode", "dynamic", Dynamic_Decode'Access);
      if Handling.Encode (Kept) /= Data then
         raise Program_Error with Case_Name & ": typed decoding differs";
      end if;
   end Measure;

   procedure Measure_Scan is new Measure (Scans.Handling);
   procedure Measure_Odometry is new Measure (Odometries.Handling);
   procedure Measure_Grid is new Measure (Grids.Handling);

begin
   Bench_Rows.Open (CSV_Argument => 2);
   Measure_Scan ("laser_scan_720", Scan);
   Measure_Odometry ("odometry", Odometry);
   Measure_Grid ("occupancy_grid_1000x1000", Grid);
   Bench_Rows.Close;
end Bench_Typed_CDR;
