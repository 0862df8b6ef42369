--  The replicated team database: every node holds a replica of every key;
--  writes are local and broadcast on the team network's state topic
--  (TRANSIENT_LOCAL, so late joiners receive the history still held by the
--  writers); reads are local.
--
--  Merge rule: each entry carries a revision and the id of the node that
--  wrote it. A node writing a key uses its replica's revision + 1. A replica
--  keeps the entry with the highest (revision, writer id) (writer ids
--  compared as strings), so replicas converge whatever the delivery order;
--  of two concurrent writes of the same revision the higher node id wins
--  (documented last-writer-wins, the other write is superseded, not merged).
--  Keys meant for one writer (e.g. "pose/r1") are never contended.
--
--  Catching up: whenever a member (re)joins, every node republishes the
--  entries it wrote and those of writers no longer members (Resynchronise),
--  so a late joiner or a node cut off and rejoined gets the current state,
--  and the others get what it wrote while cut off.
--
--  Listeners: the same API as the local database (Sancta.Runtime.Local_Databases):
--  Listen / Unlisten with a Listener, called when a key's value changes
--  (local or remote write).
with Ada.Containers.Indefinite_Holders;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Ordered_Sets;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Values;
with Sancta.Team.Networks;

package Sancta.Team.Replicated_Databases is

   subtype Value is Runtime.Values.Value;
   subtype Listener_Access is Runtime.Local_Databases.Listener_Access;

   type Team_Database (Net : not null Networks.Network_Access) is
     limited new Networks.State_Consumer and Networks.Membership_Listener with private;
   type Team_Database_Access is access all Team_Database'Class;

   procedure Attach (This : in out Team_Database);
   --  Registers with the network (before Net.Start).

   function Contains (This : Team_Database; Key : String) return Boolean;
   function Get (This : Team_Database; Key : String) return Value'Class
     with Pre => This.Contains (Key);
   function Revision (This : Team_Database; Key : String) return Long_Long_Integer;
   --  0 when the key is absent.
   function Writer (This : Team_Database; Key : String) return String;
   --  The node id whose write is held ("" when absent).

   procedure Put (This : in out Team_Database; Key : String; Item : Value'Class);
   procedure Put (This : in out Team_Database; Key : String; Text : String);
   --  A string value.
   function Get_String (This : Team_Database; Key : String) return String;
   --  The value's image, "" when absent.

   procedure Update
     (This    : in out Team_Database;
      Key     : String;
      Process : not null access procedure (Item : in out Value'Class))
     with Pre => This.Contains (Key);

   procedure Listen
     (This : in out Team_Database; Key : String; Observer : not null Listener_Access);
   procedure Unlisten
     (This : in out Team_Database; Key : String; Observer : not null Listener_Access);

   function Keys (This : Team_Database) return Runtime.Local_Databases.Key_Vectors.Vector;
   function Keys_With_Prefix
     (This : Team_Database; Prefix : String) return Runtime.Local_Databases.Key_Vectors.Vector;

   function Digest (This : Team_Database) return String;
   --  A text summarising every (key, revision, writer, value): equal on two
   --  replicas exactly when they hold the same state (tests, benchmark).

   procedure Resynchronise (This : in out Team_Database; Joined : String := "");
   --  Republishes the entries this node wrote, those whose writer is not a
   --  member now, and those of Joined (done on the join of a member Joined:
   --  a restarted node has lost what it wrote before). Enough for every
   --  replica to converge: the newest entry of a key is held by its writer
   --  (nothing replaces it there), which republishes it while alive; once
   --  the writer is gone, every node holding it does. With N members a
   --  join thus costs about one copy of the database, not N (20 robots:
   --  republishing everything on every join cost more than the annealing).

   function Republished_Count (This : Team_Database) return Long_Long_Integer;
   --  Entries republished by Resynchronise so far.

   procedure Catch_Up (This : in out Team_Database);
   --  Call periodically (the team agent's task does): republishes every
   --  entry once more Catch_Up_Delay after a member joined. A member heard
   --  again after a partition heals may not yet be matched on the state
   --  topic when its presence arrives; the second pass makes every replica
   --  converge (every key, every revision) without waiting for another join.

   Catch_Up_Delay : constant Duration := 2.0;

   overriding procedure On_State (This : in out Team_Database; Item : Networks.State_Entry);
   overriding procedure On_Joined (This : in out Team_Database; Member : String);
   overriding procedure On_Lost (This : in out Team_Database; Member : String) is null;

   function Decode (Type_Name, Text : String) return Value'Class;
   --  The value of a runtime type from its image; unknown types become a
   --  string value holding the text.

private

   use Ada.Strings.Unbounded;

   package Holders is new Ada.Containers.Indefinite_Holders
     (Value'Class, Runtime.Values."=");

   type Meta is record
      Revision : Long_Long_Integer := 0;
      Writer   : Unbounded_String;
      Item     : Holders.Holder;
   end record;

   package Meta_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Meta);

   protected type Store is
      procedure Write_Local
        (Key : String; Item : Value'Class; Self : String; Rev : out Long_Long_Integer);
      procedure Offer
        (Key : String; Item : Value'Class; Rev : Long_Long_Integer; Writer : String;
         Accepted : out Boolean);
      function Find (Key : String) return Meta;
      function Snapshot return Meta_Maps.Map;
   private
      Map : Meta_Maps.Map;
   end Store;

   package Name_Sets is new Ada.Containers.Indefinite_Ordered_Sets (String);

   protected type Due_Time is
      procedure Set (At_Time : Ada.Real_Time.Time; Member : String);
      procedure Take (Now : Ada.Real_Time.Time; Due : out Boolean; Joined : out Name_Sets.Set);
      --  Due (and cleared) when a time was set and Now is past it; Joined:
      --  the members given to Set since.
   private
      When_Due : Ada.Real_Time.Time := Ada.Real_Time.Time_Last;
      Members  : Name_Sets.Set;
   end Due_Time;

   protected type Tally is
      procedure Add (N : Natural);
      function Value return Long_Long_Integer;
   private
      Total : Long_Long_Integer := 0;
   end Tally;

   type Team_Database (Net : not null Networks.Network_Access) is
     limited new Networks.State_Consumer and Networks.Membership_Listener with record
      Replica  : Runtime.Local_Databases.Database;
      Data     : Store;
      Catch_Up_At : Due_Time;
      Republished : Tally;
   end record;

end Sancta.Team.Replicated_Databases;
