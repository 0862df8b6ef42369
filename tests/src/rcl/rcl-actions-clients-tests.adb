with Ada.Containers.Vectors;
with Ada.Real_Time;
with AUnit.Assertions; use AUnit.Assertions;
with ROSIDL.Dynamic;
with RCL.Actions.Servers;
with RCL.Nodes;
with Suite_Support; use Suite_Support;

package body RCL.Actions.Clients.Tests is

   use type Ada.Real_Time.Time;
   use type ROSIDL.Int32;

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
      Stop        : Boolean := False with Atomic;
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

      task type Spinner (Node : not null access RCL.Nodes.Node);
      task body Spinner is
      begin
         while not Stop loop
            Node.Spin (During => 0.05);
         end loop;
      end Spinner;

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
         S1 : Spinner (Server_Node'Access);
         S2 : Spinner (Client_Node'Access);
         S3 : Spinner (Other_Node'Access);
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

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("actions: clients follow their goals' status topic",
                                      Follows_Status'Access));
      return Result;
   end Suite;

end RCL.Actions.Clients.Tests;
