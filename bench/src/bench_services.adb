--  Service round-trip benchmark (bench/bench-services.sh):
--     bench_services server               answers AddTwoInts on /bench_add (no logging)
--     bench_services client CALLS TASKS   CALLS calls spread over TASKS tasks
--  The client prints "calls=N tasks=T seconds=S rate=R" (round trips per second).
with Ada.Command_Line;
with Ada.Real_Time;
with Ada.Text_IO;
with Bench_Arguments;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Clients;
with RCL.Nodes;

procedure Bench_Services is

   use Ada.Real_Time;
   use type ROSIDL.Int64;
   package CL renames Ada.Command_Line;

   Support : constant ROSIDL.Typesupport.Service_Support :=
     ROSIDL.Typesupport.Get_Service_Support ("example_interfaces", "AddTwoInts");

   procedure Adder
     (Node : in out RCL.Nodes.Node'Class;
      Req  : ROSIDL.Dynamic.Message;
      Resp : in out ROSIDL.Dynamic.Message)
   is
      pragma Unreferenced (Node);
   begin
      Resp ("sum").As_Int64 := Req ("a").As_Int64 + Req ("b").As_Int64;
   end Adder;

   Read : constant Boolean := Bench_Arguments.Checked
     ("bench_services server | client CALLS TASKS" & ASCII.LF
      & "service round trips (bench/bench-services.sh), AddTwoInts on /bench_add" & ASCII.LF
      & "  server              answers until killed" & ASCII.LF
      & "  client CALLS TASKS  CALLS calls spread over TASKS tasks; prints" & ASCII.LF
      & "                      ""calls=N tasks=T errors=E seconds=S rate=R""",
      Min => 1, Max => 3);
   pragma Unreferenced (Read);
   Mode : constant String := Bench_Arguments.One_Of (1, "MODE", "server|client");
begin
   if Mode = "server" then
      declare
         Node : RCL.Nodes.Node := RCL.Nodes.Init ("bench_server");
      begin
         Node.Serve (Support, "/bench_add", Adder'Access);
         Node.Spin;
      end;
   elsif Mode = "client" and then CL.Argument_Count = 3 then
      declare
         Calls  : constant Positive := Bench_Arguments.Count (2, "CALLS", Minimum => 1);
         Tasks  : constant Positive := Bench_Arguments.Count (3, "TASKS", Minimum => 1);
         Node   : constant RCL.Nodes.Node := RCL.Nodes.Init ("bench_client");
         Client : RCL.Clients.Client;
         Wrong  : Natural := 0 with Atomic;
         Start  : Time;

         protected Errors is
            procedure Add;
         end Errors;
         protected body Errors is
            procedure Add is
            begin
               Wrong := Wrong + 1;
            end Add;
         end Errors;

         task type Worker (Id : Natural);
         task body Worker is
            Request : constant ROSIDL.Dynamic.Message :=
              ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support (Support));
         begin
            for I in 1 .. Calls / Tasks loop
               Request ("a").As_Int64 := ROSIDL.Int64 (Id * 1_000_000 + I);
               Request ("b").As_Int64 := 1;
               if Client.Call (Request, 10.0)("sum").As_Int64
                 /= ROSIDL.Int64 (Id * 1_000_000 + I + 1)
               then
                  Errors.Add;
               end if;
            end loop;
         exception
            when others =>
               Errors.Add;
         end Worker;

         type Worker_Access is access Worker;
      begin
         Client.Init (Node, Support, "/bench_add");
         Client.Wait_For_Service (10.0);
         delay 0.2;  --  Let the server match our reply reader.
         Start := Clock;
         declare
            Workers : array (1 .. Tasks) of Worker_Access;
         begin
            for I in Workers'Range loop
               Workers (I) := new Worker (I);
            end loop;
            for W of Workers loop
               while not W'Terminated loop
                  delay 0.001;
               end loop;
            end loop;
         end;
         declare
            Seconds : constant Duration := To_Duration (Clock - Start);
            Done    : constant Natural := (Calls / Tasks) * Tasks;
         begin
            Ada.Text_IO.Put_Line
              ("calls=" & Done'Image & " tasks=" & Tasks'Image & " errors=" & Wrong'Image
               & " seconds=" & Seconds'Image
               & " rate=" & Integer'Image (Integer (Float (Done) / Float (Seconds))));
         end;
      end;
   else
      Bench_Arguments.Fail (Mode & ": wrong number of arguments");
   end if;
end Bench_Services;
