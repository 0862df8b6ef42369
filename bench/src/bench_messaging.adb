--  The Ada side of bench/bench-messaging.sh: the same runs as
--  bench/messaging_c.c, through the RCL API with std_msgs/UInt8MultiArray
--  (default: ROSIDL.Dynamic messages and ROSIDL.CDR; --typed: the generated
--  record and codec, RCL.Nodes.Typed; --raw: pre-encoded bytes through
--  Publish_Raw / Subscribe_Raw, the transport alone).
--
--     bench_messaging [--raw|--typed] ping SIZE COUNT  prints "rtt_us <median> <p99>"
--     bench_messaging [--raw|--typed] pong
--     bench_messaging [--raw|--typed] pub SIZE SECONDS
--     bench_messaging [--raw|--typed] sub      prints "throughput <msg/s> <MB/s>"
--  A message with layout.data_offset = 16#FFFF_FFFF# ends pong and sub.
with Ada.Command_Line;
with Ada.Containers.Generic_Array_Sort;
with Ada.Real_Time;
with Ada.Streams;
with Ada.Text_IO;
with Bench_Arguments;
with Interfaces;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.DDS;
with RCL.Nodes;
with RCL.Nodes.Typed;
with RCL.Publishers;
with RCL.QoS;
with ROSIDL.Static.Std_Msgs.Messages.UInt8MultiArray;

