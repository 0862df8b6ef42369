with Ada.Containers.Vectors;
with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Text_IO; use Ada.Text_IO;
with AUnit.Assertions; use AUnit.Assertions;
with ROSIDL.Dynamic;
with RCL.Actions.Servers;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with RCL.Services;
with Action_Test_Support;
with Suite_Support; use Suite_Support;

package body RCL.Actions.Clients.Tests is

   use type Ada.Real_Time.Time;
   use type ROSIDL.Int32;
   use type ROSIDL.Dynamic.Int32_Array;
   use all type Action_Test_Support.Stop_Flag;

   function Fibonacci return Action_Support is
     (Get_Action_Support ("example_interfaces", "Fibonacci"));

   function Goal_Of (Order : ROSIDL.Int32) return ROSIDL.Dynamic.Message is
      G : constant ROSIDL.Dynamic.Message := Goal_Message (Fibonacci);
   begin
      G ("order").As_Int32 := Order;
      return G;
   end Goal_Of;

   type Change is record
      Id : Goal_Id;
      To : Goal_Status;
   end record;

   package Change_Vectors is new Ada.Containers.Vectors (Positive, Change);

   type Change_Array is array (Positive range <>) of Change;

   function Same (Log : Change_Vectors.Vector; Expected : Change_Array) return Boolean is
     (Natural (Log.Length) = Expected'Length
      and then (for all I in Expected'Range => Log (I - Expected'First + 1) = Expected (I)));

   protected type Change_Log is
      procedure Add (C : Change);
      function Get return Change_Vectors.Vector;
   private
      Log : Change_Vectors.Vector;
   end Change_Log;

   protected body Change_Log is
      procedure Add (C : Change) is
      begin
         Log.Append (C);
      end Add;
      function Get return Change_Vectors.Vector is (Log);
   end Change_Log;

   type Handle_Array is array (ROSIDL.Int32 range 1 .. 9) of Servers.Goal_Handle;

   protected Accepted_Goals is
      procedure Put (Order : ROSIDL.Int32; Goal : Servers.Goal_Handle);
      function Get (Order : ROSIDL.Int32) return Servers.Goal_Handle;
   private
      Handles : Handle_Array;
   end Accepted_Goals;
   --  The server's goals by their order (the test's goals have 1 .. 9).

   protected body Accepted_Goals is
      procedure Put (Order : ROSIDL.Int32; Goal : Servers.Goal_Handle) is
      begin
         Handles (Order) := Goal;
      end Put;
      function Get (Order : ROSIDL.Int32) return Servers.Goal_Handle is (Handles (Order));
   end Accepted_Goals;

   function On_Goal
     (Node : in out RCL.Nodes.Node'Class;
      Id   : Goal_Id;
      Goal : ROSIDL.Dynamic.Message) return Servers.Goal_Response
   is
      pragma Unreferenced (Node, Id);
   begin
      return (if Goal ("order").As_Int32 in Handle_Array'Range then Servers.Accept_And_Defer
              else Servers.Reject);
   end On_Goal;
   --  Orders 1 .. 9 accepted (they stay Accepted until the test moves them).

   procedure On_Accepted (Node : in out RCL.Nodes.Node'Class; Goal : Servers.Goal_Handle) is
      pragma Unreferenced (Node);
   begin
      Accepted_Goals.Put (Servers.Goal (Goal) ("order").As_Int32, Goal);
   end On_Accepted;

   ------------
   -- Status --
   ------------

   procedure Follows_Status (Unused : in out Fixture) is
      Server_Node : aliased RCL.Nodes.Node := RCL.Nodes.Init ("act_test_server", "/act_tests");
      Client_Node : aliased RCL.Nodes.Node := RCL.Nodes.Init ("act_test_client", "/act_tests");
      Other_Node  : aliased RCL.Nodes.Node := RCL.Nodes.Init ("act_test_other", "/act_tests");
      Stop        : aliased Action_Test_Support.Stop_Flag := False;
      Mine, Theirs : Change_Log;

      procedure Log_Mine
        (Node : in out RCL.Nodes.Node'Class; Goal : Goal_Id; Status : Goal_Status) is
         pragma Unreferenced (Node);
      begin
         Mine.Add ((Goal, Status));
      end Log_Mine;

      procedure Log_Theirs
        (Node : in out RCL.Nodes.Node'Class; Goal : Goal_Id; Status : Goal_Status) is
         pragma Unreferenced (Node);
      begin
         Theirs.Add ((Goal, Status));
      end Log_Theirs;

      Server : Servers.Server;
      Client, Other : Clients.Client;
      Empty  : constant ROSIDL.Dynamic.Message := Result_Message (Fibonacci);

      --  Waits (10 s at most) until C's status of Id is Wanted.
      procedure Expect (C : Clients.Client; Id : Goal_Id; Wanted : Goal_Status; What : String) is
         Deadline : constant Ada.Real_Time.Time :=
           Ada.Real_Time.Clock + Ada.Real_Time.Seconds (10);
      begin
         while C.Status (Id) /= Wanted and then Ada.Real_Time.Clock < Deadline loop
            delay 0.01;
         end loop;
         Assert (C.Status (Id) = Wanted,
                 What & ": " & Status_Image (C.Status (Id)) & " after 10 s, expected "
                 & Status_Image (Wanted));
      end Expect;

      A, B, C, D, Rejected : Goal_Id;
      Was_Accepted : Boolean;
   begin
      Server.Init (Server_Node, Fibonacci, "fib", On_Goal'Access, On_Accepted'Access);
      Client.Init (Client_Node, Fibonacci, "fib", On_Status => Log_Mine'Access);
      Other.Init (Other_Node, Fibonacci, "/act_tests/fib", On_Status => Log_Theirs'Access);
      declare
         S1 : Action_Test_Support.Spinner (Server_Node'Access, Stop'Access);
         S2 : Action_Test_Support.Spinner (Client_Node'Access, Stop'Access);
         S3 : Action_Test_Support.Spinner (Other_Node'Access, Stop'Access);
      begin
         Client.Wait_For_Server (10.0);
         Other.Wait_For_Server (10.0);
         Assert (Client.Status (New_Goal_Id) = Unknown, "a goal never sent is Unknown");

         A := Client.Send_Goal (Goal_Of (1));
         Expect (Client, A, Accepted, "A deferred");
         Servers.Execute (Accepted_Goals.Get (1));
         Expect (Client, A, Executing, "A executed");
         B := Client.Send_Goal (Goal_Of (2));
         Expect (Client, B, Accepted, "B deferred");
         C := Other.Send_Goal (Goal_Of (3));
         Expect (Other, C, Accepted, "the other client's goal C");
         Servers.Succeed (Accepted_Goals.Get (1), Empty);
         Expect (Client, A, Succeeded, "A succeeded");
         Servers.Abort_Goal (Accepted_Goals.Get (2), Empty);
         Expect (Client, B, Aborted, "B aborted");
         Servers.Execute (Accepted_Goals.Get (3));
         Expect (Other, C, Executing, "C executed");
         Assert (Other.Cancel_Goal (C) = Error_None, "C's cancel accepted");
         Expect (Other, C, Canceling, "C canceling");
         Servers.Canceled (Accepted_Goals.Get (3), Empty);
         Expect (Other, C, Canceled, "C canceled");
         D := Client.Send_Goal (Goal_Of (4));
         Expect (Client, D, Accepted, "D deferred");
         Client.Send_Goal (Goal_Of (-1), Rejected, Was_Accepted);
         Assert (not Was_Accepted, "order -1 rejected");
         delay 0.3;  --  Would a status of the rejected goal come, it would be now.
         Assert (Client.Status (Rejected) = Unknown, "a rejected goal stays Unknown");
         Assert (Client.Status (C) = Unknown and then Other.Status (A) = Unknown,
                 "a client knows no status of the other's goals");
         Stop := True;
      exception
         when others =>
            Stop := True;
            raise;
      end;
      Assert (Same (Mine.Get, [Change'(A, Accepted), (A, Executing), (B, Accepted),
                               (A, Succeeded), (B, Aborted), (D, Accepted)]),
              "the client's callback: each change of its own goals, in order, once");
      Assert (Same (Theirs.Get, [Change'(C, Accepted), (C, Executing), (C, Canceling),
                                 (C, Canceled)]),
              "the other client's callback: its goal only");
   end Follows_Status;

   --------------------
   -- Goal lifetime --
   --------------------

   Quick_Orders : constant := 50;
   --  The lifetime test's server ends goals of lower orders at once, keeps
   --  the others executing (Parked) until the test ends them.

   protected Parked is
      procedure Put (Goal : Servers.Goal_Handle);
      function Get return Servers.Goal_Handle;
   private
      Last : Servers.Goal_Handle;
   end Parked;

   protected body Parked is
      procedure Put (Goal : Servers.Goal_Handle) is
      begin
         Last := Goal;
      end Put;
      function Get return Servers.Goal_Handle is (Last);
   end Parked;

   procedure On_Executing (Node : in out RCL.Nodes.Node'Class; Goal : Servers.Goal_Handle) is
      pragma Unreferenced (Node);
   begin
      if Servers.Goal (Goal) ("order").As_Int32 < Quick_Orders then
         Action_Test_Support.Succeed_With_Order (Fibonacci, Goal);
      else
         Parked.Put (Goal);
      end if;
   end On_Executing;

   procedure Bounded_Lifetime (Unused : in out Fixture) is
      Timeout     : constant Duration := 2.0;
      --  The server's result timeout: a result is asked for right after
      --  its goal's acceptance, so shorter would do on a machine not loaded
      --  (0.5 s failed once with a load average of 19 on 2 cores).
      Server_Node : aliased RCL.Nodes.Node := RCL.Nodes.Init ("act_life_server", "/act_tests");
      Client_Node : aliased RCL.Nodes.Node := RCL.Nodes.Init ("act_life_client", "/act_tests");
      Stop        : aliased Action_Test_Support.Stop_Flag := False;

      Server : Servers.Server;
      Client : Clients.Client;
      Empty  : constant ROSIDL.Dynamic.Message := Result_Message (Fibonacci);

      Goals : constant := 1000;
      Taken : array (1 .. Goals) of Ada.Real_Time.Time;
      --  When each goal's result was taken.

      --  Goals whose result was taken within Window before goal Last's.
      function Recent (Last : Positive; Window : Duration) return Natural is
         From : constant Ada.Real_Time.Time :=
           Taken (Last) - Ada.Real_Time.To_Time_Span (Window);
         N    : Natural := 0;
      begin
         for I in reverse 1 .. Last loop
            exit when Taken (I) < From;
            N := N + 1;
         end loop;
         return N;
      end Recent;

      procedure Wait_Until
        (Done : not null access function return Boolean; What : String; Limit : Duration := 10.0)
      is
         Deadline : constant Ada.Real_Time.Time :=
           Ada.Real_Time.Clock + Ada.Real_Time.To_Time_Span (Limit);
      begin
         while not Done.all and then Ada.Real_Time.Clock < Deadline loop
            delay 0.01;
         end loop;
         Assert (Done.all, What & " (after" & Limit'Image & " s)");
      end Wait_Until;

      Max_Followed, Max_Kept, Max_Followed_Bound, Max_Kept_Bound : Natural := 0;
      Started : Ada.Real_Time.Time;
      Id      : Goal_Id;
      Status  : Goal_Status;
      Result  : ROSIDL.Dynamic.Message;
   begin
      Server.Init (Server_Node, Fibonacci, "life", Action_Test_Support.Accept_Every_Goal'Access,
                   On_Executing'Access, Result_Timeout => Timeout);
      Client.Init (Client_Node, Fibonacci, "life");
      declare
         S1 : Action_Test_Support.Spinner (Server_Node'Access, Stop'Access);
         S2 : Action_Test_Support.Spinner (Client_Node'Access, Stop'Access);

         function Client_Empty return Boolean is (Client.Followed_Goals = 0);
         function Server_Empty return Boolean is (Server.Kept_Goals = 0);
         function Not_Followed return Boolean is (not Client.Follows (Id));
         function Ended return Boolean is (Client.Status (Id) = Succeeded);
      begin
         Client.Wait_For_Server (10.0);
         Started := Ada.Real_Time.Clock;
         for I in 1 .. Goals loop
            Id := Client.Send_Goal (Goal_Of (ROSIDL.Int32 (I mod Quick_Orders)));
            Client.Get_Result (Id, Status, Result, Timeout => 10.0);
            Taken (I) := Ada.Real_Time.Clock;
            Assert (Status = Succeeded, "goal" & I'Image & ": " & Status_Image (Status));
            Assert (Result ("sequence").Get_Int32_Array = [ROSIDL.Int32 (I mod Quick_Orders)],
                    "goal" & I'Image & "'s result");
            --  The client follows the goals whose results were taken within
            --  Status_Linger (if their terminal status did not come yet);
            --  the server keeps those ended within its result timeout. The
            --  margins: the time between a count and the goal's end.
            declare
               Followed : constant Natural := Client.Followed_Goals;
               Kept     : constant Natural := Server.Kept_Goals;
               Followed_Bound : constant Natural := Recent (I, Clients.Status_Linger + 0.5);
               Kept_Bound     : constant Natural := Recent (I, Timeout + 2.0);
            begin
               Assert (Followed <= Followed_Bound,
                       "goal" & I'Image & ": the client follows" & Followed'Image
                       & " goals, more than the" & Followed_Bound'Image & " taken lately");
               Assert (Kept <= Kept_Bound,
                       "goal" & I'Image & ": the server keeps" & Kept'Image
                       & " goals, more than the" & Kept_Bound'Image & " ended lately");
               Max_Followed := Natural'Max (Max_Followed, Followed);
               Max_Kept := Natural'Max (Max_Kept, Kept);
               Max_Followed_Bound := Natural'Max (Max_Followed_Bound, Followed_Bound);
               Max_Kept_Bound := Natural'Max (Max_Kept_Bound, Kept_Bound);
            end;
         end loop;
         Put_Line ("actions lifetime:" & Goals'Image & " goals in"
                   & Duration'Image (Ada.Real_Time.To_Duration
                       (Ada.Real_Time.Clock - Started))
                   & " s; client followed at most" & Max_Followed'Image & " (bound"
                   & Max_Followed_Bound'Image & "), server kept at most" & Max_Kept'Image
                   & " (bound" & Max_Kept_Bound'Image & ")");
         Wait_Until (Client_Empty'Access, "the client follows no goal once all results came");
         Wait_Until (Server_Empty'Access, "the server drops every goal after its result timeout");

         --  A goal whose result is never taken: followed until the server
         --  expires it (its status array, published again, omits it).
         Id := Client.Send_Goal (Goal_Of (3));
         Wait_Until (Ended'Access, "goal 3 ends on the status topic");
         Assert (Client.Follows (Id), "a goal ended but whose result was not taken is followed");
         Wait_Until (Not_Followed'Access, "a goal the server expired is no longer followed");
         Assert (Client.Status (Id) = Unknown, "an expired goal's status is Unknown");
         Client.Get_Result (Id, Status, Result, Timeout => 10.0);
         Assert (Status = Unknown, "get_result of an expired goal: " & Status_Image (Status));
         Assert (Client.Cancel_Goal (Id) = Error_Unknown_Goal_Id, "cancel of an expired goal");

         --  Forget: the server keeps the goal, the client no longer follows it.
         Id := Client.Send_Goal (Goal_Of (Quick_Orders));
         Assert (Client.Follows (Id) and Client.Followed_Goals = 1, "a running goal is followed");
         Client.Forget (Id);
         Client.Forget (Id);  --  Again: nothing.
         Client.Forget (New_Goal_Id);  --  Never sent: nothing.
         Assert (not Client.Follows (Id) and Client.Followed_Goals = 0, "a forgotten goal");
         Assert (Client.Status (Id) = Unknown, "a forgotten goal's status is Unknown");
         Assert (Client.Cancel_Goal (Id) = Error_None, "a forgotten goal can still be canceled");
         Servers.Canceled (Parked.Get, Empty);
         Client.Get_Result (Id, Status, Result, Timeout => 10.0);
         Assert (Status = Canceled, "a forgotten goal's result: " & Status_Image (Status));
         Assert (not Client.Follows (Id), "taking a forgotten goal's result follows it not again");
         Wait_Until (Server_Empty'Access, "the server drops the canceled goal");
         Assert (Servers.Status (Parked.Get) = Unknown, "an expired goal handle's status");
         Stop := True;
      exception
         when others =>
            Stop := True;
            raise;
      end;
   end Bounded_Lifetime;

   ---------------------------
   -- Server availability --
   ---------------------------

   procedure Never_Answer
     (Node     : in out RCL.Nodes.Node'Class;
      Request  : ROSIDL.Dynamic.Message;
      Response : in out ROSIDL.Dynamic.Message) is null;

   procedure Ignore_Feedback
     (Node     : in out RCL.Nodes.Node'Class;
      Goal     : Goal_Id;
      Feedback : ROSIDL.Dynamic.Message) is null;

   procedure Availability (Unused : in out Fixture) is
      --  A peer serving the three services of an action, then publishing
      --  its status topic, then its feedback topic: as
      --  rcl_action_server_is_available, a client has a server only once
      --  its status (and, with On_Feedback, feedback) subscription matched
      --  too. Before, the services alone made a server: a goal could be
      --  sent while the feedback reader matched no writer yet, and the
      --  first feedback was lost (test_actions, fresh-clone CI).
      use type Ada.Real_Time.Time_Span;
      Action      : constant String := "/act_tests/avail";
      Peer_Node   : RCL.Nodes.Node := RCL.Nodes.Init ("act_avail_peer", "/act_tests");
      Client_Node : RCL.Nodes.Node := RCL.Nodes.Init ("act_avail_client", "/act_tests");
      Fed, Plain, Unopened : Clients.Client;
      --  With a feedback subscription, without, not initialised.

      function Services_Up return Boolean is
        (Fed.Send.Service_Available and then Fed.Cancel.Service_Available
         and then Fed.Results.Service_Available and then Plain.Send.Service_Available
         and then Plain.Cancel.Service_Available and then Plain.Results.Service_Available);

      procedure Expect_Timeout (C : Clients.Client; Timeout : Duration; Missing : String) is
         Started : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
         Waited  : Duration;
      begin
         C.Wait_For_Server (Timeout);
         Assert (False, "Wait_For_Server returned, " & Missing & " missing");
      exception
         when E : RCL_Timeout =>
            Waited := Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Started);
            Assert (Contains (Ada.Exceptions.Exception_Message (E),
                              "action " & Action & ": no server available after")
                    and then Contains (Ada.Exceptions.Exception_Message (E),
                                       "(missing: " & Missing & ")"),
                    Ada.Exceptions.Exception_Message (E));
            Assert (Waited >= Timeout and then Waited < Timeout + 2.0,
                    "Wait_For_Server (" & Timeout'Image & ") took" & Waited'Image & " s");
      end Expect_Timeout;

      Deadline : constant Ada.Real_Time.Time := Ada.Real_Time.Clock + Ada.Real_Time.Seconds (10);
   begin
      RCL.Services.Serve (Peer_Node, Send_Goal_Support (Fibonacci), Action & Send_Goal_Suffix,
                          Never_Answer'Access);
      RCL.Services.Serve (Peer_Node, Cancel_Support, Action & Cancel_Suffix,
                          Never_Answer'Access);
      RCL.Services.Serve (Peer_Node, Get_Result_Support (Fibonacci), Action & Get_Result_Suffix,
                          Never_Answer'Access);
      Fed.Init (Client_Node, Fibonacci, "avail", On_Feedback => Ignore_Feedback'Access);
      Plain.Init (Client_Node, Fibonacci, "avail");
      while not Services_Up and then Ada.Real_Time.Clock < Deadline loop
         delay 0.01;
      end loop;
      Assert (Services_Up, "the three services are available to both clients (10 s)");
      Assert (not Fed.Server_Available and then not Plain.Server_Available,
              "the three services alone make no server");
      Expect_Timeout (Fed, 0.3, "status publisher, feedback publisher");
      Expect_Timeout (Plain, 0.3, "status publisher");
      declare
         Status : constant RCL.Publishers.Publisher :=
           Peer_Node.Publish (Status_Support, Action & Status_Suffix, RCL.QoS.Action_Status);
         pragma Unreferenced (Status);
      begin
         Plain.Wait_For_Server (10.0);
         Assert (Plain.Server_Available, "services and status: a server for a client without "
                 & "feedback subscription");
         Assert (not Fed.Server_Available, "no feedback publisher: no server for a client "
                 & "with a feedback subscription");
         Expect_Timeout (Fed, 0.2, "feedback publisher");
         declare
            Feedback : constant RCL.Publishers.Publisher :=
              Peer_Node.Publish (Feedback_Message_Support (Fibonacci), Action & Feedback_Suffix);
            pragma Unreferenced (Feedback);
         begin
            Fed.Wait_For_Server (10.0);
            Assert (Fed.Server_Available and then Plain.Server_Available,
                    "services, status and feedback: a server for both clients");
         end;
      end;
      Assert (not Unopened.Server_Available, "a client not initialised has no server");
   end Availability;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("actions: clients follow their goals' status topic",
                                      Follows_Status'Access));
      Result.Add_Test (Caller.Create ("actions: 1000 goals, bounded client and server goal sets",
                                      Bounded_Lifetime'Access));
      Result.Add_Test (Caller.Create ("actions: a server is available once its services, "
                                      & "status and feedback topics matched",
                                      Availability'Access));
      return Result;
   end Suite;

end RCL.Actions.Clients.Tests;
