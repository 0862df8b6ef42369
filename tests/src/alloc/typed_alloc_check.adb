--  The zero-allocation check of the typed message path (run by
--  tests/interop/test_typed_alloc.py): one node publishes generated
--  messages and receives them on its own subscription (take + decode +
--  callback, Node.Spin in this task). After a warm-up, COUNT more rounds
--  must make no Ada heap allocation in this task: every __gnat_malloc is
--  counted (heap_counters.ads). Cyclone DDS's own C allocations (its
--  serdata per sample) are not Ada heap and not counted. Then the same for
--  a typed service (example_interfaces/srv/AddTwoInts, bounded): COUNT
--  calls of a typed client in this task to a typed server of the same
--  node spun by another task; the client's task and the whole process
--  must not allocate.
--     typed_alloc_check [COUNT]
--  prints one line per message type and exits 1 when a bounded type
--  allocated or too few messages came back.
with Ada.Command_Line;
with Ada.Strings.Unbounded;
with Ada.Task_Identification;
with Ada.Text_IO;
with Heap_Counters;
with RCL.Nodes.Typed;
with RCL.Publishers;
with RCL.QoS;
with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
with ROSIDL.Static.Geometry_Msgs.Messages.Twist;
with ROSIDL.Static.Message_Support;
with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
with System;

