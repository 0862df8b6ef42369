with Ada.Unchecked_Deallocation;

with ROSIDL.CDR;
with RCL.Arguments;
with RCL.Clients;
with RCL.Clocks;
with RCL.Contexts;
with RCL.Executors.Sequential;
with RCL.Graph;
with RCL.Graph_Announcements;
with RCL.Logging;
with RCL.Names;
with RCL.Parameters;
with RCL.Publisher_Writers;
with RCL.Rosout;
with RCL.Services;
with RCL.Timer_States;

package body RCL.Nodes is

   use type RCL.Node_Entities.Node_Serial;
   use type RCL.Timers.Timer_Clock;

   type Spinner is record
      E : RCL.Executors.Sequential.Executor (Max_Nodes => 1);
   end record;

   procedure Free is new Ada.Unchecked_Deallocation (Spinner, Spinner_Access);

   ----------
   -- Init --
   ----------

   protected Serials is
      procedure Next (Serial : out RCL.Node_Entities.Node_Serial);
   private
      Last : RCL.Node_Entities.Node_Serial := 0;
   end Serials;

   protected body Serials is
      procedure Next (Serial : out RCL.Node_Entities.Node_Serial) is
      begin
         Last := Last + 1;
         Serial := Last;
      end Next;
   end Serials;

   function Init
     (Name      : String;
      Namespace : String := "/";
      Options   : Node_Options := Default_Options) return Node
   is
      Sim_Time : constant Boolean :=
        RCL.Clocks.Sim_Time_Requested and then not RCL.Clocks.Sim_Time_Enabled;
   begin
      RCL.Names.Validate_Node_Name (Name);
      RCL.Arguments.Load;
      declare
         Given_NS : constant String := RCL.Names.Normalize_Namespace (Namespace);
         New_Name : constant String :=
           (if Options.Use_Global_Arguments then RCL.Arguments.Node_Name (Name) else Name);
         NS       : constant String :=
           (if Options.Use_Global_Arguments then RCL.Arguments.Namespace (Name, Given_NS)
            else Given_NS);
      begin
         RCL.Contexts.Init;
         return N : Node do
            Serials.Next (N.Serial);
            N.Name := To_Unbounded_String (New_Name);
            N.Original := To_Unbounded_String (Name);
            N.Namespace := To_Unbounded_String (NS);
            N.Remapped := Options.Use_Global_Arguments;
            N.Pool := Options.Pool;
            RCL.Graph_Announcements.Add_Node (NS, New_Name, N.Graph_Id);
            if RCL.Arguments.Rosout_Enabled then
               RCL.Rosout.Enable;
            end if;
            if Sim_Time then
               RCL.Clocks.Enable_Sim_Time (N);
            end if;
            if RCL.Logging.Default_Logger = "" then
               RCL.Logging.Set_Default_Logger (N.Logger_Name);
            end if;
            if Options.Start_Parameter_Services then
               RCL.Parameters.Serve (N);
            end if;
         end return;
      end;
   end Init;

   function Original_Name (This : Node) return String is (To_String (This.Original));

   function Name (This : Node) return String is (To_String (This.Name));
   function Namespace (This : Node) return String is (To_String (This.Namespace));
   function Fully_Qualified_Name (This : Node) return String is
     (RCL.Names.Fully_Qualified_Node_Name (Name (This), Namespace (This)));

   function Logger_Name (This : Node) return String is
      FQN : String := Fully_Qualified_Name (This);
   begin
      for C of FQN loop
         if C = '/' then
            C := '.';
         end if;
      end loop;
      return FQN (FQN'First + 1 .. FQN'Last);
   end Logger_Name;

   function Remapped
     (This : Node; Name : String; Kind : RCL.Arguments.Name_Kind) return String
   is
      FQ : constant String :=
        RCL.Names.Expand_Topic_Name (Name, Nodes.Name (This), Namespace (This));
   begin
      return (if This.Remapped
              then RCL.Arguments.Remap (FQ, Kind, Nodes.Name (This), Namespace (This))
              else FQ);
   end Remapped;

   function Expand (This : Node; Topic : String) return String is
     (Remapped (This, Topic, RCL.Arguments.Topic));

   function Expand_Service (This : Node; Service : String) return String is
     (Remapped (This, Service, RCL.Arguments.Service));

   -----------------
   -- Publish_Raw --
   -----------------

   function Publish_Raw
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      QoS       : RCL.QoS.Profile := RCL.QoS.Default) return RCL.Publishers.Publisher
   is
      FQ : constant String := This.Expand (Topic);
   begin
      return P : RCL.Publishers.Publisher do
         RCL.Publisher_Writers.Create (P, FQ, Type_Name, QoS, This.Graph_Id);
      end return;
   end Publish_Raw;

   -------------
   -- Publish --
   -------------

   function Publish
     (This    : in out Node;
      Support : ROSIDL.Typesupport.Message_Support;
      Topic   : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Default) return RCL.Publishers.Publisher is
   begin
      return P : RCL.Publishers.Publisher :=
        This.Publish_Raw (ROSIDL.Typesupport.DDS_Type_Name (Support), Topic, QoS)
      do
         RCL.Publisher_Writers.Set_Support (P, Support);
      end return;
   end Publish;

   -----------------------
   -- Subscribe_Handler --
   -----------------------

   procedure Free is new Ada.Unchecked_Deallocation (Handler'Class, Handler_Access);

   procedure Subscribe_Handler
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile := RCL.QoS.Default)
   is
   begin
      RCL.Node_Entities.Subscribe
        (This, Type_Name, Topic, RCL.Node_Entities.Handler_Access (Handle), QoS);
   end Subscribe_Handler;

   -----------------------------
   -- Services and clients --
   -----------------------------

   procedure Serve
     (This     : in out Node;
      Support  : ROSIDL.Typesupport.Service_Support;
      Name     : String;
      Callback : not null access procedure
        (Node     : in out Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message);
      QoS      : RCL.QoS.Profile := RCL.QoS.Services_Default) is
   begin
      RCL.Services.Serve (This, Support, Name, Callback, QoS);
   end Serve;

   function Client_Call
     (This    : Node;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      Request : ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever) return ROSIDL.Dynamic.Message is
   begin
      return RCL.Clients.Call (This, Support, Name, Request, Timeout);
   end Client_Call;

   type Raw_Handler is new Handler with record
      Callback : Raw_Callback;
   end record;

   overriding procedure Deliver
     (This : in out Raw_Handler;
      Node : in out Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is
   begin
      This.Callback (Node, Data, Info);
   end Deliver;

   type Typed_Callback is access procedure
     (Node : in out Nodes.Node'Class;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info);

   --  One decoded message kept per subscription and reused (no allocation
   --  per sample); a concurrent delivery that finds it taken decodes into a
   --  fresh one.
   protected body Cache_Lock is
      procedure Try (Got : out Boolean) is
      begin
         Got := not Taken;
         Taken := True;
      end Try;
      procedure Release is
      begin
         Taken := False;
      end Release;
   end Cache_Lock;

   procedure Deliver_Decoded
     (Lock     : in out Cache_Lock;
      Use_Kept : not null access procedure;
      Use_Own  : not null access procedure)
   is
      Got : Boolean;
   begin
      Lock.Try (Got);
      if not Got then
         Use_Own.all;
         return;
      end if;
      Use_Kept.all;
      Lock.Release;
   exception
      when others =>
         if Got then
            Lock.Release;
         end if;
         raise;
   end Deliver_Decoded;

   type Typed_Handler is new Handler with record
      Support  : ROSIDL.Typesupport.Message_Support;
      Callback : Typed_Callback;
      Cached   : ROSIDL.Dynamic.Message;
      Lock     : Cache_Lock;
   end record;

   overriding procedure Deliver
     (This : in out Typed_Handler;
      Node : in out Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      procedure Use_Kept is
      begin
         if not ROSIDL.Dynamic.Is_Initialised (This.Cached) then
            This.Cached := ROSIDL.Dynamic.Init (This.Support);
         end if;
         ROSIDL.CDR.Decode (Data, This.Cached);
         This.Callback (Node, This.Cached, Info);
      end Use_Kept;

      procedure Use_Own is
         Msg : ROSIDL.Dynamic.Message := ROSIDL.CDR.Decode (This.Support, Data);
      begin
         This.Callback (Node, Msg, Info);
      end Use_Own;
   begin
      Deliver_Decoded (This.Lock, Use_Kept'Access, Use_Own'Access);
   end Deliver;

   procedure Subscribe
     (This     : in out Node;
      Support  : ROSIDL.Typesupport.Message_Support;
      Topic    : String;
      Callback : not null access procedure
        (Node : in out Nodes.Node'Class;
         Msg  : in out ROSIDL.Dynamic.Message;
         Info : ROSIDL.Message_Info);
      QoS      : RCL.QoS.Profile := RCL.QoS.Default)
   is
      Stored : constant Typed_Callback with Import, Address => Callback'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
      H : Handler_Access := new Typed_Handler;
   begin
      Typed_Handler (H.all).Support := Support;
      Typed_Handler (H.all).Callback := Stored;
      begin
         This.Subscribe_Handler (ROSIDL.Typesupport.DDS_Type_Name (Support), Topic, H, QoS);
      exception
         when others =>
            Free (H);
            raise;
      end;
   end Subscribe;

   procedure Subscribe_Raw
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      Callback  : not null access procedure
        (Node : in out Nodes.Node'Class;
         Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info);
      QoS       : RCL.QoS.Profile := RCL.QoS.Default)
   is
      Stored : constant Raw_Callback with Import, Address => Callback'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
      H : Handler_Access := new Raw_Handler'(Callback => Stored);
   begin
      This.Subscribe_Handler (Type_Name, Topic, H, QoS);
   exception
      when others =>
         Free (H);
         raise;
   end Subscribe_Raw;

   type Closure_Callback is access procedure
     (State : System.Address;
      Node  : in out Nodes.Node'Class;
      Data  : RCL.DDS.Byte_Array;
      Info  : ROSIDL.Message_Info);

   type Release_Callback is access procedure (State : System.Address);

   type Release_Guard is new Ada.Finalization.Limited_Controlled with record
      Release : Release_Callback;
      State   : System.Address := System.Null_Address;
   end record;

   overriding procedure Finalize (This : in out Release_Guard);

   overriding procedure Finalize (This : in out Release_Guard) is
      Release : constant Release_Callback := This.Release;
   begin
      This.Release := null;
      if Release /= null then
         Release (This.State);
      end if;
   exception
      when others =>
         null;
   end Finalize;

   type Closure_Handler is new Handler with record
      Deliver : Closure_Callback;
      State   : System.Address;
      Guard   : Release_Guard;
      --  Releases State with the handler.
   end record;

   overriding procedure Deliver
     (This : in out Closure_Handler;
      Node : in out Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info);

   overriding procedure Deliver
     (This : in out Closure_Handler;
      Node : in out Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is
   begin
      This.Deliver (This.State, Node, Data, Info);
   end Deliver;

   function Pool (This : Node) return RCL.Allocators.Pool_Access is (This.Pool);

   procedure Subscribe_Closure
     (This      : in out Node;
      Type_Name : String;
      Topic     : String;
      Deliver   : not null access procedure
        (State : System.Address;
         Node  : in out Nodes.Node'Class;
         Data  : RCL.DDS.Byte_Array;
         Info  : ROSIDL.Message_Info);
      State     : System.Address;
      Release   : not null access procedure (State : System.Address);
      QoS       : RCL.QoS.Profile := RCL.QoS.Default)
   is
      Stored : constant Closure_Callback with Import, Address => Deliver'Address;
      Stored_Release : constant Release_Callback with Import, Address => Release'Address;
      --  GNAT: the same subprogram accesses, kept beyond the call (see spec).
      H : Handler_Access := new Closure_Handler;
   begin
      Closure_Handler (H.all).Deliver := Stored;
      Closure_Handler (H.all).State := State;
      Closure_Handler (H.all).Guard.Release := Stored_Release;
      Closure_Handler (H.all).Guard.State := State;
      This.Subscribe_Handler (Type_Name, Topic, H, QoS);
   exception
      when others =>
         Free (H);
         raise;
   end Subscribe_Closure;

   ---------------------
   -- Callback groups --
   ---------------------

   function Default_Callback_Group (This : Node) return Callback_Group is
      pragma Unreferenced (This);
   begin
      return (others => <>);
   end Default_Callback_Group;

   function Create_Callback_Group
     (This : in out Node;
      Kind : Callback_Group_Kind) return Callback_Group is
   begin
      This.Groups := This.Groups + 1;
      return (Owner => This.Serial, Id => This.Groups, Exclusive => Kind = Mutually_Exclusive);
   end Create_Callback_Group;

   procedure Set_Callback_Group (This : in out Node; Group : Callback_Group) is
   begin
      This.Current := RCL.Node_Entities.Group_Data (Group);
   end Set_Callback_Group;

   function Current_Callback_Group (This : Node) return Callback_Group is
     (Callback_Group (This.Current));

   function Belongs_To (Group : Callback_Group; This : Node) return Boolean is
     (Group.Owner = 0 or else Group.Owner = This.Serial);

   function Kind (Group : Callback_Group) return Callback_Group_Kind is
     (if Group.Exclusive then Mutually_Exclusive else Reentrant);
   function Id (Group : Callback_Group) return Natural is (Group.Id);

   ------------
   -- Timers --
   ------------

   function Timer_Add
     (This     : in out Node;
      Period   : Duration;
      Callback : not null access procedure
        (Node    : in out RCL.Nodes.Node'Class;
         Timer   : in out RCL.Timers.Timer;
         Elapsed : Duration);
      Clock    : RCL.Timers.Timer_Clock := RCL.Timers.Node_Clock) return RCL.Timers.Timer
   is
      Stored : constant RCL.Timers.Callback with Import, Address => Callback'Address;
      S : constant RCL.Timer_States.State_Access :=
        new RCL.Timer_States.State
          (Period_Ns     => RCL.Clocks.Nanoseconds (Period * 1_000_000_000.0),
           Always_Steady => Clock = RCL.Timers.Steady_Clock);
   begin
      S.Start;
      This.Entities.Add (RCL.Node_Entities.Timer_Entry'(S, Stored, This.Current));
      return RCL.Timer_States.To_Timer (S);
   end Timer_Add;

   procedure Timer_Add
     (This     : in out Node;
      Period   : Duration;
      Callback : not null access procedure
        (Node    : in out RCL.Nodes.Node'Class;
         Timer   : in out RCL.Timers.Timer;
         Elapsed : Duration);
      Clock    : RCL.Timers.Timer_Clock := RCL.Timers.Node_Clock)
   is
      Ignored : constant RCL.Timers.Timer := This.Timer_Add (Period, Callback, Clock);
   begin
      null;
   end Timer_Add;

   ----------
   -- Spin --
   ----------

   procedure Spin
     (This   : in out Node;
      During : Duration := Forever;
      Once   : Boolean := False)
   is
   begin
      if This.Spin_Exec = null then
         This.Spin_Exec := new Spinner;
         This.Spin_Exec.E.Add (This);
      end if;
      This.Spin_Exec.E.Spin (During => During, Once => Once);
   end Spin;

   -----------------------------------
   -- Taking samples; liveliness --
   -----------------------------------

   --  This node's first subscription on Topic (expanded).
   function Subscription_On
     (This : Node; Topic : String) return RCL.Node_Entities.Subscription_Access
   is
      use type RCL.Node_Entities.Subscription_Access;
      FQ : constant String := This.Expand (Topic);
      S  : constant RCL.Node_Entities.Subscription_Access :=
        RCL.Node_Entities.Find_Subscription (This, FQ);
   begin
      if S = null then
         raise ROS_Exception with "node " & To_String (This.Name) & " has no subscription on " & FQ;
      end if;
      return S;
   end Subscription_On;

   function Take_Raw
     (This  : in out Node;
      Topic : String;
      Info  : out ROSIDL.Message_Info) return RCL.DDS.Byte_Array
   is
      S      : constant RCL.Node_Entities.Subscription_Access := Subscription_On (This, Topic);
      Sample : RCL.DDS.Sample_Info;
   begin
      return Data : constant RCL.DDS.Byte_Array := RCL.DDS.Take (S.Reader, Sample) do
         Info := RCL.Node_Entities.To_Info (Sample);
      end return;
   end Take_Raw;

   procedure Track_Liveliness (This : in out Node; Topic : String) is
      S : constant RCL.Node_Entities.Subscription_Access := Subscription_On (This, Topic);
   begin
      if not RCL.DDS.Is_Tracking_Liveliness (S.Reader) then
         RCL.DDS.Track_Liveliness (S.Reader);
      end if;
   end Track_Liveliness;

   procedure Take_Liveliness_Change
     (This      : in out Node;
      Topic     : String;
      Publisher : out ROSIDL.GID;
      Alive     : out Boolean;
      Found     : out Boolean)
   is
      S      : constant RCL.Node_Entities.Subscription_Access := Subscription_On (This, Topic);
      Writer : RCL.DDS.GUID;
   begin
      if not RCL.DDS.Is_Tracking_Liveliness (S.Reader) then
         raise ROS_Exception with "liveliness of " & S.Topic.all & " not tracked";
      end if;
      RCL.DDS.Take_Liveliness_Change (S.Reader, Writer, Alive, Found);
      Publisher := ROSIDL.GID (Writer);
   end Take_Liveliness_Change;

   --------------
   -- Finalize --
   --------------

   overriding procedure Finalize (This : in out Node) is
      Subs   : RCL.Node_Entities.Subscription_Array;
      Tims   : RCL.Node_Entities.Timer_Array;
      N_Subs : Natural;
      N_Tims : Natural;
      procedure Free_Name is new Ada.Unchecked_Deallocation
        (String, RCL.Node_Entities.Name_Access);
      procedure Free_Handler is new Ada.Unchecked_Deallocation
        (Handler'Class, RCL.Node_Entities.Handler_Access);
      procedure Free is new Ada.Unchecked_Deallocation
        (RCL.Node_Entities.Subscription, RCL.Node_Entities.Subscription_Access);
   begin
      Free (This.Spin_Exec);
      --  Before the subscriptions: it detaches their readers.
      RCL.Graph_Announcements.Remove_Node (This.Graph_Id);
      This.Graph_Id := RCL.Graph.No_Node;
      This.Entities.Take_All (Subs, N_Subs, Tims, N_Tims);
      for I in 1 .. N_Subs loop
         Free_Handler (Subs (I).Handle);
         Free_Name (Subs (I).Topic);
         Free (Subs (I));
      end loop;
      --  Timer states are left allocated: Timer handles held by users may
      --  still designate them (a few bytes per timer, once per node).
      pragma Unreferenced (Tims);
   exception
      when others =>
         null;
   end Finalize;

end RCL.Nodes;
