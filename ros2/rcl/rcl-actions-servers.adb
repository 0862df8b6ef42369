with Ada.Containers.Ordered_Maps;
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;
with ROSIDL.CDR;
with ROSIDL.Typesupport;
with RCL.Clocks;
with RCL.Publishers;
with RCL.QoS;
with RCL.Services;
with RCL.Timers;

package body RCL.Actions.Servers is

   use ROSIDL.Dynamic;
   use type RCL.Clocks.Nanoseconds;
   use type RCL.Services.Request_Id;

   type Goal_Callback is access function
     (Node : in out RCL.Nodes.Node'Class;
      Id   : Goal_Id;
      Goal : ROSIDL.Dynamic.Message) return Goal_Response;
   type Accepted_Callback is access procedure
     (Node : in out RCL.Nodes.Node'Class;
      Goal : Goal_Handle);
   type Cancel_Callback is access function
     (Node : in out RCL.Nodes.Node'Class;
      Goal : Goal_Handle) return Cancel_Response;

   package Request_Vectors is new Ada.Containers.Vectors (Positive, RCL.Services.Request_Id);

   type Goal_Entry is record
      Goal     : Message;
      Stamp    : Long_Long_Integer := 0;
      --  Acceptance time (ROS time, ns).
      Status   : Goal_Status := Accepted;
      Result   : Message;
      Ended_At : RCL.Clocks.Nanoseconds := 0;
      --  Steady clock.
      Waiting  : Request_Vectors.Vector;
      --  get_result requests to answer when the goal ends.
   end record;

   package Goal_Maps is new Ada.Containers.Ordered_Maps (Goal_Id, Goal_Entry);
   package Id_Vectors is new Ada.Containers.Vectors (Positive, Goal_Id);

   type Status_Item is record
      Id     : Goal_Id;
      Stamp  : Long_Long_Integer;
      Status : Goal_Status;
   end record;
   package Status_Vectors is new Ada.Containers.Vectors (Positive, Status_Item);

   function Allowed (From, To : Goal_Status) return Boolean is
     (case From is
         when Accepted  => To in Executing | Canceling | Aborted,
         when Executing => To in Canceling | Succeeded | Aborted,
         when Canceling => To in Succeeded | Aborted | Canceled,
         when others    => False);
   --  rcl_action's goal state machine (plus accepted -> aborted, which
   --  rclcpp allows on shutdown).

   type Transition_Outcome is record
      Done    : Boolean := False;
      Current : Goal_Status := Unknown;
      --  The status before the transition.
      Waiting : Request_Vectors.Vector;
      --  The get_result requests to answer now (the goal ended).
   end record;

   function Expired
     (E : Goal_Entry; Now, Timeout_Ns : RCL.Clocks.Nanoseconds) return Boolean is
     (E.Status in Terminal_Status and then Now - E.Ended_At > Timeout_Ns);
   --  E's result has expired (the goal is gone, even if still in the map).

   protected type Goal_Table (Timeout_Ns : RCL.Clocks.Nanoseconds) is
      procedure Add (Id : Goal_Id; Goal : Message; Stamp : Long_Long_Integer; Added : out Boolean);
      function Status_Of (Id : Goal_Id) return Goal_Status;
      --  Unknown for a goal never accepted or whose result has expired (as
      --  the other operations: an expired goal is as one never accepted).
      function Goal_Of (Id : Goal_Id) return Message;
      procedure Transition
        (Id : Goal_Id; To : Goal_Status; Result : Message; Outcome : out Transition_Outcome);
      --  When allowed (Outcome.Done): To, Result kept, the queued get_result
      --  requests handed out.
      procedure Wait_Result
        (Id : Goal_Id; Request : RCL.Services.Request_Id;
         Status : out Goal_Status; Result : out Message);
      --  Status terminal or Unknown: answer now with Result; else queued.
      procedure Snapshot (List : out Status_Vectors.Vector);
      --  Every goal, after dropping expired results.
      procedure Expire (Dropped : out Natural);
      --  Drops the goals whose result has expired.
      function Active return Natural;
      function Count return Natural;
      --  Goals in the table (expired ones not dropped yet included).
      function Cancel_Candidates
        (Id : Goal_Id; Before : Long_Long_Integer) return Status_Vectors.Vector;
      --  The goals a cancel request designates (action_msgs/CancelGoal:
      --  zero id and stamp = all; a stamp = those accepted at or before).
   private
      Goals : Goal_Maps.Map;
   end Goal_Table;

   type Publisher_Access is access RCL.Publishers.Publisher;

   type Result_Server;
   type Result_Server_Access is access all Result_Server;

   type Server_State (Timeout_Ns : RCL.Clocks.Nanoseconds) is limited record
      Expiry      : RCL.Timers.Timer;
      --  Drops expired results (Expire_Results) while the node spins.
      Support     : Action_Support;
      Name        : Ada.Strings.Unbounded.Unbounded_String;
      On_Goal     : Goal_Callback;
      On_Accepted : Accepted_Callback;
      On_Cancel   : Cancel_Callback;
      Feedback    : Publisher_Access;
      Status      : Publisher_Access;
      Results     : Result_Server_Access;
      Goals       : Goal_Table (Timeout_Ns);
   end record;

   --  The three services ---------------------------------------------------

   type Action_Service is abstract new RCL.Services.Server with record
      State : State_Access;
   end record;
   --  Each of the three answers from the action's shared state.

   type Send_Goal_Server is new Action_Service with null record;

   overriding procedure On_Request
     (This    : in out Send_Goal_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id);

   type Cancel_Server is new Action_Service with null record;

   overriding procedure On_Request
     (This    : in out Cancel_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id);

   type Result_Server is new Action_Service with null record;

   overriding procedure On_Request
     (This    : in out Result_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id);

   ----------------
   -- Goal_Table --
   ----------------

   protected body Goal_Table is

      procedure Add (Id : Goal_Id; Goal : Message; Stamp : Long_Long_Integer; Added : out Boolean)
      is
         Dropped : Natural;
      begin
         Expire (Dropped);
         Added := not Goals.Contains (Id);
         if Added then
            Goals.Insert (Id, (Goal => Goal, Stamp => Stamp, others => <>));
         end if;
      end Add;

      function Status_Of (Id : Goal_Id) return Goal_Status is
        (if Goals.Contains (Id)
           and then not Expired (Goals (Id), RCL.Clocks.Now (RCL.Clocks.Steady), Timeout_Ns)
         then Goals (Id).Status else Unknown);

      function Goal_Of (Id : Goal_Id) return Message is
        (if Status_Of (Id) /= Unknown then Goals (Id).Goal else raise ROS_Exception
           with "goal " & Image (Id) & " is unknown (expired?)");

      procedure Transition
        (Id : Goal_Id; To : Goal_Status; Result : Message; Outcome : out Transition_Outcome) is
      begin
         Outcome := (Done => False, Current => Status_Of (Id), Waiting => <>);
         Outcome.Done := Allowed (Outcome.Current, To);
         if Outcome.Done then
            declare
               E : Goal_Entry renames Goals.Reference (Id);
            begin
               E.Status := To;
               if To in Terminal_Status then
                  E.Result := Result;
                  E.Ended_At := RCL.Clocks.Now (RCL.Clocks.Steady);
                  Outcome.Waiting := E.Waiting;
                  E.Waiting.Clear;
               end if;
            end;
         end if;
      end Transition;

      procedure Wait_Result
        (Id : Goal_Id; Request : RCL.Services.Request_Id;
         Status : out Goal_Status; Result : out Message) is
      begin
         Status := Status_Of (Id);
         if Status in Terminal_Status then
            Result := Goals (Id).Result;
         elsif Status /= Unknown then
            Goals.Reference (Id).Waiting.Append (Request);
         end if;
      end Wait_Result;

      procedure Snapshot (List : out Status_Vectors.Vector) is
         Dropped : Natural;
      begin
         Expire (Dropped);
         List.Clear;
         for C in Goals.Iterate loop
            List.Append (Status_Item'(Goal_Maps.Key (C), Goals (C).Stamp, Goals (C).Status));
         end loop;
      end Snapshot;

      procedure Expire (Dropped : out Natural) is
         Now  : constant RCL.Clocks.Nanoseconds := RCL.Clocks.Now (RCL.Clocks.Steady);
         Gone : Id_Vectors.Vector;
      begin
         for C in Goals.Iterate loop
            if Expired (Goals (C), Now, Timeout_Ns) then
               Gone.Append (Goal_Maps.Key (C));
            end if;
         end loop;
         for Id of Gone loop
            Goals.Delete (Id);
         end loop;
         Dropped := Natural (Gone.Length);
      end Expire;

      function Count return Natural is (Natural (Goals.Length));

      function Active return Natural is
         N : Natural := 0;
      begin
         for E of Goals loop
            if E.Status in Accepted | Executing | Canceling then
               N := N + 1;
            end if;
         end loop;
         return N;
      end Active;

      function Cancel_Candidates
        (Id : Goal_Id; Before : Long_Long_Integer) return Status_Vectors.Vector
      is
         Result : Status_Vectors.Vector;
      begin
         for C in Goals.Iterate loop
            declare
               E : Goal_Entry renames Goals (C);
               K : constant Goal_Id := Goal_Maps.Key (C);
            begin
               if Expired (E, RCL.Clocks.Now (RCL.Clocks.Steady), Timeout_Ns) then
                  null;  --  Gone.
               elsif (Id = Null_Goal_Id and Before = 0)
                 or else K = Id
                 or else (Before /= 0 and then E.Stamp <= Before)
               then
                  Result.Append (Status_Item'(K, E.Stamp, E.Status));
               end if;
            end;
         end loop;
         return Result;
      end Cancel_Candidates;

   end Goal_Table;

   --------------------
   -- Publish_Status --
   --------------------

   procedure Publish_Status (State : not null State_Access) is
      List : Status_Vectors.Vector;
      Msg  : constant Message := Init (Status_Support);
      Arr  : constant Array_Ref := Msg ("status_list").As_Array;
   begin
      State.Goals.Snapshot (List);
      Arr.Resize (Natural (List.Length));
      for I in 1 .. Natural (List.Length) loop
         declare
            Item : constant Field_Ref := Arr.Element (I);
         begin
            Put_Id (Item ("goal_info")("goal_id"), List (I).Id);
            Put_Stamp (Item ("goal_info")("stamp"), List (I).Stamp);
            Item ("status").As_Int8.Element.all := ROSIDL.Int8 (Goal_Status'Pos (List (I).Status));
         end;
      end loop;
      State.Status.Publish_Raw (ROSIDL.CDR.Encode (Msg));
   end Publish_Status;

   --------------------
   -- Result expiry --
   --------------------

   type Expiry_Entry is record
      Timer : RCL.Timers.Timer;
      State : State_Access;
   end record;
   package Expiry_Vectors is new Ada.Containers.Vectors (Positive, Expiry_Entry);

   protected Expiry_Timers is
      procedure Add (Timer : RCL.Timers.Timer; State : State_Access);
      function Server_Of (Timer : RCL.Timers.Timer) return State_Access;
      --  Null for a timer not added.
   private
      Entries : Expiry_Vectors.Vector;
   end Expiry_Timers;
   --  The server of each expiry timer (a timer callback gets its timer).

   protected body Expiry_Timers is
      procedure Add (Timer : RCL.Timers.Timer; State : State_Access) is
      begin
         Entries.Append (Expiry_Entry'(Timer, State));
      end Add;

      function Server_Of (Timer : RCL.Timers.Timer) return State_Access is
      begin
         for E of Entries loop
            if RCL.Timers."=" (E.Timer, Timer) then
               return E.State;
            end if;
         end loop;
         return null;
      end Server_Of;
   end Expiry_Timers;

   procedure Expire_Results
     (Node    : in out RCL.Nodes.Node'Class;
      Timer   : in out RCL.Timers.Timer;
      Elapsed : Duration)
   is
      pragma Unreferenced (Node, Elapsed);
      State   : constant State_Access := Expiry_Timers.Server_Of (Timer);
      Dropped : Natural;
   begin
      if State /= null then
         State.Goals.Expire (Dropped);
         if Dropped > 0 then
            Publish_Status (State);
            --  The status array stops naming them (rclcpp names them no
            --  more in its next array only); late readers get this one.
         end if;
      end if;
   end Expire_Results;

   function Expiry_Period (Result_Timeout : Duration) return Duration is
     (Duration'Max (0.05, Duration'Min (10.0, Result_Timeout / 10)));
   --  How often a server drops its expired results: a tenth of the
   --  timeout, within 0.05 .. 10 s.

   ------------------
   -- Send a result --
   ------------------

   procedure Send_Result
     (State   : not null State_Access;
      Request : RCL.Services.Request_Id;
      Status  : Goal_Status;
      Result  : Message)
   is
      Response : constant Message :=
        Init (ROSIDL.Typesupport.Response_Support (Get_Result_Support (State.Support)));
   begin
      Response ("status").As_Int8.Element.all := ROSIDL.Int8 (Goal_Status'Pos (Status));
      if Is_Initialised (Result) then
         Response ("result").Set_Message (Result);
      end if;
      State.Results.Respond (Request, Response);
   end Send_Result;

   ----------------
   -- On_Request --
   ----------------

   overriding procedure On_Request
     (This    : in out Send_Goal_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id)
   is
      State    : constant State_Access := This.State;
      G        : constant Goal_Id := Get_Id (Request ("goal_id"));
      Goal     : constant Message := To_Message (Request ("goal"));
      Answer   : Goal_Response := State.On_Goal (Node, G, Goal);
      Stamp    : constant Long_Long_Integer :=
        Long_Long_Integer (RCL.Clocks.Now (RCL.Clocks.ROS));
      Response : constant Message :=
        Init (ROSIDL.Typesupport.Response_Support (This.Support));
      Added    : Boolean;
   begin
      if Answer /= Reject then
         State.Goals.Add (G, Goal, Stamp, Added);
         if not Added then
            Answer := Reject;  --  A goal with this id exists already.
         end if;
      end if;
      Response ("accepted").As_Bool.Element.all := Answer /= Reject;
      Put_Stamp (Response ("stamp"), Stamp);
      This.Respond (Id, Response);
      if Answer /= Reject then
         if Answer = Accept_And_Execute then
            Execute (Goal_Handle'(State, G));
         else
            Publish_Status (State);
         end if;
         State.On_Accepted (Node, Goal_Handle'(State, G));
      end if;
   end On_Request;

   overriding procedure On_Request
     (This    : in out Cancel_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id)
   is
      State      : constant State_Access := This.State;
      Info       : constant Field_Ref := Request ("goal_info");
      Wanted     : constant Goal_Id := Get_Id (Info ("goal_id"));
      Before     : constant Long_Long_Integer := Get_Stamp (Info ("stamp"));
      Candidates : constant Status_Vectors.Vector := State.Goals.Cancel_Candidates (Wanted, Before);
      Now_Canceling : Status_Vectors.Vector;
      Response   : constant Message :=
        Init (ROSIDL.Typesupport.Response_Support (This.Support));
      Code       : Cancel_Code := Error_None;
   begin
      for C of Candidates loop
         if C.Status in Accepted | Executing
           and then (State.On_Cancel = null
                     or else State.On_Cancel (Node, (State, C.Id)) = Accept_Cancel)
         then
            declare
               Outcome : Transition_Outcome;
            begin
               State.Goals.Transition (C.Id, Canceling, Response, Outcome);
               if Outcome.Done then
                  Now_Canceling.Append (C);
               end if;
            end;
         end if;
      end loop;
      if Now_Canceling.Is_Empty then
         if Wanted /= Null_Goal_Id and then Before = 0 then
            Code := (case State.Goals.Status_Of (Wanted) is
                        when Unknown         => Error_Unknown_Goal_Id,
                        when Terminal_Status => Error_Goal_Terminated,
                        when others          => Error_Rejected);
         else
            Code := Error_Rejected;
         end if;
      end if;
      Response ("return_code").As_Int8.Element.all := ROSIDL.Int8 (Cancel_Code'Pos (Code));
      declare
         List : constant Array_Ref := Response ("goals_canceling").As_Array;
      begin
         List.Resize (Natural (Now_Canceling.Length));
         for I in 1 .. Natural (Now_Canceling.Length) loop
            Put_Id (List.Element (I)("goal_id"), Now_Canceling (I).Id);
            Put_Stamp (List.Element (I)("stamp"), Now_Canceling (I).Stamp);
         end loop;
      end;
      This.Respond (Id, Response);
      if not Now_Canceling.Is_Empty then
         Publish_Status (State);
      end if;
   end On_Request;

   overriding procedure On_Request
     (This    : in out Result_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id)
   is
      pragma Unreferenced (Node);
      G      : constant Goal_Id := Get_Id (Request ("goal_id"));
      Status : Goal_Status;
      Result : Message;
   begin
      This.State.Goals.Wait_Result (G, Id, Status, Result);
      if Status = Unknown or else Status in Terminal_Status then
         Send_Result (This.State, Id, Status, Result);
      end if;
   end On_Request;

   ----------
   -- Init --
   ----------

   procedure Init
     (This        : in out Server;
      Node        : in out RCL.Nodes.Node'Class;
      Support     : Action_Support;
      Name        : String;
      On_Goal     : not null access function
        (Node : in out RCL.Nodes.Node'Class;
         Id   : Goal_Id;
         Goal : ROSIDL.Dynamic.Message) return Goal_Response;
      On_Accepted : not null access procedure
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Goal_Handle);
      On_Cancel   : access function
        (Node : in out RCL.Nodes.Node'Class;
         Goal : Goal_Handle) return Cancel_Response := null;
      Result_Timeout : Duration := Default_Result_Timeout)
   is
      Goal_Stored     : constant Goal_Callback with Import, Address => On_Goal'Address;
      Accepted_Stored : constant Accepted_Callback with Import, Address => On_Accepted'Address;
      Cancel_Stored   : constant Cancel_Callback with Import, Address => On_Cancel'Address;
      --  GNAT: the same subprogram accesses, kept beyond the call (see spec).
      FQ    : constant String := Node.Expand_Service (Name);
      State : constant State_Access :=
        new Server_State (RCL.Clocks.Nanoseconds (Result_Timeout * 1_000_000_000.0));
      Send  : constant RCL.Services.Server_Access := new Send_Goal_Server'
        (RCL.Services.Server with State => State);
      Cancel : constant RCL.Services.Server_Access := new Cancel_Server'
        (RCL.Services.Server with State => State);
   begin
      State.Support := Support;
      State.Name := Ada.Strings.Unbounded.To_Unbounded_String (FQ);
      State.On_Goal := Goal_Stored;
      State.On_Accepted := Accepted_Stored;
      State.On_Cancel := Cancel_Stored;
      State.Results := new Result_Server'(RCL.Services.Server with State => State);
      State.Status := new RCL.Publishers.Publisher'
        (Node.Publish (Status_Support, FQ & Status_Suffix, RCL.QoS.Action_Status));
      State.Feedback := new RCL.Publishers.Publisher'
        (Node.Publish (Feedback_Message_Support (Support), FQ & Feedback_Suffix));
      RCL.Services.Open (Node, Send, Send_Goal_Support (Support), FQ & Send_Goal_Suffix);
      RCL.Services.Open (Node, Cancel, Cancel_Support, FQ & Cancel_Suffix);
      RCL.Services.Open (Node, RCL.Services.Server_Access (State.Results),
                         Get_Result_Support (Support), FQ & Get_Result_Suffix);
      State.Expiry := Node.Timer_Add
        (Expiry_Period (Result_Timeout), Expire_Results'Access, RCL.Timers.Steady_Clock);
      Expiry_Timers.Add (State.Expiry, State);
      This.State := State;
      Publish_Status (State);
   end Init;

   function Name (This : Server) return String is
     (Ada.Strings.Unbounded.To_String (This.State.Name));

   function Active_Goals (This : Server) return Natural is (This.State.Goals.Active);

   function Kept_Goals (This : Server) return Natural is (This.State.Goals.Count);

   -----------
   -- Goals --
   -----------

   function Id (Goal : Goal_Handle) return Goal_Id is (Goal.Id);

   function Goal (Goal : Goal_Handle) return ROSIDL.Dynamic.Message is
     (Goal.State.Goals.Goal_Of (Goal.Id));

   function Status (Goal : Goal_Handle) return Goal_Status is
     (Goal.State.Goals.Status_Of (Goal.Id));

   procedure Move (Goal : Goal_Handle; To : Goal_Status; Result : Message) is
      Outcome : Transition_Outcome;
   begin
      Goal.State.Goals.Transition (Goal.Id, To, Result, Outcome);
      if not Outcome.Done then
         raise ROS_Exception with "action " & Ada.Strings.Unbounded.To_String (Goal.State.Name)
           & ": goal " & Image (Goal.Id) & " cannot go from " & Status_Image (Outcome.Current)
           & " to " & Status_Image (To);
      end if;
      Publish_Status (Goal.State);
      for R of Outcome.Waiting loop
         Send_Result (Goal.State, R, To, Result);
      end loop;
   end Move;

   procedure Execute (Goal : Goal_Handle) is
   begin
      Move (Goal, Executing, Result_Message (Goal.State.Support));
   end Execute;

   procedure Publish_Feedback (Goal : Goal_Handle; Feedback : ROSIDL.Dynamic.Message) is
      Msg : constant Message := Init (Feedback_Message_Support (Goal.State.Support));
   begin
      Put_Id (Msg ("goal_id"), Goal.Id);
      Msg ("feedback").Set_Message (Feedback);
      Goal.State.Feedback.Publish_Raw (ROSIDL.CDR.Encode (Msg));
   end Publish_Feedback;

   procedure Succeed (Goal : Goal_Handle; Result : ROSIDL.Dynamic.Message) is
   begin
      Move (Goal, Succeeded, Result);
   end Succeed;

   procedure Abort_Goal (Goal : Goal_Handle; Result : ROSIDL.Dynamic.Message) is
   begin
      Move (Goal, Aborted, Result);
   end Abort_Goal;

   procedure Canceled (Goal : Goal_Handle; Result : ROSIDL.Dynamic.Message) is
   begin
      Move (Goal, Actions.Canceled, Result);
   end Canceled;

end RCL.Actions.Servers;
