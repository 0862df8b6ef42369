--  Test program of tests/interop/test_actions.py: many Fibonacci goals
--  through one action client or one action server, to check that neither
--  keeps every goal it ever saw (the goal lifetime of RCL.Actions.Clients
--  and RCL.Actions.Servers).
--     action_churn client ACTION COUNT
--  sends COUNT goals one after the other (order I mod 5), takes each
--  result (exit status 1 unless SUCCEEDED); every 100 goals prints
--  "goals N followed F rss_kb R" (F: Clients.Followed_Goals, R: the
--  process's resident memory); at the end waits (10 s at most) until the
--  client follows no goal and prints "done followed F rss_kb R".
--     action_churn server ACTION RESULT_TIMEOUT
--  offers ACTION with that result timeout (s), succeeds every goal at once
--  (result: [order]); every 0.2 s prints "kept K rss_kb R" (Kept_Goals)
--  until killed.
with Ada.Command_Line;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with ROSIDL.Dynamic;
with RCL.Actions.Clients;
with RCL.Actions.Servers;
with RCL.Nodes;
with Action_Test_Support;

procedure Action_Churn is
   use Ada.Text_IO;
   use RCL.Actions;
   use type Ada.Real_Time.Time;
   use all type Action_Test_Support.Stop_Flag;

   package CL renames Ada.Command_Line;

   Support : constant Action_Support := Get_Action_Support ("example_interfaces", "Fibonacci");

   function Resident_KB return String is
      --  VmRSS of /proc/self/status, "?" when not found.
      F : File_Type;
   begin
      Open (F, In_File, "/proc/self/status");
      while not End_Of_File (F) loop
         declare
            Line  : constant String := Get_Line (F);
            First : Natural := Line'First + 6;
         begin
            if Line'Length > 6 and then Line (Line'First .. Line'First + 5) = "VmRSS:" then
               Close (F);
               while First <= Line'Last and then Line (First) not in '0' .. '9' loop
                  First := First + 1;
               end loop;
               return Ada.Strings.Fixed.Trim (Line (First .. Line'Last - 3), Ada.Strings.Both);
            end if;
         end;
      end loop;
      Close (F);
      return "?";
   end Resident_KB;

   function Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   procedure Run_Client (Name : String; Count : Positive) is
      Node   : aliased RCL.Nodes.Node := RCL.Nodes.Init ("action_churn_client");
      Client : Clients.Client;
      Stop   : aliased Action_Test_Support.Stop_Flag := False;
      Spin   : Action_Test_Support.Spinner (Node'Access, Stop'Access);
   begin
      Client.Init (Node, Support, Name);
      Client.Wait_For_Server (15.0);
      for I in 1 .. Count loop
         declare
            Goal   : constant ROSIDL.Dynamic.Message := Goal_Message (Support);
            Id     : Goal_Id;
            Status : Goal_Status;
            Result : ROSIDL.Dynamic.Message;
         begin
            Goal ("order").As_Int32 := ROSIDL.Int32 (I mod 5);
            Id := Client.Send_Goal (Goal);
            Client.Get_Result (Id, Status, Result, Timeout => 20.0);
            if Status /= Succeeded then
               Put_Line ("goal" & I'Image & " ended " & Status_Image (Status));
               CL.Set_Exit_Status (1);
               exit;
            end if;
         end;
         if I mod 100 = 0 then
            Put_Line ("goals " & Image (I) & " followed " & Image (Client.Followed_Goals)
                      & " rss_kb " & Resident_KB);
            Flush;
         end if;
      end loop;
      declare
         Deadline : constant Ada.Real_Time.Time :=
           Ada.Real_Time.Clock + Ada.Real_Time.Seconds (10);
      begin
         while Client.Followed_Goals > 0 and then Ada.Real_Time.Clock < Deadline loop
            delay 0.05;
         end loop;
      end;
      Put_Line ("done followed " & Image (Client.Followed_Goals) & " rss_kb " & Resident_KB);
      Stop := True;
   exception
      when others =>
         Stop := True;
         raise;
   end Run_Client;

   procedure On_Accepted (Node : in out RCL.Nodes.Node'Class; Goal : Servers.Goal_Handle) is
      pragma Unreferenced (Node);
   begin
      Action_Test_Support.Succeed_With_Order (Support, Goal);
   end On_Accepted;

   procedure Run_Server (Name : String; Timeout : Duration) is
      Node   : RCL.Nodes.Node := RCL.Nodes.Init ("action_churn_server");
      Server : Servers.Server;
      Next   : Ada.Real_Time.Time := Ada.Real_Time.Clock;
   begin
      Server.Init (Node, Support, Name, Action_Test_Support.Accept_Every_Goal'Access,
                   On_Accepted'Access, Result_Timeout => Timeout);
      loop
         Next := Next + Ada.Real_Time.Milliseconds (200);
         Node.Spin (During => Duration'Max
           (0.0, Ada.Real_Time.To_Duration (Next - Ada.Real_Time.Clock)));
         Put_Line ("kept " & Image (Server.Kept_Goals) & " rss_kb " & Resident_KB);
         Flush;
      end loop;
   end Run_Server;

begin
   if CL.Argument_Count = 3 and then CL.Argument (1) = "client" then
      Run_Client (CL.Argument (2), Positive'Value (CL.Argument (3)));
   elsif CL.Argument_Count = 3 and then CL.Argument (1) = "server" then
      Run_Server (CL.Argument (2), Duration'Value (CL.Argument (3)));
   else
      Put_Line (Standard_Error, "usage: action_churn client ACTION COUNT"
                & " | action_churn server ACTION RESULT_TIMEOUT");
      CL.Set_Exit_Status (2);
   end if;
end Action_Churn;
