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
--  Presence uses a heartbeat topic (/sancta/team/presence, sancta_msgs/
--  Presence) rather than DDS liveliness, because the RCL layer does not
--  expose liveliness-changed status: each node publishes its heartbeat every
--  Lease / 4 and a member silent for more than its announced Lease is lost.
--  Membership listeners hear joins (also re-joins) and losses.
--
--  The replicated database's entries travel on /sancta/team/state
--  (sancta_msgs/DbEntry, reliable, TRANSIENT_LOCAL, depth 1000) through the
--  same Network (Publish_State / Set_State_Consumer).
--
--  Isolate simulates a cut-off host: while isolated a node neither sends nor
--  receives anything (tests of catching up; the namespace test cuts a real
--  link).
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

   type State_Consumer is limited interface;
   type State_Consumer_Access is access all State_Consumer'Class;
   procedure On_State
     (This       : in out State_Consumer;
      Key        : String;
      Value_Type : String;
      Value      : String;
      Revision   : Long_Long_Integer;
      Writer     : String) is abstract;

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
   --  Starts the receiving task (and the heartbeats).

   procedure Stop (This : in out Network);
   --  Stops sending and receiving (the node is seen lost by the others).

   procedure Send
     (This    : in out Network;
      To      : Destination;
      Channel : String;
      Payload : String);
   --  Also delivered locally when the destination includes the sender.

   procedure Publish_State
     (This       : in out Network;
      Key        : String;
      Value_Type : String;
      Value      : String;
      Revision   : Long_Long_Integer;
      Writer     : String);

   procedure Isolate (This : in out Network; Cut : Boolean);
   function Is_Isolated (This : Network) return Boolean;

   package Name_Vectors is new Ada.Containers.Vectors (Positive, Unbounded_String);
   function Members (This : Network) return Name_Vectors.Vector;
   --  The members currently alive (itself included), sorted by id.
   function Is_Member (This : Network; Id : String) return Boolean;

   function Sent_Count (This : Network) return Long_Long_Integer;
   function Received_Count (This : Network) return Long_Long_Integer;

private

   type Destination is record
      Text : Unbounded_String;
   end record;

   package Time_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (String, Ada.Real_Time.Time, "<", Ada.Real_Time."=");
   package Lease_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Duration);

   protected type Roster is
      procedure Heard (Member : String; Lease : Duration; New_Member : out Boolean);
      procedure Expire (Now : Ada.Real_Time.Time; Lost : out Name_Vectors.Vector);
      procedure Clear;
      function List return Name_Vectors.Vector;
      function Contains (Member : String) return Boolean;
   private
      Last   : Time_Maps.Map;
      Leases : Lease_Maps.Map;
   end Roster;

   protected type Mutex is
      entry Seize;
      procedure Release;
   private
      Held : Boolean := False;
   end Mutex;

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

   type Network is tagged limited record
      Id         : Unbounded_String;
      Groups     : Unbounded_String;
      Lease      : Duration := 2.0;
      Node       : Node_Access;
      Messages   : Publisher_Access;
      Presence   : Publisher_Access;
      State      : Publisher_Access;
      Send_Lock  : Mutex;
      Subs       : Subscriber_Vectors.Vector;
      Listeners  : Listener_Vectors.Vector;
      States     : State_Consumer_Access;
      Alive      : Roster;
      Status     : Flag_Box;
      Counts     : Counter_Box;
      Worker     : Receiver_Access;
      Started    : Boolean := False;
      Next_Beat  : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
      Team       : Unbounded_String;
   end record;

end Sancta.Team.Networks;
