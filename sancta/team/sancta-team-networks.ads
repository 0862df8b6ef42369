--  The team network: the Network component of SANCTA on DDS topics.
--
--  Every node of the team owns one Network (one ROS 2 node named
--  "sancta_<team>_<id>" on the context's participant). The topics below are
--  under /sancta/<team>/ (team "team" by default; several teams, e.g. test
--  runs, can share a DDS domain). Messages are sancta_msgs/
--  Envelope samples on the topic /sancta/team/messages: a sender, a
--  destination (one node, a group or everyone) and a named channel; a
--  receiver hands a sample to the consumers subscribed to its channel when
--  the destination is itself, one of its groups, or everyone.
--
--  Presence rests on DDS liveliness: each node writes its presence
--  (sancta_msgs/Presence on /sancta/team/presence: id, groups, lease) with
--  the QoS liveliness MANUAL_BY_TOPIC and a lease of Lease, every Lease / 4;
--  each write asserts its liveliness. A node hearing a presence sample
--  from an unknown member reports a join; when DDS reports the member's
--  presence writer not alive (its process died, its host is cut off, or it
--  stopped writing for longer than its lease) it reports the loss; a member
--  heard again rejoins. Membership listeners hear joins and losses.
--  (Cyclone applies no lease to the writers of its own participant: members
--  living in the same process are expired when silent for their lease.)
--
--  A member heard again after a cut rejoins only once DDS has found its
--  participant again: a participant that a peer dropped (no word from it
--  for the participant lease) is found again at its next announcement,
--  every 8 s with DDS's default 10 s lease; a team that finished its
--  mission meanwhile may have left. So the first network of a process
--  creates the process's DDS participant (when nothing did before) with a
--  lease of 2 x Lease (2 .. 10 s), which announces it every 1.6 x Lease:
--  with Lease 1 s, a healed link is found again within 1.6 s.
--
--  The replicated database's entries travel on /sancta/team/state
--  (sancta_msgs/DbEntry, reliable, TRANSIENT_LOCAL, depth 1000) through the
--  same Network (Publish_State / Set_State_Consumer); the mission's entries
--  ("mission", "task/<id>") on /sancta/team/tasks (same type and QoS), so
--  that DDS-Security permissions can say who may write tasks
--  (Sancta.Team.Security). A node refused the tasks topic (its permissions
--  deny it) does not re-publish task entries.
--
--  Isolate simulates a cut-off host: while isolated a node neither sends nor
--  receives anything, so the others' DDS liveliness declares it lost after
--  its lease; and it expires the others itself once it has not heard them
--  for their lease (what their lapsed liveliness would tell a really cut-off
--  host). Tests of catching up use it; the namespace test cuts a real link.
--
--     Net : Network_Access := Create ("r1", Groups => "robots", Lease => 2.0);
--     Net.Subscribe ("auction", My_Consumer'Access);
--     Net.Start;
--     Net.Send (To_Group ("robots"), "auction", "offer t3");
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Vectors;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with RCL.Nodes;
with RCL.Publishers;
private with Sancta.Mutexes;

package Sancta.Team.Networks is

   use Ada.Strings.Unbounded;

   --  Destinations -----------------------------------------------------------

   type Destination is private;
   function To_Node (Id : String) return Destination;
   function To_Group (Name : String) return Destination;
   function To_All return Destination;

   --  Consumers --------------------------------------------------------------

   type Consumer is limited interface;
   type Consumer_Access is access all Consumer'Class;
   procedure On_Message
     (This    : in out Consumer;
      Sender  : String;
      Channel : String;
      Payload : String) is abstract;
   --  Called in the network's receiving task, one message at a time.

   type Membership_Listener is limited interface;
   type Membership_Listener_Access is access all Membership_Listener'Class;
   procedure On_Joined (This : in out Membership_Listener; Member : String) is abstract;
   procedure On_Lost (This : in out Membership_Listener; Member : String) is abstract;

   type State_Entry is record
      Key        : Unbounded_String;
      Value_Type : Unbounded_String;
      Value      : Unbounded_String;
      Revision   : Long_Long_Integer := 0;
      Writer     : Unbounded_String;
   end record;
   --  One entry of the replicated state, as a sancta_msgs/DbEntry carries
   --  it: Key's Value (the image of a value of type Value_Type, e.g.
   --  "types.string"), at Revision, written by member Writer.

   type State_Consumer is limited interface;
   type State_Consumer_Access is access all State_Consumer'Class;
   procedure On_State (This : in out State_Consumer; Item : State_Entry) is abstract;

   --  Data from outside ----------------------------------------------------------
   --
   --  Every sample heard is validated before any consumer sees it: member
   --  ids and channels are 1 .. 64 letters, digits and '_'; keys 1 .. 256
   --  printable ASCII characters; values and payloads at most 64 KiB of
   --  text (printable ASCII, tab, CR, LF); revisions positive; leases finite.
   --  A sample failing a rule, or refused by its consumer (Malformed_Data, or
   --  Constraint_Error while a consumer parses it), is dropped and counted;
   --  the network says so on standard error at most once per 10 s, with the
   --  reason and no traceback:
   --     team network r1: dropped malformed state entry (key "task/\x01" has a
   --     non-printable character); 12 dropped so far

   Malformed_Data : exception;
   --  Raised by a consumer that refuses a sample (e.g. a value that does
   --  not parse as its declared type); the message says why.

   Max_Id_Length    : constant := 64;
   Max_Key_Length   : constant := 256;
   Max_Value_Length : constant := 65_536;

   function Is_Member_Id (Text : String) return Boolean is
     (Text'Length in 1 .. Max_Id_Length
      and then (for all C of Text => C in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_'));
   --  Is_Member_Id ("r1") and not Is_Member_Id ("r 1").

   function Is_Key (Text : String) return Boolean is
     (Text'Length in 1 .. Max_Key_Length
      and then (for all C of Text => C in ' ' .. '~'));
   --  Is_Key ("done/t3") and not Is_Key ("done/" & ASCII.NUL).

   function Is_Text (Text : String) return Boolean is
     (Text'Length <= Max_Value_Length
      and then (for all C of Text => C in ' ' .. '~' | ASCII.HT | ASCII.LF | ASCII.CR));
   --  A value or payload.

   function Tasks_Topic (Team : String) return String;
   --  "/sancta/<team>/tasks": the topic of the mission's entries.

   function Is_Task_Key (Key : String) return Boolean;
   --  "mission" and "task/<id>": the entries published on Tasks_Topic.

   --  The network -------------------------------------------------------------

   type Network is tagged limited private;
   type Network_Access is access all Network'Class;

   function Create
     (Id     : String;
      Groups : String := "";
      Lease  : Duration := 2.0;
      Team   : String := "team") return Network_Access
     with Pre => Id'Length > 0 and then Team'Length > 0 and then Lease >= 0.1;
   --  A network for node Id (letters, digits, '_'), member of the comma-
   --  separated Groups. Not started: subscribe first, then Start.

   function Id (This : Network) return String;
   function Lease (This : Network) return Duration;

   procedure Subscribe
     (This : in out Network; Channel : String; Who : not null Consumer_Access);
   procedure Add_Membership_Listener
     (This : in out Network; Who : not null Membership_Listener_Access);
   procedure Set_State_Consumer
     (This : in out Network; Who : not null State_Consumer_Access);
   --  Before Start.

   procedure Start (This : in out Network);
   --  Starts the receiving task (and the heartbeats); again: no effect.
   function Is_Started (This : Network) return Boolean;

   procedure Stop (This : in out Network);
   --  Stops sending and receiving (the node is seen lost by the others).

   procedure Send
     (This    : in out Network;
      To      : Destination;
      Channel : String;
      Payload : String);
   --  Also delivered locally when the destination includes the sender.

   procedure Publish_State (This : in out Network; Item : State_Entry);

   procedure Isolate (This : in out Network; Cut : Boolean);
   function Is_Isolated (This : Network) return Boolean;

   package Name_Vectors is new Ada.Containers.Vectors (Positive, Unbounded_String);
   function Members (This : Network) return Name_Vectors.Vector;
   --  The members currently alive (itself included), sorted by id.
   function Is_Member (This : Network; Id : String) return Boolean;

   function Sent_Count (This : Network) return Long_Long_Integer;
   function Received_Count (This : Network) return Long_Long_Integer;
   function Dropped_Count (This : Network) return Long_Long_Integer;
   --  Samples dropped as malformed (see "Data from outside").

private

   type Destination is record
      Text : Unbounded_String;
   end record;

   package Time_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (String, Ada.Real_Time.Time, "<", Ada.Real_Time."=");
   package Lease_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Duration);

   package Name_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, String);

   protected type Roster is
      procedure Heard
        (Member : String; Lease : Duration; Writer : String; New_Member : out Boolean);
      --  Writer: the image of the member's presence writer GID ("" for
      --  the node itself).
      procedure Writer_Lost (Writer : String; Member : out Unbounded_String);
      --  Removes the member whose current presence writer is Writer; Member
      --  is "" when there is none (an older writer of a restarted member).
      procedure Expire
        (Now : Ada.Real_Time.Time; Local_Prefix : String; All_Members : Boolean;
         Lost : in out Name_Vectors.Vector);
      --  Appends to Lost, and removes, the members silent for more than
      --  their lease among those whose presence writer's GUID starts with
      --  Local_Prefix (or all members when All_Members).
      procedure Postpone (By : Ada.Real_Time.Time_Span);
      --  Every member last heard By later: the receiving task was kept
      --  from running for By, and a silence it explains is not a loss.
      procedure Clear;
      function List return Name_Vectors.Vector;
      function Contains (Member : String) return Boolean;
   private
      Last    : Time_Maps.Map;
      Leases  : Lease_Maps.Map;
      Writers : Name_Maps.Map;
      --  Member -> image of its presence writer's GID.
   end Roster;

   subtype Mutex is Sancta.Mutexes.Mutex;

   type Subscriber is record
      Channel : Unbounded_String;
      Who     : Consumer_Access;
   end record;
   package Subscriber_Vectors is new Ada.Containers.Vectors (Positive, Subscriber);
   package Listener_Vectors is new Ada.Containers.Vectors
     (Positive, Membership_Listener_Access);

   task type Receiver (Owner : not null access Network) is
      entry Go;
   end Receiver;
   type Receiver_Access is access Receiver;

   task type Beater (Owner : not null access Network) is
      entry Go;
   end Beater;
   --  Writes the node's presence every Lease / 4, whatever the receiving
   --  task is doing (a long callback must not make the node look lost).
   type Beater_Access is access Beater;

   type Node_Access is access RCL.Nodes.Node;
   type Publisher_Access is access RCL.Publishers.Publisher;

   type Flags is record
      Isolated : Boolean := False;
      Stopping : Boolean := False;
   end record;
   protected type Flag_Box is
      procedure Set_Isolated (Value : Boolean);
      procedure Set_Stopping;
      function Get return Flags;
   private
      F : Flags;
   end Flag_Box;

   protected type Counter_Box is
      procedure Add_Sent;
      procedure Add_Received;
      function Next_Sequence return Long_Long_Integer;
      procedure Bump_Sequence;
      function Sent return Long_Long_Integer;
      function Received return Long_Long_Integer;
   private
      S, R, Seq : Long_Long_Integer := 0;
   end Counter_Box;

   protected type Drop_Box is
      procedure Add (Now : Ada.Real_Time.Time; Say : out Boolean; Total : out Long_Long_Integer);
      --  Counts a drop; Say when no warning was given in the last 10 s.
      function Count return Long_Long_Integer;
   private
      Dropped     : Long_Long_Integer := 0;
      Last_Warned : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
   end Drop_Box;

   type Network is tagged limited record
      Id         : Unbounded_String;
      Groups     : Unbounded_String;
      Lease      : Duration := 2.0;
      Node       : Node_Access;
      Messages   : Publisher_Access;
      Presence   : Publisher_Access;
      State      : Publisher_Access;
      Tasks      : Publisher_Access;
      --  Created on the first task entry published, unless refused.
      Tasks_Refused : Boolean := False;
      Send_Lock  : Mutex;
      Subs       : Subscriber_Vectors.Vector;
      Listeners  : Listener_Vectors.Vector;
      States     : State_Consumer_Access;
      Alive      : Roster;
      Status     : Flag_Box;
      Counts     : Counter_Box;
      Drops      : Drop_Box;
      Worker     : Receiver_Access;
      Heart      : Beater_Access;
      Started    : Boolean := False;
      Team       : Unbounded_String;
   end record;

end Sancta.Team.Networks;
