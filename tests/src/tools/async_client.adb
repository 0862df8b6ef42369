--  Test client of tests/interop/test_typed_services.py: asynchronous calls
--  of a typed client (RCL.Services.Typed.Call_Async) and of a dynamic one
--  (RCL.Clients.Call_Async: the same machinery, RCL.Pending_Calls.
--  Asynchronous) to the AddTwoInts service SERVICE, which the test answers
--  late on purpose (so a call that waited for its response is seen).
--  Typed: calls 20 + 22 and 20 + -22, prints whether Call_Async returned
--  before any response and each sum as its callback got it ("Async
--  answer: N"); then a synchronous call (3 + 4) on the same client
--  ("Sync answer: 7"); a callback making a synchronous call of its own
--  client must get ROS_Exception ("Self call refused: TRUE"). Dynamic: the
--  same two calls ("Dynamic async answer: N"). Then an asynchronous call,
--  with a 0.5 s timeout, of a service nobody offers (SERVICE_nobody): its
--  callback must never run and the call must be forgotten; and a client
--  finalized with a call pending (60 s timeout) must end at once.
--  Exit status 1 if a check fails.
--     async_client SERVICE
with Ada.Command_Line;
with Ada.Real_Time;
with Ada.Text_IO;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Clients;
with RCL.Nodes;
with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;

procedure Async_Client is
   use Ada.Real_Time;
   use Ada.Text_IO;
   use type ROSIDL.Int64;

   package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;

   type Sum_Array is array (1 .. 8) of ROSIDL.Int64;

   protected type Answers is
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

   Typed_Answers, Dynamic_Answers, Lost_Answers : Answers;

   type Self_Call_Outcome is (Not_Yet, Answered, Refused, Other_Error);

   Self_Call : Self_Call_Outcome := Not_Yet with Atomic;
   --  Set by the callback that calls its own client.

   procedure On_Dynamic_Sum (Response : ROSIDL.Dynamic.Message) is
   begin
      Dynamic_Answers.Put (Response ("sum").As_Int64);
   end On_Dynamic_Sum;

   Failed : Boolean := False;

   procedure Check (OK : Boolean; What : String) is
   begin
      if not OK then
         Put_Line ("FAILED: " & What);
         Failed := True;
      end if;
   end Check;

   procedure Await (Done : access function return Boolean; Since : Time) is
   begin
      while not Done.all and then Clock - Since < Seconds (5) loop
         delay 0.01;
      end loop;
   end Await;

begin
   if Ada.Command_Line.Argument_Count /= 1 then
      Put_Line (Standard_Error, "usage: async_client SERVICE");
      Ada.Command_Line.Set_Exit_Status (2);
      return;
   end if;
   declare
      Service : constant String := Ada.Command_Line.Argument (1);
      Node    : constant RCL.Nodes.Node := RCL.Nodes.Init ("async_client");
      package Adding is new RCL.Services.Typed (Add.Handling);
      C, Lost : Adding.Client;
      D       : RCL.Clients.Client;
      Support : constant ROSIDL.Typesupport.Service_Support :=
        ROSIDL.Typesupport.Get_Service_Support ("example_interfaces", "AddTwoInts");
      Start   : Time;
      Took    : Duration;
      Before  : Natural;

      procedure On_Sum (Resp : Add.Response.Message) is
      begin
         Typed_Answers.Put (Resp.Sum);
      end On_Sum;

      procedure On_Lost (Resp : Add.Response.Message) is
      begin
         Lost_Answers.Put (Resp.Sum);
      end On_Lost;

      procedure Call_Self (Resp : Add.Response.Message) is
         pragma Unreferenced (Resp);
      begin
         if C.Call ((A => 1, B => 1), Timeout => 3.0).Sum = 2 then
            Self_Call := Answered;
         end if;
      exception
         when RCL.ROS_Exception =>
            Self_Call := Refused;
         when others =>
            Self_Call := Other_Error;
      end Call_Self;

      function Typed_Done return Boolean is (Typed_Answers.Count >= 2);
      function Self_Call_Done return Boolean is (Self_Call /= Not_Yet);
      function Dynamic_Done return Boolean is (Dynamic_Answers.Count >= 2);
      function Lost_Done return Boolean is (Lost.Pending_Async = 0);

      function Request (A, B : ROSIDL.Int64) return ROSIDL.Dynamic.Message is
         R : constant ROSIDL.Dynamic.Message :=
           ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support (Support));
      begin
         R ("a").As_Int64 := A;
         R ("b").As_Int64 := B;
         return R;
      end Request;
   begin
      C.Init (Node, Service);
      Lost.Init (Node, Service & "_nobody");
      D.Init (Node, Support, Service);
      C.Wait_For_Service (Timeout => 10.0);
      D.Wait_For_Service (Timeout => 10.0);

      --  Typed.
      Start := Clock;
      C.Call_Async ((A => 20, B => 22), On_Sum'Access, Timeout => 10.0);
      C.Call_Async ((A => 20, B => -22), On_Sum'Access, Timeout => 10.0);
      Before := Typed_Answers.Count;
      Took := To_Duration (Clock - Start);
      Put_Line ("Returned before the responses: " & Boolean'Image (Before = 0)
                & " (" & Duration'Image (Took) & " s)");
      Check (Before = 0, "a response came before Call_Async returned");
      Lost.Call_Async ((A => 1, B => 1), On_Lost'Access, Timeout => 0.5);

      Await (Typed_Done'Access, Start);
      Check (Typed_Answers.Count = 2,
             "callbacks run:" & Typed_Answers.Count'Image & ", 2 expected");
      for I in 1 .. Typed_Answers.Count loop
         Put_Line ("Async answer:" & Typed_Answers.Sum (I)'Image);
      end loop;
      Check (C.Pending_Async = 0, "calls still pending after their responses");

      Put_Line ("Sync answer:" & C.Call ((A => 3, B => 4), Timeout => 5.0).Sum'Image);

      C.Call_Async ((A => 5, B => 6), Call_Self'Access, Timeout => 10.0);
      Await (Self_Call_Done'Access, Clock);
      Put_Line ("Self call refused: " & Boolean'Image (Self_Call = Refused)
                & " (" & Self_Call'Image & ")");
      Check (Self_Call = Refused, "a synchronous call from the own callback");

      --  Dynamic.
      D.Call_Async (Request (20, 22), On_Dynamic_Sum'Unrestricted_Access, Timeout => 10.0);
      D.Call_Async (Request (20, -22), On_Dynamic_Sum'Unrestricted_Access, Timeout => 10.0);
      Await (Dynamic_Done'Access, Clock);
      Check (Dynamic_Answers.Count = 2,
             "dynamic callbacks run:" & Dynamic_Answers.Count'Image & ", 2 expected");
      for I in 1 .. Dynamic_Answers.Count loop
         Put_Line ("Dynamic async answer:" & Dynamic_Answers.Sum (I)'Image);
      end loop;
      Check (D.Pending_Async = 0, "dynamic calls still pending after their responses");

      --  Unanswered, then dropped at finalization.
      Await (Lost_Done'Access, Start);
      Put_Line ("Unanswered call forgotten: " & Boolean'Image (Lost.Pending_Async = 0)
                & ", its callback ran" & Lost_Answers.Count'Image & " time(s)");
      Check (Lost.Pending_Async = 0, "the unanswered call was not forgotten");
      Check (Lost_Answers.Count = 0, "the callback of an unanswered call ran");
      Start := Clock;
      declare
         Dropping : Adding.Client;
      begin
         Dropping.Init (Node, Service & "_nobody");
         Dropping.Call_Async ((A => 1, B => 1), On_Lost'Access, Timeout => 60.0);
      end;
      Took := To_Duration (Clock - Start);
      Put_Line ("Finalized with a call pending in" & Duration'Image (Took) & " s");
      Check (Took < 2.0, "finalizing a client with a call pending took" & Took'Image & " s");
      Check (Lost_Answers.Count = 0, "the callback of a dropped call ran");
   end;
   if Failed then
      Ada.Command_Line.Set_Exit_Status (1);
   end if;
end Async_Client;