procedure Typed_Alloc_Check is

   use Ada.Text_IO;
   use type ROSIDL.Float64;

   Count  : constant Positive :=
     (if Ada.Command_Line.Argument_Count >= 1
      then Positive'Value (Ada.Command_Line.Argument (1)) else 2_000);
   Warmup : constant := 200;
   Failed : Boolean := False;

   function Me return System.Address is
      Id  : constant Ada.Task_Identification.Task_Id := Ada.Task_Identification.Current_Task;
      Raw : constant System.Address with Import, Address => Id'Address;
   begin
      return Raw;
   end Me;

   procedure Count_Allocations
     (Round : not null access procedure (N : Positive); Own, All_Tasks : out Natural) is
      --  Round (1) .. Round (Count) with the heap counters on: Own, the
      --  allocations of this task; All_Tasks, those of every task.
   begin
      Heap_Counters.Start (Me);
      for N in 1 .. Count loop
         Round (N);
      end loop;
      Own := Heap_Counters.Task_Allocations;
      All_Tasks := Heap_Counters.All_Allocations;
   end Count_Allocations;

   generic
      with package Handling is new ROSIDL.Static.Message_Support (<>);
      Topic : String;
      with procedure Vary (Msg : in out Handling.Message; N : Positive);
   procedure Check;

   procedure Check is
      package Topics is new RCL.Nodes.Typed (Handling);
      Node     : RCL.Nodes.Node := RCL.Nodes.Init ("typed_alloc_check");
      --  Finalized before Topics: its subscription's callbacks live there.
      Pub      : constant RCL.Publishers.Publisher :=
        Topics.Publish (Node, Topic, RCL.QoS.Default);
      Received : Natural := 0;
      Msg      : Topics.Message;

      procedure On_Message
        (Node : in out RCL.Nodes.Node'Class;
         Msg  : Topics.Message;
         Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Msg, Info);
      begin
         Received := Received + 1;
      end On_Message;

      procedure Round (N : Positive) is
      begin
         Vary (Msg, N);
         Topics.Publish (Pub, Msg);
         Node.Spin (Once => True, During => 0.05);
      end Round;

   begin
      Topics.Subscribe (Node, Topic, On_Message'Access);
      Node.Spin (During => 0.5);  --  discovery of our own endpoints
      for N in 1 .. Warmup loop
         Round (N);
      end loop;
      Node.Spin (During => 0.2);
      Received := 0;
      declare
         Own, All_Tasks : Natural;
      begin
         Count_Allocations (Round'Access, Own, All_Tasks);
         Put_Line (Topics.Full_Name & (if Topics.Is_Bounded then " (bounded)" else "")
                   & ": published" & Count'Image & ", received" & Received'Image
                   & ", Ada heap allocations in the publishing/receiving task:" & Own'Image
                   & " (all tasks of the process:" & All_Tasks'Image & ")");
         if Received < Count * 9 / 10 then
            Put_Line ("  FAILED: too few messages received");
            Failed := True;
         elsif Topics.Is_Bounded and then Own > 0 then
            Put_Line ("  FAILED: a bounded type allocated in steady state");
            Failed := True;
         end if;
      end;
   end Check;

   procedure Vary_Twist
     (Msg : in out ROSIDL.Static.Geometry_Msgs.Messages.Twist.Message; N : Positive) is
   begin
      Msg.Linear.X := ROSIDL.Float64 (N);
      Msg.Angular.Z := -ROSIDL.Float64 (N) / 2.0;
   end Vary_Twist;

   procedure Vary_Scan
     (Msg : in out ROSIDL.Static.Sensor_Msgs.Messages.LaserScan.Message; N : Positive) is
   begin
      if Msg.Ranges.Length = 0 then
         Msg.Header.Frame_Id := Ada.Strings.Unbounded.To_Unbounded_String ("laser");
         Msg.Ranges.Set_Length (720);
      end if;
      Msg.Header.Stamp.Sec := ROSIDL.Int32 (N);
      Msg.Ranges (N mod 720) := ROSIDL.Float32 (N);
   end Vary_Scan;

   procedure Check_Twist is new Check
     (ROSIDL.Static.Geometry_Msgs.Messages.Twist.Handling, "/alloc_check/twist", Vary_Twist);
   procedure Check_Scan is new Check
     (ROSIDL.Static.Sensor_Msgs.Messages.LaserScan.Handling, "/alloc_check/scan", Vary_Scan);

   procedure Check_Service is
      package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
      package Adding is new RCL.Services.Typed (Add.Handling);
      use type ROSIDL.Int64;

      procedure Adder
        (Node : in out RCL.Nodes.Node'Class;
         Req  : Add.Request.Message;
         Resp : in out Add.Response.Message)
      is
         pragma Unreferenced (Node);
      begin
         Resp.Sum := Req.A + Req.B;
      end Adder;

      package Adder_Server is new Adding.Server (Adder);

      Node : RCL.Nodes.Node := RCL.Nodes.Init ("typed_alloc_check_service");
      --  Finalized before the instances: its service calls Adder.
      Client : Adding.Client;
      Stop   : Boolean := False with Atomic;
      Wrong  : Natural := 0;

      task Spinner;
      task body Spinner is
      begin
         while not Stop loop
            Node.Spin (Once => True, During => 0.05);
         end loop;
      exception
         when others =>
            Stop := True;
      end Spinner;

      procedure Round (N : Positive) is
         Resp : Add.Response.Message;
      begin
         Client.Call ((A => ROSIDL.Int64 (N), B => -3), Resp, Timeout => 5.0);
         if Resp.Sum /= ROSIDL.Int64 (N) - 3 then
            Wrong := Wrong + 1;
         end if;
      end Round;

   begin
      Adder_Server.Serve (Node, "/alloc_check/add");
      Client.Init (Node, "/alloc_check/add");
      Client.Wait_For_Service (Timeout => 10.0);
      for N in 1 .. Warmup loop
         Round (N);
      end loop;
      declare
         Own, All_Tasks : Natural;
      begin
         Count_Allocations (Round'Access, Own, All_Tasks);
         Stop := True;
         Put_Line (Add.Full_Name & " (bounded): called" & Count'Image & ", wrong sums"
                   & Wrong'Image
                   & ", Ada heap allocations in the calling task:" & Own'Image
                   & " (all tasks of the process, the serving one included:"
                   & All_Tasks'Image & ")");
         if Wrong > 0 then
            Put_Line ("  FAILED: wrong responses");
            Failed := True;
         elsif Own > 0 or else All_Tasks > 0 then
            Put_Line ("  FAILED: a bounded service allocated in steady state");
            Failed := True;
         end if;
      end;
   exception
      when others =>
         Stop := True;
         raise;
   end Check_Service;

   type Int_Access is access Integer;
   Probe : Int_Access with Volatile;

begin
   --  The counter must see an allocation, else the check proves nothing.
   Heap_Counters.Start (Me);
   Probe := new Integer'(Count);
   if Heap_Counters.Task_Allocations /= 1 or else Probe.all /= Count then
      Put_Line ("FAILED: the heap counter did not see an allocation (linked without "
                & "-Wl,--wrap=__gnat_malloc?)");
      Ada.Command_Line.Set_Exit_Status (1);
      return;
   end if;
   Check_Twist;
   Check_Scan;
   Check_Service;
   Ada.Command_Line.Set_Exit_Status (if Failed then 1 else 0);
end Typed_Alloc_Check;