procedure Bench_Messaging is

   use Ada.Real_Time;
   use Ada.Streams;
   use type Interfaces.Unsigned_32;

   package CL renames Ada.Command_Line;

   Read  : constant Boolean := Bench_Arguments.Checked
     ("bench_messaging [--raw|--typed] MODE ..." & ASCII.LF
      & "the Ada side of bench/bench-messaging.sh (std_msgs/UInt8MultiArray on /bench_ping,"
      & ASCII.LF & "/bench_pong, /bench_thr; default: dynamic messages; --typed: generated"
      & ASCII.LF & "record and codec; --raw: pre-encoded bytes)" & ASCII.LF
      & "  ping SIZE COUNT     COUNT round trips of SIZE-byte messages with a pong;" & ASCII.LF
      & "                      prints ""rtt_us <median> <p99>""" & ASCII.LF
      & "  pong                answers pings until ping ends" & ASCII.LF
      & "  pub SIZE [SECONDS]  publishes SIZE-byte messages to a sub for SECONDS (1)"
      & ASCII.LF
      & "  sub                 counts until pub ends; prints ""throughput <msg/s> <MB/s>""",
      Min => 1, Max => 4);
   pragma Unreferenced (Read);
   Raw   : constant Boolean := CL.Argument (1) = "--raw";
   Typed : constant Boolean := CL.Argument (1) = "--typed";
   First : constant Positive := (if Raw or Typed then 2 else 1);
   Mode  : constant String := Bench_Arguments.One_Of (First, "MODE", "ping|pong|pub|sub");

   Stop_Mark : constant ROSIDL.UInt32 := 16#FFFF_FFFF#;

   Support : constant ROSIDL.Typesupport.Message_Support :=
     ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "UInt8MultiArray");
   Type_Name : constant String := ROSIDL.Typesupport.DDS_Type_Name (Support);

   Ping_QoS : constant RCL.QoS.Profile := RCL.QoS.Default;
   Thr_QoS  : constant RCL.QoS.Profile :=
     (RCL.QoS.Default with delta History => RCL.QoS.Keep_All);
   --  Keep all: every sample counts (flow control instead of loss).

   package Arrays renames ROSIDL.Static.Std_Msgs.Messages.UInt8MultiArray;
   package Typed_Topics is new RCL.Nodes.Typed (Arrays.Handling);
   --  Before Node: its typed subscriptions' callbacks live here.

   Node : RCL.Nodes.Node := RCL.Nodes.Init ("bench_messaging");

   function Make_Typed (Size : Natural; Offset : ROSIDL.UInt32) return Arrays.Message is
   begin
      return Msg : Arrays.Message do
         Msg.Layout.Data_Offset := Offset;
         Msg.Data.Set_Length (Size);
      end return;
   end Make_Typed;

   procedure Publish (Pub : RCL.Publishers.Publisher; Msg : Arrays.Message)
     renames Typed_Topics.Publish;

   function Make (Size : Natural; Offset : ROSIDL.UInt32) return ROSIDL.Dynamic.Message is
      Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
   begin
      Msg ("layout") ("data_offset").As_UInt32 := Offset;
      Msg ("data").As_Array.Resize (Size);
      return Msg;
   end Make;

   --  data_offset in raw CDR (little endian): header 4, dim count 4, then it.
   function Raw_Offset (Data : Stream_Element_Array) return ROSIDL.UInt32 is
      R : ROSIDL.UInt32 := 0;
   begin
      for I in reverse 0 .. 3 loop
         R := R * 256 + ROSIDL.UInt32 (Data (Data'First + 8 + Stream_Element_Offset (I)));
      end loop;
      return R;
   end Raw_Offset;

   procedure Send
     (Pub       : in out RCL.Publishers.Publisher;
      Bytes     : Stream_Element_Array;
      Typed_Msg : Arrays.Message;
      Msg       : ROSIDL.Dynamic.Message) is
      --  One message, in the form the command line chose: the raw CDR
      --  Bytes (--raw), the typed Typed_Msg (--typed) or the dynamic Msg.
   begin
      if Raw then
         Pub.Publish_Raw (Bytes);
      elsif Typed then
         Publish (Pub, Typed_Msg);
      else
         Pub.Publish (Msg);
      end if;
   end Send;

   procedure Wait_Match (Pub : RCL.Publishers.Publisher) is
   begin
      for I in 1 .. 2000 loop
         exit when Pub.Matched_Subscriptions > 0;
         delay 0.005;
      end loop;
      delay 0.3;
   end Wait_Match;

   Got       : Boolean := False with Atomic;
   Stopped   : Boolean := False with Atomic;
   --  Set by callbacks (through the executor): read afresh in the loops.
   Count     : Natural := 0;
   Bytes     : Long_Float := 0.0;
   T_First   : Time := Time_First;
   T_Last    : Time := Time_First;

begin
   if Mode = "pong" then
      declare
         Pub : RCL.Publishers.Publisher := Node.Publish (Support, "/bench_pong", Ping_QoS);

         procedure Echo
           (Node : in out RCL.Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            Pub.Publish (Msg);
            Stopped := Msg ("layout") ("data_offset").As_UInt32 = Stop_Mark;
         end Echo;

         procedure Echo_Raw
           (Node : in out RCL.Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            Pub.Publish_Raw (Data);
            Stopped := Raw_Offset (Data) = Stop_Mark;
         end Echo_Raw;

         procedure Echo_Typed
           (Node : in out RCL.Nodes.Node'Class; Msg : Arrays.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            Publish (Pub, Msg);
            Stopped := Msg.Layout.Data_Offset = Stop_Mark;
         end Echo_Typed;
      begin
         if Raw then
            Node.Subscribe_Raw (Type_Name, "/bench_ping", Echo_Raw'Access, Ping_QoS);
         elsif Typed then
            Typed_Topics.Subscribe (Node, "/bench_ping", Echo_Typed'Access, Ping_QoS);
         else
            Node.Subscribe (Support, "/bench_ping", Echo'Access, Ping_QoS);
         end if;
         while not Stopped loop
            Node.Spin (Once => True, During => 30.0);
         end loop;
         delay 0.2;
      end;

   elsif Mode = "ping" then
      declare
         Size  : constant Natural := Bench_Arguments.Count (First + 1, "SIZE");
         N     : constant Positive := Bench_Arguments.Count (First + 2, "COUNT", Minimum => 1);
         Warm  : constant Natural := N / 10 + 10;
         Pub   : RCL.Publishers.Publisher := Node.Publish (Support, "/bench_ping", Ping_QoS);
         Msg   : constant ROSIDL.Dynamic.Message := Make (Size, 0);
         Bytes : constant Stream_Element_Array := ROSIDL.CDR.Encode (Msg);
         Typed_Msg : constant Arrays.Message := Make_Typed (Size, 0);
         type Span_Array is array (Positive range <>) of Duration;
         procedure Sort is new Ada.Containers.Generic_Array_Sort (Positive, Duration, Span_Array);
         RTT   : Span_Array (1 .. N);

         procedure On_Pong
           (Node : in out RCL.Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Msg, Info);
         begin
            Got := True;
         end On_Pong;

         procedure On_Pong_Raw
           (Node : in out RCL.Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Data, Info);
         begin
            Got := True;
         end On_Pong_Raw;

         procedure On_Pong_Typed
           (Node : in out RCL.Nodes.Node'Class; Msg : Arrays.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Msg, Info);
         begin
            Got := True;
         end On_Pong_Typed;
      begin
         if Raw then
            Node.Subscribe_Raw (Type_Name, "/bench_pong", On_Pong_Raw'Access, Ping_QoS);
         elsif Typed then
            Typed_Topics.Subscribe (Node, "/bench_pong", On_Pong_Typed'Access, Ping_QoS);
         else
            Node.Subscribe (Support, "/bench_pong", On_Pong'Access, Ping_QoS);
         end if;
         Wait_Match (Pub);
         for I in 1 .. Warm + N loop
            declare
               T0 : constant Time := Clock;
            begin
               Got := False;
               Send (Pub, Bytes, Typed_Msg, Msg);
               while not Got loop
                  Node.Spin (Once => True, During => 10.0);
               end loop;
               if I > Warm then
                  RTT (I - Warm) := To_Duration (Clock - T0);
               end if;
            end;
         end loop;
         Sort (RTT);
         Ada.Text_IO.Put_Line
           ("rtt_us" & Duration'Image (RTT (N / 2 + 1) * 1_000_000)
            & Duration'Image (RTT ((N * 99) / 100) * 1_000_000));
         Pub.Publish (Make (0, Stop_Mark));
         delay 0.2;
      end;

   elsif Mode = "pub" then
      declare
         Size    : constant Natural := Bench_Arguments.Count (First + 1, "SIZE");
         Seconds : constant Duration :=
           Bench_Arguments.Seconds (First + 2, "SECONDS", Default => 1.0);
         Pub     : RCL.Publishers.Publisher := Node.Publish (Support, "/bench_thr", Thr_QoS);
         Msg     : constant ROSIDL.Dynamic.Message := Make (Size, 0);
         Bytes   : constant Stream_Element_Array := ROSIDL.CDR.Encode (Msg);
         Typed_Msg : constant Arrays.Message := Make_Typed (Size, 0);
         Stop_At : Time;
         Sent    : Natural := 0;
      begin
         Wait_Match (Pub);
         Stop_At := Clock + To_Time_Span (Seconds);
         while Clock < Stop_At loop
            Send (Pub, Bytes, Typed_Msg, Msg);
            Sent := Sent + 1;
         end loop;
         Pub.Publish (Make (0, Stop_Mark));
         delay 0.5;
         Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, "sent" & Sent'Image);
      end;

   elsif Mode = "sub" then
      declare
         procedure Count_It (Size : Natural) is
         begin
            if Count = 0 then
               T_First := Clock;
            end if;
            Count := Count + 1;
            Bytes := Bytes + Long_Float (Size);
            T_Last := Clock;
         end Count_It;

         procedure On_Data
           (Node : in out RCL.Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            if Msg ("layout") ("data_offset").As_UInt32 = Stop_Mark then
               Stopped := True;
            else
               Count_It (Msg ("data").As_Array.Length);
            end if;
         end On_Data;

         procedure On_Raw
           (Node : in out RCL.Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            if Raw_Offset (Data) = Stop_Mark then
               Stopped := True;
            else
               Count_It (Natural (Data'Length) - 16);
            end if;
         end On_Raw;

         procedure On_Typed
           (Node : in out RCL.Nodes.Node'Class; Msg : Arrays.Message;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            if Msg.Layout.Data_Offset = Stop_Mark then
               Stopped := True;
            else
               Count_It (Msg.Data.Length);
            end if;
         end On_Typed;
      begin
         if Raw then
            Node.Subscribe_Raw (Type_Name, "/bench_thr", On_Raw'Access, Thr_QoS);
         elsif Typed then
            Typed_Topics.Subscribe (Node, "/bench_thr", On_Typed'Access, Thr_QoS);
         else
            Node.Subscribe (Support, "/bench_thr", On_Data'Access, Thr_QoS);
         end if;
         while not Stopped loop
            Node.Spin (Once => True, During => 30.0);
         end loop;
         declare
            Secs : constant Long_Float := Long_Float (To_Duration (T_Last - T_First));
         begin
            if Count > 1 and then Secs > 0.0 then
               Ada.Text_IO.Put_Line
                 ("throughput" & Long_Float'Image (Long_Float (Count - 1) / Secs)
                  & Long_Float'Image (Bytes / Secs / 1.0e6));
            else
               Ada.Text_IO.Put_Line ("throughput 0 0");
            end if;
         end;
      end;
   else
      raise Program_Error with "bench_messaging: unknown mode " & Mode;
   end if;
end Bench_Messaging;
