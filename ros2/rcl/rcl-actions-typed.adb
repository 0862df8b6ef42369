with Ada.Strings.Fixed;
with ROSIDL.CDR;
with ROSIDL.Dynamic;

package body RCL.Actions.Typed is

   package Goals renames Handling.Goal_Handling;
   package Results renames Handling.Result_Handling;
   package Feedbacks renames Handling.Feedback_Handling;

   function Support return Action_Support is
      Full  : constant String := Handling.Full_Name;
      --  "pkg/action/Name"
      First : constant Natural := Ada.Strings.Fixed.Index (Full, "/");
      Last  : constant Natural := Ada.Strings.Fixed.Index (Full, "/", Ada.Strings.Backward);
   begin
      return Get_Action_Support (Full (Full'First .. First - 1), Full (Last + 1 .. Full'Last));
   end Support;

   --  Conversions through the CDR encoding (both codecs write the same
   --  bytes: tests/src/rosidl/rosidl-static-tests.adb).

   function To_Dynamic (Item : Goal) return ROSIDL.Dynamic.Message is
     (ROSIDL.CDR.Decode (Goal_Support (Support), Goals.Encode (Item)));

   function To_Dynamic (Item : Result) return ROSIDL.Dynamic.Message is
     (ROSIDL.CDR.Decode (Result_Support (Support), Results.Encode (Item)));

   function To_Dynamic (Item : Feedback) return ROSIDL.Dynamic.Message is
     (ROSIDL.CDR.Decode (Feedback_Support (Support), Feedbacks.Encode (Item)));

   function To_Goal (Msg : ROSIDL.Dynamic.Message) return Goal is
     (Goals.Decode (ROSIDL.CDR.Encode (Msg)));

   function To_Result (Msg : ROSIDL.Dynamic.Message) return Result is
     (Results.Decode (ROSIDL.CDR.Encode (Msg)));

   function To_Feedback (Msg : ROSIDL.Dynamic.Message) return Feedback is
     (Feedbacks.Decode (ROSIDL.CDR.Encode (Msg)));

   -----------
   -- Goals --
   -----------

   function Id (Handle : Goal_Handle) return Goal_Id is (Servers.Id (Handle.Dynamic));

   function Goal_Of (Handle : Goal_Handle) return Goal is
     (To_Goal (Servers.Goal (Handle.Dynamic)));

   function Status (Handle : Goal_Handle) return Goal_Status is
     (Servers.Status (Handle.Dynamic));

   function Is_Active (Handle : Goal_Handle) return Boolean is
     (Servers.Is_Active (Handle.Dynamic));

   function Is_Canceling (Handle : Goal_Handle) return Boolean is
     (Servers.Is_Canceling (Handle.Dynamic));

   procedure Execute (Handle : Goal_Handle) is
   begin
      Servers.Execute (Handle.Dynamic);
   end Execute;

   procedure Publish_Feedback (Handle : Goal_Handle; Progress : Feedback) is
   begin
      Servers.Publish_Feedback (Handle.Dynamic, To_Dynamic (Progress));
   end Publish_Feedback;

   procedure Succeed (Handle : Goal_Handle; Outcome : Result) is
   begin
      Servers.Succeed (Handle.Dynamic, To_Dynamic (Outcome));
   end Succeed;

   procedure Abort_Goal (Handle : Goal_Handle; Outcome : Result) is
   begin
      Servers.Abort_Goal (Handle.Dynamic, To_Dynamic (Outcome));
   end Abort_Goal;

   procedure Canceled (Handle : Goal_Handle; Outcome : Result) is
   begin
      Servers.Canceled (Handle.Dynamic, To_Dynamic (Outcome));
   end Canceled;

   ------------
   -- Server --
   ------------

   package body Server is

      The_Server : Servers.Server;

      function Dynamic_On_Goal
        (Node : in out RCL.Nodes.Node'Class;
         Id   : Goal_Id;
         Item : ROSIDL.Dynamic.Message) return Servers.Goal_Response is
        (On_Goal (Node, Id, To_Goal (Item)));

      procedure Dynamic_On_Accepted
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Servers.Goal_Handle) is
      begin
         On_Accepted (Node, (Dynamic => Goal));
      end Dynamic_On_Accepted;

      function Dynamic_On_Cancel
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Servers.Goal_Handle) return Servers.Cancel_Response is
        (On_Cancel (Node, (Dynamic => Goal)));

      procedure Init
        (Node           : in out RCL.Nodes.Node'Class;
         Name           : String;
         Result_Timeout : Duration := Servers.Default_Result_Timeout) is
      begin
         The_Server.Init (Node, Support, Name, Dynamic_On_Goal'Access,
                          Dynamic_On_Accepted'Access, Dynamic_On_Cancel'Access,
                          Result_Timeout);
      end Init;

      function Name return String is (The_Server.Name);

      function Active_Goals return Natural is (The_Server.Active_Goals);

      function Kept_Goals return Natural is (The_Server.Kept_Goals);

   end Server;

   ------------
   -- Client --
   ------------

   package body Client is

      The_Client : Clients.Client;

      procedure Dynamic_On_Feedback
        (Node     : in out RCL.Nodes.Node'Class;
         Goal     : Goal_Id;
         Progress : ROSIDL.Dynamic.Message) is
      begin
         On_Feedback (Node, Goal, To_Feedback (Progress));
      end Dynamic_On_Feedback;

      procedure Dynamic_On_Status
        (Node   : in out RCL.Nodes.Node'Class;
         Goal   : Goal_Id;
         Status : Goal_Status) is
      begin
         On_Status (Node, Goal, Status);
      end Dynamic_On_Status;

      procedure Init (Node : in out RCL.Nodes.Node'Class; Name : String) is
      begin
         The_Client.Init (Node, Support, Name, Dynamic_On_Feedback'Access,
                          Dynamic_On_Status'Access);
      end Init;

      function Status (Id : Goal_Id) return Goal_Status is (The_Client.Status (Id));

      function Follows (Id : Goal_Id) return Boolean is (The_Client.Follows (Id));

      function Followed_Goals return Natural is (The_Client.Followed_Goals);

      procedure Forget (Id : Goal_Id) is
      begin
         The_Client.Forget (Id);
      end Forget;

      function Server_Available return Boolean is (The_Client.Server_Available);

      procedure Wait_For_Server (Timeout : Duration := Clients.Forever) is
      begin
         The_Client.Wait_For_Server (Timeout);
      end Wait_For_Server;

      function Send_Goal (Item : Goal; Timeout : Duration := 10.0) return Goal_Id is
        (The_Client.Send_Goal (To_Dynamic (Item), Timeout));

      procedure Get_Result
        (Id      : Goal_Id;
         Status  : out Goal_Status;
         Outcome : out Result;
         Timeout : Duration := Clients.Forever)
      is
         Dynamic : ROSIDL.Dynamic.Message;
         Empty   : Result;
         pragma Warnings (Off, Empty);
         --  The generated record's defaults.
      begin
         The_Client.Get_Result (Id, Status, Dynamic, Timeout);
         Outcome := (if Status = Unknown then Empty else To_Result (Dynamic));
      end Get_Result;

      function Cancel_Goal (Id : Goal_Id; Timeout : Duration := 10.0) return Cancel_Code is
        (The_Client.Cancel_Goal (Id, Timeout));

   end Client;

end RCL.Actions.Typed;
