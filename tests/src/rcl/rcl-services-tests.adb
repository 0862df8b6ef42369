with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with AUnit.Assertions; use AUnit.Assertions;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Clients;
with RCL.Graph.Queries;
with RCL.Publishers;
with RCL.QoS;
with RCL.DDS.Matching;
with RCL.Nodes;
with RCL.Pending_Calls.Asynchronous;
with Suite_Support; use Suite_Support;

package body RCL.Services.Tests is

   use type ROSIDL.Int64;
   use type RCL.Pending_Calls.Outcome;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;

   package Graph renames RCL.Graph.Queries;

   function Add_Support return ROSIDL.Typesupport.Service_Support is
     (ROSIDL.Typesupport.Get_Service_Support ("example_interfaces", "AddTwoInts"));

   function Sum_Of (Response : ROSIDL.Dynamic.Message) return ROSIDL.Int64 is
     (Response ("sum").As_Int64);

   function Request (A, B : ROSIDL.Int64) return ROSIDL.Dynamic.Message is
      R : constant ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support (Add_Support));
   begin
      R ("a").As_Int64 := A;
      R ("b").As_Int64 := B;
      return R;
   end Request;
   --  An AddTwoInts request a + b.

   procedure Adder
     (Node     : in out RCL.Nodes.Node'Class;
      Request  : ROSIDL.Dynamic.Message;
      Response : in out ROSIDL.Dynamic.Message)
   is
      pragma Unreferenced (Node);
   begin
      Response ("sum").As_Int64 := Request ("a").As_Int64 + Request ("b").As_Int64;
   end Adder;
   --  The AddTwoInts service's callback.

   --  Pairing ---------------------------------------------------------------

   procedure Pairing (Unused : in out Fixture) is
      use RCL.Pending_Calls;
      T        : Table;
      A, B     : constant Slot_Access := new Slot;
      Response : constant ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Response_Support (Add_Support));
      Result   : Outcome;
      S1       : constant ROSIDL.Int64 := Next_Sequence;
      S2       : constant ROSIDL.Int64 := Next_Sequence;
   begin
      Assert (S2 = S1 + 1, "sequence numbers follow each other");
      T.Add_Sync (5, A);
      T.Add_Sync (6, B);
      Assert (T.Count = 2, "two calls");
      Response ("sum").As_Int64 := 11;
      T.Deliver (6, Response, Result);
      Assert (Result = Delivered and B.Filled and not A.Filled, "reply 6 goes to B only");
      Assert (Sum_Of (B.Response) = 11, "B holds the response");
      T.Deliver (6, Response, Result);
      Assert (Result = Unknown_Sequence, "a duplicate reply is unknown");
      T.Deliver (99, Response, Result);
      Assert (Result = Unknown_Sequence, "someone else's sequence is unknown");
      T.Remove (5);
      T.Remove (5);
      Assert (T.Count = 0, "call 5 removed (twice is harmless)");
      declare
         First, Second : Boolean;
      begin
         T.Try_Lead (First);
         T.Try_Lead (Second);
         Assert (First and not Second, "one leader at a time");
         T.Release;
         T.Try_Lead (Second);
         Assert (Second, "leading again after Release");
      end;
   end Pairing;

   --  Asynchronous calls' table and pump, with a stand-in client whose
   --  replies never come (its reading counts the pump's rounds).

   protected Stand_In is
      procedure Read;
      function Reads return Natural;
      procedure Add_Sum (Value : ROSIDL.Int64; In_Own_Callback, Refused : Boolean);
      function Sum return ROSIDL.Int64;
      function All_In_Own_Callback return Boolean;
      function All_Refused return Boolean;
   private
      Count   : Natural := 0;
      Total   : ROSIDL.Int64 := 0;
      Inside  : Boolean := True;
      Refusal : Boolean := True;
   end Stand_In;

   protected body Stand_In is
      procedure Read is
      begin
         Count := Count + 1;
      end Read;
      function Reads return Natural is (Count);
      procedure Add_Sum (Value : ROSIDL.Int64; In_Own_Callback, Refused : Boolean) is
      begin
         Total := Total + Value;
         Inside := Inside and In_Own_Callback;
         Refusal := Refusal and Refused;
      end Add_Sum;
      function Sum return ROSIDL.Int64 is (Total);
      function All_In_Own_Callback return Boolean is (Inside);
      function All_Refused return Boolean is (Refusal);
   end Stand_In;

   type Stand_In_Client is null record;
   type Stand_In_Ref is access all Stand_In_Client;
   The_Stand_In : aliased Stand_In_Client;

   procedure Read_Nothing (Client : Stand_In_Ref) is
      pragma Unreferenced (Client);
   begin
      Stand_In.Read;
      delay 0.005;
   end Read_Nothing;

   function Stand_In_Name (Unused : Stand_In_Ref) return String is ("/stand_in");

   type Sum_Callback is access procedure (Response : ROSIDL.Dynamic.Message);

   package Stand_In_Calls is new RCL.Pending_Calls.Asynchronous
     (ROSIDL.Dynamic.Message, Sum_Callback, Stand_In_Ref, Read_Nothing, Stand_In_Name);

   Async_Table : Stand_In_Calls.Calls;

   procedure Note (Response : ROSIDL.Dynamic.Message) is
      Refused : Boolean := False;
   begin
      begin
         Async_Table.Check_Not_In_Callback;
      exception
         when ROS_Exception =>
            Refused := True;
      end;
      Stand_In.Add_Sum (Sum_Of (Response), Async_Table.In_Callback, Refused);
   end Note;

   procedure Asynchronous_Table (Unused : in out Fixture) is
      Response : constant ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Response_Support (Add_Support));
      Client   : constant Stand_In_Ref := The_Stand_In'Access;

      function Settled (Condition : access function return Boolean) return Boolean is
         Deadline : constant Ada.Real_Time.Time :=
           Ada.Real_Time.Clock + Ada.Real_Time.Seconds (5);
      begin
         while not Condition.all and Ada.Real_Time.Clock < Deadline loop
            delay 0.005;
         end loop;
         return Condition.all;
      end Settled;

      function None_Pending return Boolean is (Async_Table.Count = 0);
      function Pumped return Boolean is (Stand_In.Reads > 0);
      Reads_Before : Natural;
   begin
      Async_Table.Add (Client, 7, Note'Access, Timeout => 60.0);
      Assert (Async_Table.Count = 1 and Async_Table.Is_Pending (7), "call 7 pending");
      Assert (Settled (Pumped'Access), "the first call started the pump");
      Assert (not Async_Table.In_Callback, "not in a callback outside one");
      Async_Table.Check_Not_In_Callback;
      Response ("sum").As_Int64 := 11;
      Async_Table.Complete (7, Response);
      Assert (Stand_In.Sum = 11, "reply 7 ran its callback");
      Assert (Stand_In.All_In_Own_Callback, "the callback knows it is one");
      Assert (Stand_In.All_Refused, "a synchronous call from the callback is refused");
      Assert (Async_Table.Count = 0 and not Async_Table.Is_Pending (7), "call 7 done");
      Async_Table.Complete (7, Response);
      Assert (Stand_In.Sum = 11, "a duplicate reply runs nothing");

      --  The pump ended with the last call; a new call starts another,
      --  which forgets the call after its timeout.
      Async_Table.Add (Client, 8, Note'Access, Timeout => 0.05);
      Assert (Settled (None_Pending'Access), "call 8 forgotten after its timeout");
      Async_Table.Complete (8, Response);
      Assert (Stand_In.Sum = 11, "a late reply runs nothing");

      --  Stop drops what is pending, waits for the pump's end and starts
      --  no pump afterwards.
      Async_Table.Add (Client, 9, Note'Access, Timeout => 60.0);
      Async_Table.Add (Client, 10, Note'Access, Timeout => 60.0);
      Async_Table.Remove (10);
      Async_Table.Remove (10);
      Assert (Async_Table.Count = 1, "call 10 removed (twice is harmless)");
      Async_Table.Stop;
      Assert (Async_Table.Count = 0, "Stop dropped call 9");
      Reads_Before := Stand_In.Reads;
      Async_Table.Add (Client, 11, Note'Access, Timeout => 60.0);
      delay 0.05;
      Assert (Stand_In.Reads = Reads_Before, "no pump after Stop");
      Async_Table.Complete (11, Response);
      Assert (Stand_In.Sum = 22, "a reply read by a synchronous call still runs");
   end Asynchronous_Table;

   --  Ids ------------------------------------------------------------------

   procedure Ids (Unused : in out Fixture) is
      use RCL.DDS.Matching;
      Prefix : RCL.DDS.GUID := [others => 0];
   begin
      Prefix (1) := 16#01#;
      Prefix (2) := 16#0F#;
      Prefix (3) := 16#AB#;
      Prefix (16) := 16#FF#;  --  Replaced by the counter.
      Assert (Id_Image (Prefix, 258) = " 1.f.ab.0.0.0.0.0.0.0.0.0.0.0.1.2",
              "rmw_cyclonedds format: " & Id_Image (Prefix, 258));
      Prefix (1) := 16#C3#;
      Assert (Id_Image (Prefix, 16#0A0B0C0D#) = "c3.f.ab.0.0.0.0.0.0.0.0.0.a.b.c.d",
              "counter big-endian: " & Id_Image (Prefix, 16#0A0B0C0D#));
      Assert (User_Data_Value ("clientid=1.2.3;enclave=/;", "clientid") = "1.2.3", "first key");
      Assert (User_Data_Value ("clientid=1.2.3;enclave=/;", "enclave") = "/", "second key");
      Assert (User_Data_Value ("clientid=1.2.3;", "serviceid") = "", "absent key");
      Assert (User_Data_Value ("xclientid=4;clientid=5", "clientid") = "5",
              "whole key names only, last item without ';'");
      Assert (User_Data_Value ("", "clientid") = "", "empty user data");
   end Ids;

   --  In-process calls -------------------------------------------------------

   protected Async_Results is
      procedure Add (Value : ROSIDL.Int64);
      function Count return Natural;
      function Total return ROSIDL.Int64;
   private
      N   : Natural := 0;
      Sum : ROSIDL.Int64 := 0;
   end Async_Results;

   protected body Async_Results is
      procedure Add (Value : ROSIDL.Int64) is
      begin
         N := N + 1;
         Sum := Sum + Value;
      end Add;
      function Count return Natural is (N);
      function Total return ROSIDL.Int64 is (Sum);
   end Async_Results;

   procedure On_Async (Response : ROSIDL.Dynamic.Message) is
   begin
      Async_Results.Add (Sum_Of (Response));
   end On_Async;

   type Client_Access is access all RCL.Clients.Client;
   Self_Caller : Client_Access;

   type Self_Call_Outcome is (Not_Yet, Answered, Refused, Failed);

   protected Self_Call is
      procedure Set (Outcome : Self_Call_Outcome);
      function Get return Self_Call_Outcome;
   private
      Result : Self_Call_Outcome := Not_Yet;
   end Self_Call;

   protected body Self_Call is
      procedure Set (Outcome : Self_Call_Outcome) is
      begin
         Result := Outcome;
      end Set;
      function Get return Self_Call_Outcome is (Result);
   end Self_Call;

   procedure Call_Self (Response : ROSIDL.Dynamic.Message) is
      pragma Unreferenced (Response);
   begin
      if Sum_Of (Self_Caller.Call (Request (1, 1), 3.0)) = 2 then
         Self_Call.Set (Answered);
      end if;
   exception
      when ROS_Exception =>
         Self_Call.Set (Refused);
      when others =>
         Self_Call.Set (Failed);
   end Call_Self;
   --  An asynchronous callback making a synchronous call of its own client.

   procedure Calls (Unused : in out Fixture) is
      Server_Node : RCL.Nodes.Node := RCL.Nodes.Init ("svc_test_server", "/svc_tests");
      Client_Node : constant RCL.Nodes.Node := RCL.Nodes.Init ("svc_test_client", "/svc_tests");
      Stop        : Boolean := False with Atomic;

      task Spinner;
      task body Spinner is
      begin
         while not Stop loop
            Server_Node.Spin (During => 0.05);
         end loop;
      end Spinner;

      Client : aliased RCL.Clients.Client;
      Failures : Natural := 0 with Atomic;
      Done : Natural := 0 with Atomic;

      protected Count_Lock is
         procedure Fail;
         procedure Finish;
      end Count_Lock;
      protected body Count_Lock is
         procedure Fail is
         begin
            Failures := Failures + 1;
         end Fail;
         procedure Finish is
         begin
            Done := Done + 1;
         end Finish;
      end Count_Lock;

   begin
      Server_Node.Serve (Add_Support, "adder", Adder'Access);
      Client.Init (Client_Node, Add_Support, "adder");
      Assert (Client.Service_Name = "/svc_tests/adder", "relative name expanded");
      Assert (Client.Wait_For_Service (10.0), "service available");
      Assert (Sum_Of (Client.Call (Request (2, 3), 5.0)) = 5, "2 + 3");
      Assert (Sum_Of (Client_Node.Client_Call (Add_Support, "/svc_tests/adder",
                                               Request (40, 2), 5.0)) = 42,
              "Node.Client_Call");

      --  Eight tasks calling one client at once: each gets its own sum.
      declare
         task type Worker (Id : Natural);
         task body Worker is
         begin
            for I in 1 .. 25 loop
               declare
                  A : constant ROSIDL.Int64 := ROSIDL.Int64 (Id * 1000 + I);
                  B : constant ROSIDL.Int64 := ROSIDL.Int64 (I * 7);
               begin
                  if Sum_Of (Client.Call (Request (A, B), 10.0)) /= A + B then
                     Count_Lock.Fail;
                  end if;
               exception
                  when others =>
                     Count_Lock.Fail;
               end;
            end loop;
            Count_Lock.Finish;
         end Worker;
         W1 : Worker (1);
         W2 : Worker (2);
         W3 : Worker (3);
         W4 : Worker (4);
         W5 : Worker (5);
         W6 : Worker (6);
         W7 : Worker (7);
         W8 : Worker (8);
      begin
         null;
      end;
      Assert (Done = 8, "all workers ended");
      Assert (Failures = 0, Failures'Image & " concurrent calls got a wrong or no response");

      --  Two clients of one service: both readers see every reply of the
      --  topic, each keeps only its own (request header guid).
      declare
         Other      : RCL.Clients.Client;
         Other_Fail : Natural := 0 with Atomic;
      begin
         Other.Init (Client_Node, Add_Support, "adder");
         Assert (Other.Wait_For_Service (10.0), "second client sees the service");
         declare
            task Second;
            task body Second is
            begin
               for I in 1 .. 50 loop
                  if Sum_Of (Other.Call (Request (ROSIDL.Int64 (I), 1_000), 10.0))
                    /= ROSIDL.Int64 (I) + 1_000
                  then
                     Other_Fail := Other_Fail + 1;
                  end if;
               end loop;
            exception
               when others =>
                  Other_Fail := Other_Fail + 100;
            end Second;
         begin
            for I in 1 .. 50 loop
               if Sum_Of (Client.Call (Request (ROSIDL.Int64 (I), 2_000), 10.0))
                 /= ROSIDL.Int64 (I) + 2_000
               then
                  Count_Lock.Fail;
               end if;
            end loop;
         end;
         Assert (Other_Fail = 0 and Failures = 0, "each client got its own responses");
      end;

      --  Asynchronous calls.
      for I in 1 .. 100 loop
         Client.Call_Async (Request (ROSIDL.Int64 (I), 0), On_Async'Access, 10.0);
      end loop;
      declare
         Deadline : constant Ada.Real_Time.Time :=
           Ada.Real_Time.Clock + Ada.Real_Time.Seconds (10);
      begin
         while Async_Results.Count < 100 and Ada.Real_Time.Clock < Deadline loop
            delay 0.01;
         end loop;
      end;
      Assert (Async_Results.Count = 100,
              "100 asynchronous responses:" & Async_Results.Count'Image);
      Assert (Async_Results.Total = 5050, "their sums add up to 5050");
      Assert (Client.Pending_Async = 0, "none pending");

      --  A synchronous call from the client's own callback is refused (it
      --  would wait for itself: the callback holds the client's reading).
      Self_Caller := Client'Unchecked_Access;
      Client.Call_Async (Request (5, 6), Call_Self'Access, 10.0);
      declare
         Deadline : constant Ada.Real_Time.Time :=
           Ada.Real_Time.Clock + Ada.Real_Time.Seconds (10);
      begin
         while Self_Call.Get = Not_Yet and Ada.Real_Time.Clock < Deadline loop
            delay 0.01;
         end loop;
      end;
      Assert (Self_Call.Get = Refused,
              "a call from the own callback: " & Self_Call.Get'Image & ", REFUSED expected");
      Assert (Sum_Of (Client.Call (Request (2, 2), 5.0)) = 4, "the client works after it");

      --  A missing service times out.
      declare
         Nobody  : RCL.Clients.Client;
         Raised  : Boolean := False;
         Started : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
      begin
         Nobody.Init (Client_Node, Add_Support, "nobody_serves_this");
         begin
            Assert (Sum_Of (Nobody.Call (Request (1, 1), 0.3)) = 2, "unreachable");
         exception
            when E : RCL_Timeout =>
               Raised := Ada.Exceptions.Exception_Message (E)'Length > 0;
         end;
         Assert (Raised, "RCL_Timeout for a missing service");
         Assert (Ada.Real_Time.Clock - Started < Ada.Real_Time.Seconds (5),
                 "the timeout is honoured");
      end;

      --  A client finalized with an asynchronous call pending drops it and
      --  ends its pumping task at once (not after the call's timeout).
      declare
         Started : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
      begin
         declare
            Dropping : RCL.Clients.Client;
         begin
            Dropping.Init (Client_Node, Add_Support, "nobody_serves_this");
            Dropping.Call_Async (Request (1, 1), On_Async'Access, 60.0);
            Assert (Dropping.Pending_Async = 1, "the call is pending");
         end;
         Assert (Ada.Real_Time.Clock - Started < Ada.Real_Time.Seconds (5),
                 "finalized at once with a call pending");
         Assert (Async_Results.Count = 100, "the dropped call's callback did not run");
      end;
      Stop := True;
   exception
      when others =>
         Stop := True;
         raise;
   end Calls;

   --  Futures -----------------------------------------------------------------

   procedure Futures (Unused : in out Fixture) is
      --  The service and the client are on one node that nobody else spins:
      --  only Spin_Until_Complete makes the service answer.
      use type RCL.Clients.Future_Return_Code;
      Node   : RCL.Nodes.Node := RCL.Nodes.Init ("future_test", "/svc_tests");
      Client : RCL.Clients.Client;
      Served : Natural := 0;

      procedure Counting_Adder
        (Node     : in out RCL.Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message) is
      begin
         Served := Served + 1;
         Adder (Node, Request, Response);
      end Counting_Adder;

   begin
      Node.Serve (Add_Support, "future_adder", Counting_Adder'Access);
      Client.Init (Node, Add_Support, "future_adder");
      Assert (Client.Wait_For_Service (10.0), "service available");
      declare
         F : RCL.Clients.Future;
      begin
         Assert (not RCL.Clients.Is_Pending (F), "a new future stands for no call");
         Client.Call_Future (Request (20, 22), F);
         Assert (RCL.Clients.Is_Pending (F), "pending once called");
         Assert (RCL.Clients.Wait (F, Timeout => 0.3) = RCL.Clients.Timed_Out,
                 "nobody spins the node: no response");
         Assert (not RCL.Clients.Is_Ready (F) and Served = 0, "not served yet");
         Assert (RCL.Clients.Spin_Until_Complete (Node, F, Timeout => 10.0)
                   = RCL.Clients.Success,
                 "spinning the node serves the request");
         Assert (RCL.Clients.Is_Ready (F) and Served = 1, "ready, served once");
         Assert (Sum_Of (RCL.Clients.Response (F)) = 42, "20 + 22");
         Assert (Sum_Of (RCL.Clients.Response (F)) = 42, "the response stays available");
      end;
      --  Several futures at once, completed in any order.
      declare
         F1, F2, F3 : RCL.Clients.Future;
      begin
         Client.Call_Future (Request (1, 1), F1);
         Client.Call_Future (Request (2, 2), F2);
         Client.Call_Future (Request (3, 3), F3);
         Assert (RCL.Clients.Spin_Until_Complete (Node, F3, 10.0) = RCL.Clients.Success
                 and then RCL.Clients.Spin_Until_Complete (Node, F1, 10.0) = RCL.Clients.Success
                 and then RCL.Clients.Spin_Until_Complete (Node, F2, 10.0) = RCL.Clients.Success,
                 "three futures complete");
         Assert (Sum_Of (RCL.Clients.Response (F1)) = 2
                 and Sum_Of (RCL.Clients.Response (F2)) = 4
                 and Sum_Of (RCL.Clients.Response (F3)) = 6, "each its own response");
      end;
      --  A future dropped before its response: the late reply is dropped.
      declare
         F : RCL.Clients.Future;
      begin
         Client.Call_Future (Request (5, 5), F);
         Assert (Client.Pending_Calls = 1, "the future's call is pending");
      end;
      Assert (Client.Pending_Calls = 0, "a finalized future forgets its call");
      Node.Spin (During => 0.2);
      Assert (Client.Pending_Calls = 0, "nothing left pending");
      --  A missing service: the wait ends at its timeout.
      declare
         Nobody : RCL.Clients.Client;
         F      : RCL.Clients.Future;
      begin
         Nobody.Init (Node, Add_Support, "nobody_serves_this_future");
         Nobody.Call_Future (Request (1, 1), F);
         Assert (RCL.Clients.Spin_Until_Complete (Node, F, 0.3) = RCL.Clients.Timed_Out,
                 "Timed_Out for a missing service");
      end;
   end Futures;

   --  Graph queries on this process's own endpoints -------------------------

   procedure Own_Graph (Unused : in out Fixture) is
      use Ada.Strings.Unbounded;
      Node : RCL.Nodes.Node := RCL.Nodes.Init ("graph_test", "/gt");
      Pub  : constant RCL.Publishers.Publisher :=
        Node.Publish_Raw ("std_msgs::msg::dds_::String_", "out", RCL.QoS.Sensor_Data);
      pragma Unreferenced (Pub);

      procedure Adder
        (Node     : in out RCL.Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message) is null;

      function Has (List : Graph.Name_And_Types_Array; Name, Types : String)
        return Boolean is
        (for some E of List => E.Name = Name and then E.Types = Types);
   begin
      Node.Serve (Add_Support, "graph_add", Adder'Access);
      Graph.Wait_For_Discovery (0.2);
      Assert (Graph.Count_Publishers ("/gt/out") = 1, "one publisher on /gt/out");
      Assert (Graph.Count_Subscribers ("/gt/out") = 0, "no subscriber");
      Assert (Has (Graph.Topic_Names_And_Types, "/gt/out", "std_msgs/msg/String"),
              "topic with its type");
      Assert (Has (Graph.Service_Names_And_Types, "/gt/graph_add",
                   "example_interfaces/srv/AddTwoInts"), "service with its type");
      Assert (not Has (Graph.Topic_Names_And_Types, "/gt/graph_add",
                       "example_interfaces/srv/AddTwoInts"), "services are not topics");
      declare
         Info : constant Graph.Endpoint_Array := Graph.Publishers_Info ("/gt/out");
         use type RCL.QoS.Reliability_Policy;
      begin
         Assert (Info'Length = 1
                 and then Info (Info'First).QoS.Reliability = RCL.QoS.Best_Effort
                 and then Info (Info'First).QoS.Depth = 5, "endpoint QoS (sensor data)");
      end;
      declare
         Rosout : constant Graph.Endpoint_Array := Graph.Publishers_Info ("/rosout");
         use type RCL.QoS.Durability_Policy;
      begin
         Assert (Rosout'Length >= 1, "this process publishes /rosout");
         Assert (Rosout (Rosout'First).QoS.Lifespan = 10.0
                 and then Rosout (Rosout'First).QoS.Durability = RCL.QoS.Transient_Local,
                 "rosout QoS: lifespan 10 s, transient local");
      end;
   end Own_Graph;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("services: request/reply pairing", Pairing'Access));
      Result.Add_Test (Caller.Create ("services: asynchronous calls' table and pump",
                                      Asynchronous_Table'Access));
      Result.Add_Test (Caller.Create ("services: client/service ids, USER_DATA", Ids'Access));
      Result.Add_Test (Caller.Create ("services: sync, concurrent, async calls, timeout",
                                      Calls'Access));
      Result.Add_Test (Caller.Create ("services: futures, spin until complete",
                                      Futures'Access));
      Result.Add_Test (Caller.Create ("graph: own topics, services, QoS", Own_Graph'Access));
      return Result;
   end Suite;

end RCL.Services.Tests;
