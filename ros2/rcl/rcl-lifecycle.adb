with Ada.Exceptions;
with ROSIDL.CDR;
with RCL.Clocks;
with RCL.Logging;
with RCL.Services;

package body RCL.Lifecycle is

   use ROSIDL.Dynamic;
   use ROSIDL.Typesupport;

   function Id (S : State_Id) return Natural is
     (case S is
         when Unknown .. Finalized => State_Id'Pos (S),
         when others               => State_Id'Pos (S) - State_Id'Pos (Configuring) + 10);

   function Label (S : State_Id) return String is
     (case S is
         when Unknown          => "unknown",
         when Unconfigured     => "unconfigured",
         when Inactive         => "inactive",
         when Active           => "active",
         when Finalized        => "finalized",
         when Configuring      => "configuring",
         when Cleaning_Up      => "cleaningup",
         when Shutting_Down    => "shuttingdown",
         when Activating       => "activating",
         when Deactivating     => "deactivating",
         when Error_Processing => "errorprocessing");

   function Label (T : Transition_Id) return String is
     (case T is
         when Configure  => "configure",
         when Cleanup    => "cleanup",
         when Activate   => "activate",
         when Deactivate => "deactivate",
         when Shutdown   => "shutdown");

   --  The state machine (rcl_lifecycle's default one) -----------------------

   function Allowed (From : State_Id; T : Transition_Id) return Boolean is
     (case From is
         when Unconfigured => T in Configure | Shutdown,
         when Inactive     => T in Cleanup | Activate | Shutdown,
         when Active       => T in Deactivate | Shutdown,
         when others       => False);

   function Via (T : Transition_Id) return State_Id is
     (case T is
         when Configure  => Configuring,
         when Cleanup    => Cleaning_Up,
         when Activate   => Activating,
         when Deactivate => Deactivating,
         when Shutdown   => Shutting_Down);

   function Transition_Number (T : Transition_Id; From : State_Id) return Natural is
     (case T is
         when Configure  => 1,
         when Cleanup    => 2,
         when Activate   => 3,
         when Deactivate => 4,
         when Shutdown   => (case From is
                                when Inactive => 6,
                                when Active   => 7,
                                when others   => 5));

   function Goal (Via : State_Id; R : Callback_Return) return State_Id is
     (case Via is
         when Configuring      => (case R is when Success => Inactive, when Failure => Unconfigured,
                                      when Error => Error_Processing),
         when Cleaning_Up      => (case R is when Success => Unconfigured, when Failure => Inactive,
                                      when Error => Error_Processing),
         when Activating       => (case R is when Success => Active, when Failure => Inactive,
                                      when Error => Error_Processing),
         when Deactivating     => (case R is when Success => Inactive, when Failure => Active,
                                      when Error => Error_Processing),
         when Shutting_Down    => (case R is when Error => Error_Processing,
                                      when others => Finalized),
         when Error_Processing => (case R is when Success => Unconfigured,
                                      when others => Finalized),
         when others           => Via);

   function Result_Number (Via : State_Id; R : Callback_Return) return Natural is
     ((case Via is
          when Configuring  => 10, when Cleaning_Up => 20, when Activating => 30,
          when Deactivating => 40, when Shutting_Down => 50, when others => 60)
      + Callback_Return'Pos (R));

   function Result_Label (R : Callback_Return) return String is
     (case R is
         when Success => "transition_success",
         when Failure => "transition_failure",
         when Error   => "transition_error");

   ------------------
   -- The machine  --
   ------------------

   protected type Guard is
      procedure Begin_Transition (Ok : out Boolean; Current : out State_Id);
      procedure Set (S : State_Id);
      procedure End_Transition;
      function Get return State_Id;
   private
      State : State_Id := Unconfigured;
      Busy  : Boolean := False;
   end Guard;

   protected body Guard is
      procedure Begin_Transition (Ok : out Boolean; Current : out State_Id) is
      begin
         Ok := not Busy;
         Busy := True;
         Current := State;
      end Begin_Transition;
      procedure Set (S : State_Id) is
      begin
         State := S;
      end Set;
      procedure End_Transition is
      begin
         Busy := False;
      end End_Transition;
      function Get return State_Id is (State);
   end Guard;

   type Node_Access is access all RCL.Nodes.Node'Class;

   type Machine is limited record
      Node   : Node_Access;
      On     : Callbacks;
      State  : Guard;
      Events : Publisher_Access;
   end record;

   procedure Put_State (Ref : Field_Ref; S : State_Id) is
   begin
      Ref ("id").As_UInt8.Element.all := ROSIDL.UInt8 (Id (S));
      Ref ("label").Set_String (Label (S));
   end Put_State;

   procedure Put_Transition (Ref : Field_Ref; Number : Natural; Name : String) is
   begin
      Ref ("id").As_UInt8.Element.all := ROSIDL.UInt8 (Number);
      Ref ("label").Set_String (Name);
   end Put_Transition;

   procedure Publish_Event
     (M : Machine; Number : Natural; Name : String; From, To : State_Id)
   is
      Event : constant Message :=
        Init (Get_Message_Support ("lifecycle_msgs", "TransitionEvent"));
   begin
      Event ("timestamp").As_UInt64.Element.all :=
        ROSIDL.UInt64 (RCL.Clocks.Now (RCL.Clocks.System));
      Put_Transition (Event ("transition"), Number, Name);
      Put_State (Event ("start_state"), From);
      Put_State (Event ("goal_state"), To);
      M.Events.Publish_Raw (ROSIDL.CDR.Encode (Event));
   end Publish_Event;

   function Call
     (M : Machine; Callback : Transition_Callback; Previous : State_Id) return Callback_Return is
   begin
      return (if Callback = null then Success else Callback (M.Node.all, Previous));
   exception
      when E : others =>
         RCL.Logging.Error ("lifecycle callback raised " & Ada.Exceptions.Exception_Name (E)
                            & ": " & Ada.Exceptions.Exception_Message (E),
                            Logger => M.Node.Logger_Name);
         return Error;
   end Call;

   function Callback_Of (M : Machine; Via : State_Id) return Transition_Callback is
     (case Via is
         when Configuring   => M.On.On_Configure,
         when Cleaning_Up   => M.On.On_Cleanup,
         when Activating    => M.On.On_Activate,
         when Deactivating  => M.On.On_Deactivate,
         when Shutting_Down => M.On.On_Shutdown,
         when others        => M.On.On_Error);

   --  Runs T from the current state; True when it reached its goal.
   function Run (M : in out Machine; T : Transition_Id) return Boolean is
      Ok    : Boolean;
      Start : State_Id;
      Mid   : State_Id;
      R     : Callback_Return;
      Next  : State_Id;
   begin
      M.State.Begin_Transition (Ok, Start);
      if not Ok then
         return False;  --  Another transition is running.
      end if;
      if not Allowed (Start, T) then
         M.State.End_Transition;
         return False;
      end if;
      Mid := Via (T);
      M.State.Set (Mid);
      Publish_Event (M, Transition_Number (T, Start), Label (T), Start, Mid);
      R := Call (M, Callback_Of (M, Mid), Start);
      Next := Goal (Mid, R);
      M.State.Set (Next);
      Publish_Event (M, Result_Number (Mid, R), Result_Label (R), Mid, Next);
      if Next = Error_Processing then
         declare
            E : constant Callback_Return := Call (M, M.On.On_Error, Start);
            After : constant State_Id := Goal (Error_Processing, E);
         begin
            M.State.Set (After);
            Publish_Event (M, Result_Number (Error_Processing, E), Result_Label (E),
                           Error_Processing, After);
         end;
      end if;
      M.State.End_Transition;
      return R = Success;
   exception
      when others =>
         M.State.End_Transition;
         raise;
   end Run;

   --  The services -------------------------------------------------------------

   type Service_Kind is (Change_State, Get_State, Get_States, Get_Transitions, Get_Graph);

   type Lifecycle_Server is new RCL.Services.Server with record
      Kind : Service_Kind;
      M    : Machine_Access;
   end record;

   overriding procedure On_Request
     (This    : in out Lifecycle_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id);

   --  Transitions from State, with their transition state as the goal (as
   --  rcl lists them); every one when State is Unknown (the graph).
   procedure Put_Transitions (List : Array_Ref; State : State_Id) is
      N : Natural := 0;
   begin
      for From in Primary_State loop
         for T in Transition_Id loop
            if (State = Unknown or else From = State) and then Allowed (From, T) then
               N := N + 1;
               List.Resize (N);
               Put_Transition (List.Element (N)("transition"), Transition_Number (T, From),
                               Label (T));
               Put_State (List.Element (N)("start_state"), From);
               Put_State (List.Element (N)("goal_state"), Via (T));
            end if;
         end loop;
      end loop;
      if State = Unknown then
         for Mid in Configuring .. Error_Processing loop
            for R in Callback_Return loop
               N := N + 1;
               List.Resize (N);
               Put_Transition (List.Element (N)("transition"), Result_Number (Mid, R),
                               Result_Label (R));
               Put_State (List.Element (N)("start_state"), Mid);
               Put_State (List.Element (N)("goal_state"), Goal (Mid, R));
            end loop;
         end loop;
      end if;
   end Put_Transitions;

   function Requested (Number : Natural; Name : String; From : State_Id; T : out Transition_Id)
     return Boolean is
   begin
      for X in Transition_Id loop
         if (Number /= 0 and then Number = Transition_Number (X, From))
           or else (Number = 0 and then Name = Label (X))
         then
            T := X;
            return True;
         end if;
      end loop;
      T := Configure;
      return False;
   end Requested;

   overriding procedure On_Request
     (This    : in out Lifecycle_Server;
      Node    : in out RCL.Nodes.Node'Class;
      Request : Message;
      Id      : RCL.Services.Request_Id)
   is
      pragma Unreferenced (Node);
      Response : constant Message := Init (Response_Support (This.Support));
   begin
      case This.Kind is
         when Change_State =>
            declare
               T      : Transition_Id;
               Number : constant Natural :=
                 Natural (Request ("transition")("id").As_UInt8.Element.all);
               Name   : constant String := Request ("transition")("label").Get_String;
               Known  : constant Boolean :=
                 Requested (Number, Name, This.M.State.Get, T);
            begin
               Response ("success").As_Bool.Element.all := Known and then Run (This.M.all, T);
               if not Known then
                  RCL.Logging.Warn ("lifecycle: transition" & Number'Image & " '" & Name
                                    & "' is not available in state "
                                    & Label (This.M.State.Get),
                                    Logger => This.M.Node.Logger_Name);
               end if;
            end;
         when Get_State =>
            Put_State (Response ("current_state"), This.M.State.Get);
         when Get_States =>
            declare
               List : constant Array_Ref := Response ("available_states").As_Array;
            begin
               List.Resize (State_Id'Pos (State_Id'Last));
               for S in Unconfigured .. State_Id'Last loop
                  Put_State (List.Element (State_Id'Pos (S)), S);
               end loop;
            end;
         when Get_Transitions =>
            Put_Transitions (Response ("available_transitions").As_Array, This.M.State.Get);
         when Get_Graph =>
            Put_Transitions (Response ("available_transitions").As_Array, Unknown);
      end case;
      This.Respond (Id, Response);
   end On_Request;

   ----------
   -- Init --
   ----------

   procedure Init
     (This          : in out Managed_Node;
      Node          : in out RCL.Nodes.Node'Class;
      On_Configure  : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Activate   : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Deactivate : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Cleanup    : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Shutdown   : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null;
      On_Error      : access function
        (Node : in out RCL.Nodes.Node'Class; Previous : State_Id) return Callback_Return := null)
   is
      --  GNAT: the same subprogram accesses, kept beyond the call (see spec).
      Configure_CB  : constant Transition_Callback with Import, Address => On_Configure'Address;
      Activate_CB   : constant Transition_Callback with Import, Address => On_Activate'Address;
      Deactivate_CB : constant Transition_Callback with Import, Address => On_Deactivate'Address;
      Cleanup_CB    : constant Transition_Callback with Import, Address => On_Cleanup'Address;
      Shutdown_CB   : constant Transition_Callback with Import, Address => On_Shutdown'Address;
      Error_CB      : constant Transition_Callback with Import, Address => On_Error'Address;
      On : constant Callbacks :=
        (On_Configure  => Configure_CB,
         On_Cleanup    => Cleanup_CB,
         On_Activate   => Activate_CB,
         On_Deactivate => Deactivate_CB,
         On_Shutdown   => Shutdown_CB,
         On_Error      => Error_CB);
      M : constant Machine_Access := new Machine;
      procedure Serve (Kind : Service_Kind; Type_Name, Name : String) is
      begin
         RCL.Services.Open
           (Node, new Lifecycle_Server'(RCL.Services.Server with Kind => Kind, M => M),
            Get_Service_Support ("lifecycle_msgs", Type_Name), Name);
      end Serve;
   begin
      M.Node := Node'Unchecked_Access;
      M.On := On;
      M.Events := new RCL.Publishers.Publisher'
        (Node.Publish (Get_Message_Support ("lifecycle_msgs", "TransitionEvent"),
                       "~/transition_event"));
      Serve (Change_State, "ChangeState", "~/change_state");
      Serve (Get_State, "GetState", "~/get_state");
      Serve (Get_States, "GetAvailableStates", "~/get_available_states");
      Serve (Get_Transitions, "GetAvailableTransitions", "~/get_available_transitions");
      Serve (Get_Graph, "GetAvailableTransitions", "~/get_transition_graph");
      This.M := M;
   end Init;

   function Current_State (This : Managed_Node) return State_Id is (This.M.State.Get);

   function Trigger (This : in out Managed_Node; Transition : Transition_Id) return Boolean is
     (Run (This.M.all, Transition));

   -------------------------
   -- Lifecycle_Publisher --
   -------------------------

   function Publish
     (This    : in out Managed_Node'Class;
      Support : ROSIDL.Typesupport.Message_Support;
      Topic   : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Default) return Lifecycle_Publisher is
   begin
      return P : Lifecycle_Publisher do
         P.M := This.M;
         P.Pub := new RCL.Publishers.Publisher'(This.M.Node.Publish (Support, Topic, QoS));
      end return;
   end Publish;

   function Is_Activated (This : Lifecycle_Publisher) return Boolean is
     (This.M.State.Get = Active);

   procedure Publish (This : in out Lifecycle_Publisher; Msg : ROSIDL.Dynamic.Message) is
   begin
      if This.Is_Activated then
         This.Warned := False;
         This.Pub.Publish (Msg);
      elsif not This.Warned then
         This.Warned := True;
         RCL.Logging.Warn ("Trying to publish message on the topic '" & This.Pub.Topic
                           & "', but the publisher is not activated",
                           Logger => This.M.Node.Logger_Name);
      end if;
   end Publish;

end RCL.Lifecycle;
