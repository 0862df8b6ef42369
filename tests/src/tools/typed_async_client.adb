--  Test client of tests/interop/test_typed_services.py: asynchronous calls
--  of a typed client (RCL.Services.Typed.Call_Async) to the AddTwoInts
--  service SERVICE, which the test answers late on purpose (so a call that
--  waited for its response is seen). Calls 20 + 22 and 20 + -22, prints
--  whether Call_Async returned before any response and each sum as its
--  callback got it ("Async answer: N"); then a synchronous call (3 + 4)
--  on the same client; then an asynchronous call, with a 0.5 s timeout,
--  of a service nobody offers (SERVICE_nobody): its callback must never
--  run and the call must be forgotten. Exit status 1 if a check fails.
--     typed_async_client SERVICE
with Ada.Command_Line;
with Ada.Real_Time;
with Ada.Text_IO;
with RCL.Nodes;
with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;

procedure Typed_Async_Client is
   use Ada.Real_Time;
   use Ada.Text_IO;
   use type ROSIDL.Int64;

   package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
   package Adding is new RCL.Services.Typed (Add.Handling);

   type Sum_Array is array (1 .. 8) of ROSIDL.Int64;

   protected Answers is
      procedure Put (Sum : ROSIDL.Int64);
      function Count return Natural;
      function Sum (I : Positive) return ROSIDL.Int64;
   private
      Sums : Sum_Array := [others => 0];
      Got  : Natural := 0;
   end Answers;

   protected body Answers is
      procedure Put (Sum : ROSIDL.Int64) is
      begin
         if Got < Sums'Last then
            Got := Got + 1;
            Sums (Got) := Sum;
         end if;
      end Put;
      function Count return Natural is (Got);
      function Sum (I : Positive) return ROSIDL.Int64 is (Sums (I));
   end Answers;

   protected Lost_Answers is
      procedure Put;
      function Count return Natural;
   private
      Got : Natural := 0;
   end Lost_Answers;

   protected body Lost_Answers is
      procedure Put is
      begin
         Got := Got + 1;
      end Put;
      function Count return Natural is (Got);
   end Lost_Answers;

   procedure On_Sum (Resp : Add.Response.Message) is
   begin
      Answers.Put (Resp.Sum);
   end On_Sum;

   procedure On_Lost (Resp : Add.Response.Message) is
      pragma Unreferenced (Resp);
   begin
      Lost_Answers.Put;
   end On_Lost;

   Failed : Boolean := False;

   procedure Check (OK : Boolean; What : String) is
   begin
      if not OK then
         Put_Line ("FAILED: " & What);
         Failed := True;
      end if;
   end Check;

begin
   if Ada.Command_Line.Argument_Count /= 1 then
      Put_Line (Standard_Error, "usage: typed_async_client SERVICE");
      Ada.Command_Line.Set_Exit_Status (2);
      return;
   end if;
   declare
      Service : constant String := Ada.Command_Line.Argument (1);
      Node    : constant RCL.Nodes.Node := RCL.Nodes.Init ("typed_async_client");
      C, Lost : Adding.Client;
      Start   : Time;
      Took    : Duration;
      Before  : Natural;
   begin
      C.Init (Node, Service);
      Lost.Init (Node, Service & "_nobody");
      C.Wait_For_Service (Timeout => 10.0);
      Start := Clock;
      C.Call_Async ((A => 20, B => 22), On_Sum'Access, Timeout => 10.0);
      C.Call_Async ((A => 20, B => -22), On_Sum'Access, Timeout => 10.0);
      Before := Answers.Count;
      Took := To_Duration (Clock - Start);
      Put_Line ("Returned before the responses: " & Boolean'Image (Before = 0)
                & " (" & Duration'Image (Took) & " s)");
      Check (Before = 0, "a response came before Call_Async returned");
      Lost.Call_Async ((A => 1, B => 1), On_Lost'Access, Timeout => 0.5);

      while Answers.Count < 2 and then Clock - Start < Seconds (5) loop
         delay 0.01;
      end loop;
      Check (Answers.Count = 2, "callbacks run:" & Answers.Count'Image & ", 2 expected");
      for I in 1 .. Answers.Count loop
         Put_Line ("Async answer:" & Answers.Sum (I)'Image);
      end loop;
      Check (C.Pending_Async = 0, "calls still pending after their responses");

      Put_Line ("Sync answer:" & C.Call ((A => 3, B => 4), Timeout => 5.0).Sum'Image);

      while Lost.Pending_Async > 0 and then Clock - Start < Seconds (5) loop
         delay 0.01;
      end loop;
      Put_Line ("Unanswered call forgotten: " & Boolean'Image (Lost.Pending_Async = 0)
                & ", its callback ran" & Lost_Answers.Count'Image & " time(s)");
      Check (Lost.Pending_Async = 0, "the unanswered call was not forgotten");
      Check (Lost_Answers.Count = 0, "the callback of an unanswered call ran");
   end;
   if Failed then
      Ada.Command_Line.Set_Exit_Status (1);
   end if;
end Typed_Async_Client;
