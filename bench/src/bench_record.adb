--  The Ada side of bench/bench-record.sh (recording throughput, issue 15):
--     bench_record payload CASE FILE        the CDR bytes of CASE into FILE
--     bench_record write CASE COUNT         RCL.MCAP.Writers alone: COUNT messages
--                                           into a zstd MCAP file (in-process)
--     bench_record pub CASE COUNT TOPIC     publishes COUNT messages on TOPIC as
--                                           fast as a reliable KEEP_ALL writer may,
--                                           once a subscription matched
--     bench_record record CASE TOPIC DIR SECONDS
--                                           RCL.Bags.Recorders (what "rclada bag
--                                           record" runs) into the bag DIR
--     bench_record sink CASE TOPIC SECONDS  subscribes only (the DDS ceiling);
--                                           prints "count,first_ns,last_ns"
--  CASE: "64" (std_msgs/String of 64 CDR bytes) or "scan" (sensor_msgs/
--  LaserScan, 360 ranges). write prints "case,count,bytes,seconds".
with Ada.Command_Line;
with Ada.Directories;
with Ada.Real_Time;
with Ada.Streams.Stream_IO;
with Ada.Text_IO;
with Bench_Arguments;
with Interfaces;
with RCL.Bags;
with RCL.Bags.Recorders;
with RCL.Contexts;
with RCL.DDS;
with RCL.Graph.Queries;
with RCL.MCAP.Writers;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

procedure Bench_Record is
   use Ada.Command_Line;
   use Ada.Real_Time;
   use Ada.Streams;
   use type Interfaces.Unsigned_64;

   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_record COMMAND CASE ..." & ASCII.LF
      & "the Ada side of bench/bench-record.sh (recording throughput)" & ASCII.LF
      & "  payload CASE FILE              the CDR bytes of CASE into FILE" & ASCII.LF
      & "  write CASE COUNT               RCL.MCAP.Writers alone: COUNT messages into a zstd"
      & ASCII.LF
      & "                                 MCAP file; prints ""case,count,bytes,seconds"""
      & ASCII.LF
      & "  pub CASE COUNT TOPIC           publishes COUNT messages on TOPIC (reliable,"
      & ASCII.LF
      & "                                 keep all) once a subscription matched" & ASCII.LF
      & "  record CASE TOPIC DIR SECONDS  RCL.Bags.Recorders (rclada bag record) into DIR"
      & ASCII.LF
      & "  sink CASE TOPIC SECONDS        subscribes only; prints ""count,first_ns,last_ns"""
      & ASCII.LF
      & "CASE: 64 (std_msgs/String of 64 CDR bytes) or scan (sensor_msgs/LaserScan, 360"
      & " ranges)",
      Min => 3, Max => 5);
   pragma Unreferenced (Read);
   Command : constant String :=
     Bench_Arguments.One_Of (1, "COMMAND", "payload|write|pub|record|sink");
   Kind    : constant String := Bench_Arguments.One_Of (2, "CASE", "64|scan");
   Needed  : constant Positive :=
     (if Command in "payload" | "write" then 3 elsif Command in "pub" | "sink" then 4 else 5);

   function Type_Name return String is
     (if Kind = "scan" then "sensor_msgs/msg/LaserScan" else "std_msgs/msg/String");

   function Payload return Stream_Element_Array is
      use ROSIDL.Dynamic;
   begin
      if Kind = "scan" then
         declare
            M      : constant Message :=
              Init (ROSIDL.Typesupport.Get_Message_Support ("sensor_msgs", "LaserScan"));
            Ranges : Float32_Array (1 .. 360);
         begin
            for I in Ranges'Range loop
               Ranges (I) := ROSIDL.Float32 (Float (10 + I mod 50) / 10.0);
            end loop;
            M ("header")("frame_id").Set_String ("r1/laser");
            M ("angle_min").As_Float32 := ROSIDL.Float32 (-3.14159);
            M ("angle_max").As_Float32 := 3.14159;
            M ("angle_increment").As_Float32 := 0.01745;
            M ("range_max").As_Float32 := 8.0;
            M ("ranges").Set_Float32_Array (Ranges);
            return ROSIDL.CDR.Encode (M);
         end;
      elsif Kind = "64" then
         declare
            M : constant Message :=
              Init (ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String"));
         begin
            --  4 (encapsulation) + 4 (length) + 55 characters + NUL = 64.
            M ("data").Set_String ([1 .. 55 => 'x']);
            return ROSIDL.CDR.Encode (M);
         end;
      end if;
      raise Constraint_Error with "case: 64 or scan, not " & Kind;
   end Payload;

   Data : constant Stream_Element_Array := Payload;

   function Trim (Image : String) return String is
     (if Image (Image'First) = ' ' then Image (Image'First + 1 .. Image'Last) else Image);
begin
   if Argument_Count /= Needed then
      Bench_Arguments.Fail
        (Command & " takes" & Needed'Image & " arguments, found" & Argument_Count'Image);
   end if;
   if Command = "payload" then
      declare
         use Ada.Streams.Stream_IO;
         F : File_Type;
      begin
         Create (F, Out_File, Argument (3));
         Write (F, Data);
         Close (F);
      exception
         when Name_Error | Use_Error =>
            Bench_Arguments.Fail
              ("FILE (argument 3): """ & Argument (3) & """ cannot be created");
      end;
   elsif Command = "write" then
      declare
         Count : constant Natural := Bench_Arguments.Count (3, "COUNT");
         Path  : constant String := "/tmp/bench_record_" & Kind & ".mcap";
         W     : RCL.MCAP.Writers.Writer;
         Start : Time;
         Meta  : RCL.MCAP.String_Maps.Map;
         S     : RCL.MCAP.Schema_Id;
         C     : RCL.MCAP.Channel_Id;
         Stamp : RCL.MCAP.Time_Stamp := 1_700_000_000_000_000_000;
      begin
         Start := Clock;
         W.Create (Path, Compression => RCL.MCAP.Zstd);
         S := W.Add_Schema (Type_Name, "ros2msg", RCL.Bags.Message_Definition_Text (Type_Name));
         Meta.Include ("offered_qos_profiles", RCL.Bags.Offered_QoS_Text ([RCL.QoS.Default]));
         C := W.Add_Channel ("/bench", S, "cdr", Meta);
         for I in 1 .. Count loop
            Stamp := Stamp + 1000;
            W.Write (C, Stamp, Data, Sequence => Interfaces.Unsigned_32 (I));
         end loop;
         W.Close;
         Ada.Text_IO.Put_Line
           (Kind & "," & Count'Image & "," & Data'Length'Image & ","
            & Duration'Image (To_Duration (Clock - Start)));
         Ada.Directories.Delete_File (Path);
      end;
   elsif Command = "record" then
      declare
         Node   : RCL.Nodes.Node := RCL.Nodes.Init ("bench_record_recorder");
         Rec    : RCL.Bags.Recorders.Recorder;
         Topics : RCL.Bags.Recorders.Topic_List;
         Stop   : constant Time :=
           Clock + To_Time_Span (Bench_Arguments.Seconds (5, "SECONDS", Default => 0.0));
      begin
         Topics.Append (Argument (3));
         Rec.Start (Argument (4), Topics);
         Ada.Text_IO.Put_Line ("ready");
         Ada.Text_IO.Flush;
         RCL.Contexts.Install_Signal_Handlers;
         while Clock < Stop and then not RCL.Contexts.Is_Shutdown loop
            Rec.Discover (Node);
            Node.Spin (During => 0.1);
         end loop;
         Rec.Stop;
         Ada.Text_IO.Put_Line ("Recorded" & Rec.Message_Count'Image & " messages");
      end;
   elsif Command = "sink" then
      declare
         Node  : RCL.Nodes.Node := RCL.Nodes.Init ("bench_record_sink");
         Stop  : constant Time :=
           Clock + To_Time_Span (Bench_Arguments.Seconds (4, "SECONDS", Default => 0.0));
         Count : Natural := 0;
         First, Last : ROSIDL.Int64 := 0;
         procedure Count_It
           (N : in out RCL.Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (N, Data);
         begin
            Count := Count + 1;
            if Count = 1 then
               First := Info.Source_Timestamp;
            end if;
            Last := Info.Received_Timestamp;
         end Count_It;
      begin
         Node.Subscribe_Raw
           (RCL.Graph.Queries.Mangle_Type (Type_Name), Argument (3), Count_It'Access,
            (RCL.QoS.Default with delta History => RCL.QoS.Keep_All, Depth => 1000));
         RCL.Contexts.Install_Signal_Handlers;
         Ada.Text_IO.Put_Line ("ready");
         Ada.Text_IO.Flush;
         while Clock < Stop and then not RCL.Contexts.Is_Shutdown loop
            Node.Spin (During => 0.1);
         end loop;
         Ada.Text_IO.Put_Line
           (Trim (Count'Image) & "," & Trim (First'Image) & "," & Trim (Last'Image));
      end;
   elsif Command = "pub" then
      declare
         Count : constant Natural := Bench_Arguments.Count (3, "COUNT");
         Node  : RCL.Nodes.Node := RCL.Nodes.Init ("bench_record_pub");
         Pub   : constant RCL.Publishers.Publisher :=
           Node.Publish_Raw (RCL.Graph.Queries.Mangle_Type (Type_Name), Argument (4),
                             (RCL.QoS.Default with delta History => RCL.QoS.Keep_All));
         Give_Up : constant Time := Clock + Seconds (20);
      begin
         while Pub.Matched_Subscriptions = 0 and then Clock < Give_Up loop
            delay 0.01;
         end loop;
         delay 1.0;  --  The recorder's side of the match too.
         for I in 1 .. Count loop
            Pub.Publish_Raw (Data);
         end loop;
         delay 2.0;  --  Reliable delivery of the tail before the writer goes.
         RCL.Contexts.Shutdown;
      end;
   end if;
end Bench_Record;
