with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Hash;
with Ada.Text_IO;
with ROSIDL;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Contexts;
with RCL.DDS;
with RCL.QoS;
with Sancta.Team.Interface_Paths;

package body Sancta.Team.Networks is

   use Ada.Real_Time;

   function Messages_Topic (Team : String) return String is ("/sancta/" & Team & "/messages");
   function Presence_Topic (Team : String) return String is ("/sancta/" & Team & "/presence");
   function State_Topic (Team : String) return String is ("/sancta/" & Team & "/state");
   function Tasks_Topic (Team : String) return String is ("/sancta/" & Team & "/tasks");

   function Is_Task_Key (Key : String) return Boolean is
     (Key = "mission"
      or else (Key'Length > 5 and then Key (Key'First .. Key'First + 4) = "task/"));

   Message_QoS  : constant RCL.QoS.Profile := (Depth => 1000, others => <>);
   Presence_QoS : constant RCL.QoS.Profile := (Depth => 50, others => <>);
   State_QoS    : constant RCL.QoS.Profile :=
     (Depth => 1000, Durability => RCL.QoS.Transient_Local, others => <>);

   --  Which network a node's callback belongs to ------------------------------

   package Owner_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, Network_Access, Ada.Strings.Hash, "=");

   protected Registry is
      procedure Add (Node_Name : String; Net : Network_Access);
      function Find (Node_Name : String) return Network_Access;
   private
      Map : Owner_Maps.Map;
   end Registry;

   protected body Registry is
      procedure Add (Node_Name : String; Net : Network_Access) is
      begin
         Map.Include (Node_Name, Net);
      end Add;
      function Find (Node_Name : String) return Network_Access is
        (if Map.Contains (Node_Name) then Map.Element (Node_Name) else null);
   end Registry;

   function Support (Name : String) return ROSIDL.Typesupport.Message_Support is
   begin
      Sancta.Team.Interface_Paths.Ensure;
      return ROSIDL.Typesupport.Get_Message_Support ("sancta_msgs", Name);
   end Support;

   --  Destinations ------------------------------------------------------------

   function To_Node (Id : String) return Destination is ((Text => To_Unbounded_String (Id)));
   function To_Group (Name : String) return Destination is
     ((Text => To_Unbounded_String ("@" & Name)));
   function To_All return Destination is ((Text => Null_Unbounded_String));

   function In_Groups (Groups, Name : String) return Boolean is
      Padded : constant String := "," & Groups & ",";
   begin
      return Name /= "" and then Ada.Strings.Fixed.Index (Padded, "," & Name & ",") > 0;
   end In_Groups;

   function Accepts (This : Network'Class; Dest : String) return Boolean is
     (Dest = ""
      or else Dest = To_String (This.Id)
      or else (Dest (Dest'First) = '@'
               and then In_Groups (To_String (This.Groups), Dest (Dest'First + 1 .. Dest'Last))));

   --  Protected helpers ---------------------------------------------------------

   protected body Roster is
      procedure Heard
        (Member : String; Lease : Duration; Writer : String; New_Member : out Boolean) is
      begin
         New_Member := not Last.Contains (Member);
         Last.Include (Member, Clock);
         Leases.Include (Member, Lease);
         Writers.Include (Member, Writer);
      end Heard;

      procedure Writer_Lost (Writer : String; Member : out Unbounded_String) is
      begin
         Member := Null_Unbounded_String;
         for C in Writers.Iterate loop
            if Name_Maps.Element (C) = Writer then
               Member := To_Unbounded_String (Name_Maps.Key (C));
            end if;
         end loop;
         if Length (Member) > 0 then
            Last.Exclude (To_String (Member));
            Leases.Exclude (To_String (Member));
            Writers.Exclude (To_String (Member));
         end if;
      end Writer_Lost;

      procedure Expire
        (Now : Time; Local_Prefix : String; All_Members : Boolean;
         Lost : in out Name_Vectors.Vector)
      is
         use Time_Maps;
         C : Cursor := Last.First;
         function Is_Local (Member : String) return Boolean is
           (Writers.Contains (Member)
            and then Ada.Strings.Fixed.Head (Writers.Element (Member), Local_Prefix'Length)
                     = Local_Prefix);
         Expired : Name_Vectors.Vector;
      begin
         while Has_Element (C) loop
            if (All_Members or else Is_Local (Key (C)))
              and then Now - Element (C) > To_Time_Span (Leases.Element (Key (C)))
            then
               Expired.Append (To_Unbounded_String (Key (C)));
            end if;
            Next (C);
         end loop;
         Lost.Append (Expired);
         for M of Expired loop
            Last.Delete (To_String (M));
            Leases.Delete (To_String (M));
            Writers.Exclude (To_String (M));
         end loop;
      end Expire;

      procedure Postpone (By : Time_Span) is
      begin
         for T of Last loop
            T := T + By;
         end loop;
      end Postpone;

      procedure Clear is
      begin
         Last.Clear;
         Leases.Clear;
         Writers.Clear;
      end Clear;

      function List return Name_Vectors.Vector is
      begin
         return Result : Name_Vectors.Vector do
            for C in Last.Iterate loop
               Result.Append (To_Unbounded_String (Time_Maps.Key (C)));
            end loop;
         end return;
      end List;

      function Contains (Member : String) return Boolean is (Last.Contains (Member));
   end Roster;

   protected body Flag_Box is
      procedure Set_Isolated (Value : Boolean) is
      begin
         F.Isolated := Value;
      end Set_Isolated;
      procedure Set_Stopping is
      begin
         F.Stopping := True;
      end Set_Stopping;
      function Get return Flags is (F);
   end Flag_Box;

   protected body Counter_Box is
      procedure Add_Sent is
      begin
         S := S + 1;
      end Add_Sent;
      procedure Add_Received is
      begin
         R := R + 1;
      end Add_Received;
      function Next_Sequence return Long_Long_Integer is (Seq + 1);
      procedure Bump_Sequence is
      begin
         Seq := Seq + 1;
      end Bump_Sequence;
      function Sent return Long_Long_Integer is (S);
      function Received return Long_Long_Integer is (R);
   end Counter_Box;

   --  Membership events ---------------------------------------------------------

   procedure Notify_Joined (This : in out Network'Class; Member : String) is
   begin
      for L of This.Listeners loop
         L.On_Joined (Member);
      end loop;
   end Notify_Joined;

   procedure Notify_Lost (This : in out Network'Class; Member : String) is
   begin
      for L of This.Listeners loop
         L.On_Lost (Member);
      end loop;
   end Notify_Lost;

   function Image (Writer : ROSIDL.GID) return String is
     (RCL.DDS.Image (RCL.DDS.GUID (Writer)));

   procedure Heard
     (This : in out Network'Class; Member : String; Lease : Duration; Writer : String) is
      New_Member : Boolean;
   begin
      This.Alive.Heard (Member, Lease, Writer, New_Member);
      if New_Member then
         Notify_Joined (This, Member);
      end if;
   end Heard;

   --  Callbacks (run by the receiving task in Node.Spin) ------------------------

   procedure Log_Failure
     (This : Network'Class; What : String; E : Ada.Exceptions.Exception_Occurrence) is
   begin
      Ada.Text_IO.Put_Line
        (Ada.Text_IO.Standard_Error,
         "team network " & To_String (This.Id) & ": " & What & ": "
         & Ada.Exceptions.Exception_Information (E));
   end Log_Failure;

   protected body Drop_Box is
      procedure Add (Now : Ada.Real_Time.Time; Say : out Boolean; Total : out Long_Long_Integer) is
         use type Ada.Real_Time.Time;
      begin
         Dropped := Dropped + 1;
         Total := Dropped;
         Say := Last_Warned = Ada.Real_Time.Time_First
           or else Now - Last_Warned >= Ada.Real_Time.Seconds (10);
         if Say then
            Last_Warned := Now;
         end if;
      end Add;

      function Count return Long_Long_Integer is (Dropped);
   end Drop_Box;

   function Quoted (Text : String) return String is
      --  Text in quotes, at most 40 characters, others as \xNN.
      Hex    : constant String := "0123456789abcdef";
      Result : Unbounded_String;
   begin
      for I in Text'First .. Integer'Min (Text'Last, Text'First + 39) loop
         if Text (I) in ' ' .. '~' then
            Append (Result, Text (I));
         else
            Append (Result, "\x" & Hex (Character'Pos (Text (I)) / 16 + 1)
                    & Hex (Character'Pos (Text (I)) mod 16 + 1));
         end if;
      end loop;
      return '"' & To_String (Result) & (if Text'Length > 40 then "..." else "") & '"';
   end Quoted;

   procedure Drop (This : in out Network'Class; What, Reason : String) is
      Say   : Boolean;
      Total : Long_Long_Integer;
   begin
      This.Drops.Add (Ada.Real_Time.Clock, Say, Total);
      if Say then
         Ada.Text_IO.Put_Line
           (Ada.Text_IO.Standard_Error,
            "team network " & To_String (This.Id) & ": dropped malformed " & What
            & " (" & Reason & ");" & Total'Image & " dropped so far");
      end if;
   end Drop;
   --  Counts a malformed sample and warns at most once per 10 s.

   function Problem_With_Id (What, Text : String) return String is
     (if Is_Member_Id (Text) then ""
      else What & " " & Quoted (Text) & " is not 1 .." & Max_Id_Length'Image
           & " letters, digits and '_'");

   function Problem_With_Text (What, Text : String) return String is
     (if Is_Text (Text) then ""
      elsif Text'Length > Max_Value_Length then
         What & " of" & Text'Length'Image & " characters exceeds" & Max_Value_Length'Image
      else What & " " & Quoted (Text) & " has a non-printable character");

   generic
      with procedure Handle
        (Net  : Network_Access;
         Msg  : in out ROSIDL.Dynamic.Message;
         Info : ROSIDL.Message_Info);
   procedure Receive
     (Node : in out RCL.Nodes.Node'Class;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info);
   --  A subscription callback of the team topics: Handle for Node's
   --  network unless there is none or it is cut off (Isolated) or stopping.

   procedure Receive
     (Node : in out RCL.Nodes.Node'Class;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
      Net : constant Network_Access := Registry.Find (Node.Name);
   begin
      if Net /= null and then not Net.Status.Get.Isolated and then not Net.Status.Get.Stopping
      then
         Handle (Net, Msg, Info);
      end if;
   end Receive;

   procedure Handle_Envelope
     (Net  : Network_Access;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Info);
   begin
      declare
         Dest    : constant String := Msg ("destination").Get_String;
         Channel : constant String := Msg ("channel").Get_String;
         Sender  : constant String := Msg ("sender").Get_String;
         Payload : constant String := Msg ("payload").Get_String;
         Problem : constant String :=
           (if not (Dest = "" or else Is_Member_Id (Dest)
                    or else (Dest (Dest'First) = '@'
                             and then Is_Member_Id (Dest (Dest'First + 1 .. Dest'Last))))
            then "destination " & Quoted (Dest) & " is not a node, @group or """""
            elsif not Is_Member_Id (Sender) then Problem_With_Id ("sender", Sender)
            elsif not Is_Member_Id (Channel) then Problem_With_Id ("channel", Channel)
            else Problem_With_Text ("payload", Payload));
      begin
         if Problem /= "" then
            Drop (Net.all, "message", Problem);
            return;
         end if;
         if not Accepts (Net.all, Dest) then
            return;
         end if;
         Net.Counts.Add_Received;
         for S of Net.Subs loop
            if To_String (S.Channel) = Channel then
               begin
                  S.Who.On_Message (Sender, Channel, Payload);
               exception
                  when E : Malformed_Data | Constraint_Error =>
                     --  The payload did not parse: data from outside.
                     Drop (Net.all, "message on channel " & Channel & " from " & Sender,
                           Ada.Exceptions.Exception_Message (E));
                  when E : others =>
                     Log_Failure (Net.all, "consumer of channel " & Channel, E);
               end;
            end if;
         end loop;
      end;
   end Handle_Envelope;

   procedure On_Envelope is new Receive (Handle_Envelope);

   procedure Handle_Presence
     (Net  : Network_Access;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
   begin
      declare
         Lease_Ref : constant ROSIDL.Dynamic.Float64_Ref := Msg ("lease").As_Float64;
         --  Tested through the reference: copying a NaN raises under
         --  validity checks.
         Member    : constant String := Msg ("node").Get_String;
      begin
         if not Is_Member_Id (Member) then
            Drop (Net.all, "presence", Problem_With_Id ("member", Member));
         elsif not Lease_Ref.Element.all'Valid
           or else Long_Float (Lease_Ref.Element.all) not in 0.01 .. 3600.0
         then
            Drop (Net.all, "presence of " & Member, "lease not in 0.01 .. 3600 s");
         else
            Heard (Net.all, Member, Duration (Long_Float (Lease_Ref.Element.all)),
                   Image (Info.Publisher_GID));
         end if;
      end;
   end Handle_Presence;

   procedure On_Presence is new Receive (Handle_Presence);

   procedure Handle_State
     (Net  : Network_Access;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Info);
   begin
      if Net.States = null then
         return;
      end if;
      declare
         Key        : constant String := Msg ("key").Get_String;
         Value_Type : constant String := Msg ("value_type").Get_String;
         Value      : constant String := Msg ("value").Get_String;
         Wire_Rev   : constant ROSIDL.UInt64 := Msg ("revision").As_UInt64.Element.all;
         Writer     : constant String := Msg ("writer").Get_String;
         use type ROSIDL.UInt64;
         Problem    : constant String :=
           (if not Is_Key (Key) then
              (if Key'Length not in 1 .. Max_Key_Length
               then "key of" & Key'Length'Image & " characters"
               else "key " & Quoted (Key) & " has a non-printable character")
            elsif not Is_Member_Id (Writer) then Problem_With_Id ("writer", Writer)
            elsif Value_Type'Length not in 1 .. Max_Id_Length
              or else (for some C of Value_Type => C not in 'a' .. 'z' | '.' | '_')
            then "value type " & Quoted (Value_Type) & " is not like ""types.string"""
            elsif Wire_Rev = 0 or else Wire_Rev > ROSIDL.UInt64 (Long_Long_Integer'Last)
            then "revision" & Wire_Rev'Image & " for key " & Quoted (Key)
            else Problem_With_Text ("value", Value));
      begin
         if Problem /= "" then
            Drop (Net.all, "state entry", Problem);
            return;
         end if;
         Net.States.On_State
           ((Key        => To_Unbounded_String (Key),
             Value_Type => To_Unbounded_String (Value_Type),
             Value      => To_Unbounded_String (Value),
             Revision   => Long_Long_Integer (Wire_Rev),
             Writer     => To_Unbounded_String (Writer)));
      exception
         when E : Malformed_Data | Constraint_Error =>
            Drop (Net.all, "state entry " & Quoted (Key), Ada.Exceptions.Exception_Message (E));
      end;
   exception
      when E : others =>
         Log_Failure (Net.all, "state consumer", E);
   end Handle_State;

   procedure On_State is new Receive (Handle_State);

   --  The network ---------------------------------------------------------------

   function Participant_Lease (Lease : Duration) return Duration is
     (Duration'Min (Duration'Max (2.0 * Lease, 2.0), 10.0));

   function Create
     (Id     : String;
      Groups : String := "";
      Lease  : Duration := 2.0;
      Team   : String := "team") return Network_Access
   is
      Net : constant Network_Access := new Network;
   begin
      if (for some C of String'(Id & Team) =>
            not (C in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_'))
      then
         raise Constraint_Error with
           "team node id """ & Id & """ or team """ & Team
           & """: only letters, digits and '_' are allowed";
      end if;
      Net.Id := To_Unbounded_String (Id);
      Net.Groups := To_Unbounded_String (Groups);
      Net.Lease := Lease;
      Net.Team := To_Unbounded_String (Team);
      if not RCL.Contexts.Is_Initialized then
         RCL.Contexts.Init (Participant_Lease => Participant_Lease (Lease));
      end if;
      Net.Node := new RCL.Nodes.Node'(RCL.Nodes.Init ("sancta_" & Team & "_" & Id));
      Registry.Add (Net.Node.Name, Net);
      Net.Messages := new RCL.Publishers.Publisher'
        (Net.Node.Publish (Support ("Envelope"), Messages_Topic (Team), Message_QoS));
      Net.Presence := new RCL.Publishers.Publisher'
        (Net.Node.Publish (Support ("Presence"), Presence_Topic (Team),
                           (Presence_QoS with delta Liveliness => RCL.QoS.Manual_By_Topic,
                                                    Lease      => Lease)));
      Net.State := new RCL.Publishers.Publisher'
        (Net.Node.Publish (Support ("DbEntry"), State_Topic (Team), State_QoS));
      return Net;
   end Create;

   function Id (This : Network) return String is (To_String (This.Id));
   function Lease (This : Network) return Duration is (This.Lease);

   procedure Subscribe
     (This : in out Network; Channel : String; Who : not null Consumer_Access) is
   begin
      This.Subs.Append (Subscriber'(To_Unbounded_String (Channel), Who));
   end Subscribe;

   procedure Add_Membership_Listener
     (This : in out Network; Who : not null Membership_Listener_Access) is
   begin
      This.Listeners.Append (Who);
   end Add_Membership_Listener;

   procedure Set_State_Consumer
     (This : in out Network; Who : not null State_Consumer_Access) is
   begin
      This.States := Who;
   end Set_State_Consumer;

   function Is_Started (This : Network) return Boolean is (This.Started);

   procedure Start (This : in out Network) is
   begin
      if This.Started then
         return;
      end if;
      This.Started := True;
      This.Node.Subscribe (Support ("Envelope"), Messages_Topic (To_String (This.Team)),
                           On_Envelope'Access, Message_QoS);
      This.Node.Subscribe (Support ("Presence"), Presence_Topic (To_String (This.Team)),
                           On_Presence'Access, Presence_QoS);
      --  The reader's lease is infinite: it matches writers of any lease,
      --  and DDS reports each one's liveliness by its own lease.
      This.Node.Track_Liveliness (Presence_Topic (To_String (This.Team)));
      This.Node.Subscribe (Support ("DbEntry"), State_Topic (To_String (This.Team)),
                           On_State'Access, State_QoS);
      This.Node.Subscribe (Support ("DbEntry"), Tasks_Topic (To_String (This.Team)),
                           On_State'Access, State_QoS);
      This.Worker := new Receiver (This'Unchecked_Access);
      This.Worker.Go;
      This.Heart := new Beater (This'Unchecked_Access);
      This.Heart.Go;
   end Start;

   procedure Stop (This : in out Network) is
   begin
      This.Status.Set_Stopping;
   end Stop;

   procedure While_Sending
     (This : in out Network'Class; Action : not null access procedure) is
      --  Action under This.Send_Lock (one publication at a time); the lock
      --  is released when Action raises.
   begin
      This.Send_Lock.Seize;
      begin
         Action.all;
      exception
         when others =>
            This.Send_Lock.Release;
            raise;
      end;
      This.Send_Lock.Release;
   end While_Sending;

   procedure Send
     (This    : in out Network;
      To      : Destination;
      Channel : String;
      Payload : String)
   is
      Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support ("Envelope"));

      procedure Number_And_Publish is
      begin
         This.Counts.Bump_Sequence;
         Msg ("sequence").As_UInt64.Element.all :=
           ROSIDL.UInt64 (This.Counts.Next_Sequence - 1);
         This.Messages.Publish (Msg);
         This.Counts.Add_Sent;
      end Number_And_Publish;
   begin
      if This.Status.Get.Isolated or else This.Status.Get.Stopping then
         return;
      end if;
      Msg ("sender").Set_String (To_String (This.Id));
      Msg ("destination").Set_String (To_String (To.Text));
      Msg ("channel").Set_String (Channel);
      Msg ("payload").Set_String (Payload);
      While_Sending (This, Number_And_Publish'Access);
   end Send;

   procedure Publish_State (This : in out Network; Item : State_Entry) is
      Key : constant String := To_String (Item.Key);
      Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support ("DbEntry"));

      procedure Publish_Entry is
      begin
         if not Is_Task_Key (Key) then
            This.State.Publish (Msg);
         else
            if This.Tasks = null and then not This.Tasks_Refused then
               begin
                  This.Tasks := new RCL.Publishers.Publisher'
                    (This.Node.Publish (Support ("DbEntry"), Tasks_Topic (To_String (This.Team)),
                                        State_QoS));
               exception
                  when E : RCL.ROS_Exception =>
                     --  Secured, without the permission to write tasks.
                     This.Tasks_Refused := True;
                     Ada.Text_IO.Put_Line
                       (Ada.Text_IO.Standard_Error,
                        "team network " & To_String (This.Id) & ": task entries are not"
                        & " re-published: " & Ada.Exceptions.Exception_Message (E));
               end;
            end if;
            if This.Tasks /= null then
               This.Tasks.Publish (Msg);
            end if;
         end if;
      end Publish_Entry;
   begin
      if This.Status.Get.Isolated or else This.Status.Get.Stopping then
         return;
      end if;
      Msg ("key").Set_String (Key);
      Msg ("value_type").Set_String (To_String (Item.Value_Type));
      Msg ("value").Set_String (To_String (Item.Value));
      Msg ("revision").As_UInt64.Element.all := ROSIDL.UInt64 (Item.Revision);
      Msg ("writer").Set_String (To_String (Item.Writer));
      While_Sending (This, Publish_Entry'Access);
   end Publish_State;

   procedure Beat (This : in out Network'Class) is
      Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support ("Presence"));

      procedure Publish_Presence is
      begin
         This.Presence.Publish (Msg);
      end Publish_Presence;
   begin
      Heard (This, To_String (This.Id), This.Lease, "");
      if This.Status.Get.Isolated then
         return;
      end if;
      Msg ("node").Set_String (To_String (This.Id));
      Msg ("groups").Set_String (To_String (This.Groups));
      Msg ("lease").As_Float64.Element.all := ROSIDL.Float64 (This.Lease);
      While_Sending (This, Publish_Presence'Access);
   end Beat;

   procedure Isolate (This : in out Network; Cut : Boolean) is
   begin
      This.Status.Set_Isolated (Cut);
   end Isolate;

   function Is_Isolated (This : Network) return Boolean is (This.Status.Get.Isolated);

   function Members (This : Network) return Name_Vectors.Vector is (This.Alive.List);
   function Is_Member (This : Network; Id : String) return Boolean is
     (This.Alive.Contains (Id));

   function Sent_Count (This : Network) return Long_Long_Integer is (This.Counts.Sent);
   function Dropped_Count (This : Network) return Long_Long_Integer is (This.Drops.Count);

   function Received_Count (This : Network) return Long_Long_Integer is
     (This.Counts.Received);

   task body Beater is
      Period    : constant Time_Span := To_Time_Span (Owner.Lease / 4);
      Late_Wake : constant Time_Span := Milliseconds (50);
      Next      : Time;
   begin
      accept Go;
      Next := Clock;
      loop
         exit when Owner.Status.Get.Stopping or else RCL.Contexts.Is_Shutdown;
         begin
            Beat (Owner.all);
         exception
            when E : others =>
               Log_Failure (Owner.all, "presence", E);
         end;
         Next := Next + Period;
         if Next < Clock then
            Next := Clock;  --  this task did not run for a while: no burst
         end if;
         delay until Next;
         --  Woken late: this process (the members living in it, whose
         --  silence is judged here) was kept from running that long.
         if Clock - Next > Late_Wake then
            Owner.Alive.Postpone (Clock - Next);
         end if;
      end loop;
   end Beater;

   task body Receiver is
      Period : constant Time_Span := To_Time_Span (Owner.Lease / 4);
      Lost   : Name_Vectors.Vector;
      Local_Prefix : constant String :=
        Ada.Strings.Fixed.Head (RCL.DDS.Image (Owner.Presence.GID), 12 * 3 - 1);
      --  "xx.xx....": the 12-byte GUID prefix of this process's participant.
      Last_Check : Time;
      Check_Gap  : constant Time_Span := Period;
      --  A turn of the loop takes about 20 ms; a longer time between two
      --  checks of the silences means this task did not run (a loaded
      --  machine, a long callback, a stopped process).
   begin
      accept Go;
      Last_Check := Clock;
      loop
         exit when Owner.Status.Get.Stopping;
         --  After Ctrl-C / SIGTERM the context is shut down: nothing can be
         --  sent any more (publishing would raise at every beat).
         exit when RCL.Contexts.Is_Shutdown;
         begin
            --  The samples waiting first: after this task was kept from
            --  running (a loaded machine), the presence samples that came
            --  meanwhile renew their members before any of them is expired.
            Owner.Node.Spin (During => 0.02);
            Lost.Clear;
            loop
               declare
                  Writer       : ROSIDL.GID;
                  Alive, Found : Boolean;
                  Member       : Unbounded_String;
               begin
                  Owner.Node.Take_Liveliness_Change
                    (Presence_Topic (To_String (Owner.Team)), Writer, Alive, Found);
                  exit when not Found;
                  if not Alive and then not Owner.Status.Get.Isolated then
                     Owner.Alive.Writer_Lost (Image (Writer), Member);
                     if Length (Member) > 0 then
                        Lost.Append (Member);
                     end if;
                  end if;
               end;
            end loop;
            --  Cyclone applies no lease to the writers of its own
            --  participant: members in this process are expired on silence,
            --  as is everyone while this node is isolated.
            --
            --  Silence is judged on the time this process ran: the
            --  members of this process (expired on silence) stalled with
            --  it, and expiring them now would make a team flap on a
            --  loaded machine (20 robots in one process: rounds re-opened
            --  every second). Remote members' losses come from DDS.
            if Clock - Last_Check > Check_Gap then
               Owner.Alive.Postpone (Clock - Last_Check);
            end if;
            Owner.Alive.Expire (Clock, Local_Prefix, Owner.Status.Get.Isolated, Lost);
            Last_Check := Clock;
            for M of Lost loop
               if To_String (M) /= To_String (Owner.Id) then
                  Notify_Lost (Owner.all, To_String (M));
               end if;
            end loop;
         exception
            when E : others =>
               Log_Failure (Owner.all, "receiving task", E);
               delay 0.1;
         end;
      end loop;
      Owner.Alive.Clear;
   end Receiver;

end Sancta.Team.Networks;
