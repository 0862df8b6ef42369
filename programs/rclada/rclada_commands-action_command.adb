--  rclada action list | info | type | send_goal, as "ros2 action".
with RCL.Actions.Clients;

separate (Rclada_Commands)
procedure Action_Command (Args : Arguments) is
   use RCL.Actions;
   use type Graph.Endpoint_Kind;

   Pos : constant Arguments := Positional (Args);

   Goal_Suffix : constant String := "_SendGoal";

   --  The actions on the network: their send_goal services.
   procedure For_Each_Action
     (Process : not null access procedure (Name, Type_Name : String)) is
   begin
      for S of Graph.Service_Names_And_Types loop
         declare
            N : constant String := To_String (S.Name);
            T : constant String := To_String (S.Types);
         begin
            if N'Length > Send_Goal_Suffix'Length
              and then N (N'Last - Send_Goal_Suffix'Length + 1 .. N'Last) = Send_Goal_Suffix
            then
               Process (N (N'First .. N'Last - Send_Goal_Suffix'Length),
                        (if T'Length > Goal_Suffix'Length
                           and then T (T'Last - Goal_Suffix'Length + 1 .. T'Last) = Goal_Suffix
                         then T (T'First .. T'Last - Goal_Suffix'Length) else T));
            end if;
         end;
      end loop;
   end For_Each_Action;

   function Action_Type (Name : String) return String is
      Found : Unbounded_String;
      procedure Check (N, T : String) is
      begin
         if N = Name then
            Found := To_Unbounded_String (T);
         end if;
      end Check;
   begin
      For_Each_Action (Check'Access);
      if Found = "" then
         raise Command_Error with "action " & Name & " not found";
      end if;
      return To_String (Found);
   end Action_Type;

   procedure List is
      procedure Show (N, T : String) is
      begin
         Put_Line (if Has_Flag (Args, "-t", "--show-types") then N & " [" & T & "]" else N);
      end Show;
   begin
      For_Each_Action (Show'Access);
   end List;

   procedure Info (Name : String) is
      Type_Name : constant String := Action_Type (Name);
      Request   : constant String := "rq" & Name & Send_Goal_Suffix & "Request";
      Servers, Clients : Unbounded_String;
      N_Servers, N_Clients : Natural := 0;
      Types : constant Boolean := Has_Flag (Args, "-t", "--show-types");
   begin
      for Node of Graph.Node_Names loop
         for E of Graph.Node_Endpoints (Node) loop
            if To_String (E.DDS_Topic) = Request then
               declare
                  Line : constant String := "    " & Graph.Fully_Qualified (Node)
                    & (if Types then " [" & Type_Name & "]" else "") & LF;
               begin
                  if E.Kind = Graph.Subscription then
                     Append (Servers, Line);
                     N_Servers := N_Servers + 1;
                  else
                     Append (Clients, Line);
                     N_Clients := N_Clients + 1;
                  end if;
               end;
            end if;
         end loop;
      end loop;
      Put_Line ("Action: " & Name);
      Put_Line ("Action clients:" & N_Clients'Image);
      Put (To_String (Clients));
      Put_Line ("Action servers:" & N_Servers'Image);
      if N_Servers > 0 then
         Put_Lines (To_String (Servers));
      end if;
   end Info;

   --  "pkg/action/Name" (or "pkg/Name") -> its support.
   function Support_Of (Name : String) return Action_Support is
      First : constant Natural := Ada.Strings.Fixed.Index (Name, "/");
      Last  : constant Natural :=
        Ada.Strings.Fixed.Index (Name, "/", Going => Ada.Strings.Backward);
   begin
      if First = 0 then
         raise Command_Error with "action type '" & Name & "': expected pkg/action/Name";
      elsif First /= Last and then Name (First + 1 .. Last - 1) /= "action" then
         raise Command_Error with "action type '" & Name & "': expected pkg/action/Name";
      end if;
      return Get_Action_Support (Name (Name'First .. First - 1), Name (Last + 1 .. Name'Last));
   end Support_Of;

   procedure Send_Goal (Name, Type_Name, Text : String) is
      Support  : constant Action_Support := Support_Of (Type_Name);
      Goal     : constant ROSIDL.Dynamic.Message := Message_From (Goal_Support (Support), Text);
      Feedback : constant Boolean := Has_Flag (Args, "-f", "--feedback");
      Statuses : constant Boolean := Has_Flag (Args, "-s", "--status");
      Node     : RCL.Nodes.Node := Tool_Node;
      Client   : RCL.Actions.Clients.Client;
      Id       : Goal_Id;
      Accepted : Boolean;
      Saw_End  : Boolean := False with Atomic;
      --  The status topic gave the goal a terminal status.

      procedure On_Feedback
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Goal_Id;
         Msg  : ROSIDL.Dynamic.Message)
      is
         pragma Unreferenced (Node, Goal);
      begin
         Put_Line ("Feedback:");
         Put_Block (Indented (ROSIDL.Dynamic.Image (Msg)));
         New_Line;
         Flush;
      exception
         when Ada.IO_Exceptions.Device_Error =>
            Output_Closed;
      end On_Feedback;

      --  The goal's status changes, from the action's status topic.
      procedure On_Status
        (Node   : in out RCL.Nodes.Node'Class;
         Goal   : Goal_Id;
         Status : Goal_Status)
      is
         pragma Unreferenced (Node, Goal);
      begin
         Saw_End := Status in Terminal_Status;
         Put_Line ("Goal status: " & Status_Image (Status));
         New_Line;
         Flush;
      exception
         when Ada.IO_Exceptions.Device_Error =>
            Output_Closed;
      end On_Status;

      protected Outcome is
         procedure Set (S : Goal_Status; R : ROSIDL.Dynamic.Message; Error : String);
         function Done return Boolean;
         function Status return Goal_Status;
         function Result return ROSIDL.Dynamic.Message;
         function Error return String;
      private
         Is_Done : Boolean := False;
         Final   : Goal_Status := Unknown;
         Value   : ROSIDL.Dynamic.Message;
         Problem : Unbounded_String;
      end Outcome;

      protected body Outcome is
         procedure Set (S : Goal_Status; R : ROSIDL.Dynamic.Message; Error : String) is
         begin
            Final := S;
            Value := R;
            Problem := To_Unbounded_String (Error);
            Is_Done := True;
         end Set;
         function Done return Boolean is (Is_Done);
         function Status return Goal_Status is (Final);
         function Result return ROSIDL.Dynamic.Message is (Value);
         function Error return String is (To_String (Problem));
      end Outcome;
   begin
      Client.Init (Node, Support, Checked_Name (Name),
                   (if Feedback then On_Feedback'Access else null),
                   (if Statuses then On_Status'Access else null));
      Put_Line ("Waiting for an action server to become available...");
      Client.Wait_For_Server (Duration (Number_Option (Args, "--timeout", "10.0")));
      Put_Line ("Sending goal:");
      Put_Block (Indented (ROSIDL.Dynamic.Image (Goal), "     "));
      New_Line;
      Client.Send_Goal (Goal, Id, Accepted);
      if not Accepted then
         Put_Line ("Goal was rejected.");
         return;
      end if;
      Put_Line ("Goal accepted with ID: " & Image (Id));
      New_Line;
      Flush;
      declare
         task Waiter;
         task body Waiter is
            Status : Goal_Status;
            Result : ROSIDL.Dynamic.Message;
         begin
            Client.Get_Result (Id, Status, Result);
            Outcome.Set (Status, Result, "");
         exception
            when E : others =>
               Outcome.Set (Unknown, Result, Ada.Exceptions.Exception_Message (E));
         end Waiter;
      begin
         while not Outcome.Done loop
            Node.Spin (During => 0.05);
         end loop;
         if RCL.Contexts.Is_Shutdown and then Outcome.Error /= "" then
            return;  --  Ctrl-C or closed output.
         elsif Outcome.Error /= "" then
            raise Command_Error with Outcome.Error;
         end if;
         Node.Spin (During => 0.05);  --  The last feedback, if any.
         if Statuses and then Outcome.Status in Terminal_Status then
            --  The status topic's word on the end (it may come after the
            --  result); a server that never publishes it costs 1 s. Not
            --  Client.Status: the client stops following the goal once
            --  both came.
            declare
               Deadline : constant Ada.Real_Time.Time :=
                 Ada.Real_Time.Clock + Ada.Real_Time.Seconds (1);
            begin
               while not Saw_End
                 and then Ada.Real_Time.Clock < Deadline
               loop
                  Node.Spin (During => 0.05);
               end loop;
            end;
         end if;
         Put_Line ("Result:");
         Put_Block (Indented (ROSIDL.Dynamic.Image (Outcome.Result)));
         New_Line;
         Put_Line ("Goal finished with status: " & Status_Image (Outcome.Status));
      end;
   exception
      when E : RCL.RCL_Timeout =>
         raise Command_Error with Ada.Exceptions.Exception_Message (E);
   end Send_Goal;

begin
   if Pos.Is_Empty then
      raise Usage_Error with "missing sub-command (list, info, type, send_goal)";
   elsif Pos (1) = "list" then
      Check_Options (Args, "-t --show-types --spin-time");
      Discover (Args);
      List;
   elsif Pos (1) in "info" | "type" then
      Check_Options (Args, "-t --show-types --spin-time");
      if Natural (Pos.Length) /= 2 then
         raise Usage_Error with "action " & Pos (1) & " takes an action name";
      end if;
      Discover (Args);
      if Pos (1) = "info" then
         Info (Fully_Qualified (Pos (2)));
      else
         Put_Line (Action_Type (Fully_Qualified (Pos (2))));
      end if;
   elsif Pos (1) = "send_goal" then
      Check_Options (Args, "-f --feedback -s --status --timeout");
      if Natural (Pos.Length) /= 4 then
         raise Usage_Error with "action send_goal takes an action name, a type and a goal";
      end if;
      Send_Goal (Pos (2), Pos (3), Pos (4));
   else
      raise Usage_Error with "unknown action sub-command '" & Pos (1) & "'";
   end if;
end Action_Command;
