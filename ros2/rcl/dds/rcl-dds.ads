--  The thick Ada layer over Cyclone DDS used by RCL (clients of RCL never
--  see it): participants, raw-CDR writers and readers, waitsets. Every
--  Cyclone error becomes RCL.ROS_Exception with a message saying what was
--  attempted and Cyclone's own text (dds_strretcode).
--  Example:
--     P : Participant;
--     W : Writer;
--     Create (P, Domain => 0, Localhost_Only => True);
--     Create (W, P, "rt/chatter", "std_msgs::msg::dds_::String_", QoS.Default);
--     Write (W, Bytes);  --  CDR including the 4-byte encapsulation header
with Ada.Finalization;
with Ada.Streams;
with Interfaces;
with RCL.QoS;
with RCL.Security;
with ROSIDL;

private with System;

package RCL.DDS is

   use type Ada.Streams.Stream_Element_Offset;

   subtype Byte_Array is Ada.Streams.Stream_Element_Array;

   subtype GUID is ROSIDL.GID;
   --  A DDS GUID: 12-byte participant prefix and 4-byte entity id. The
   --  library has one GUID type, ROSIDL.GID (a message's Publisher_GID).

   Null_GUID : constant GUID := [others => 0];

   function Image (This : GUID) return String;
   --  Hex bytes separated by dots, "01.0f.3a...".

   type Domain_Id is range 0 .. 232;
   --  ROS_DOMAIN_ID range.

   procedure Check (Code : Integer; What : String);
   --  Raises ROS_Exception "<What>: <dds_strretcode (Code)>" when Code < 0.

   function Error_Text (Code : Integer) return String;
   --  dds_strretcode (Code).

   type Time_Ns is new Interfaces.Integer_64;
   --  Nanoseconds since the Unix epoch (DDS time).

   Invalid_Time : constant Time_Ns := Time_Ns'Last;
   --  DDS_TIME_INVALID.

   function Now return Time_Ns;
   --  The system clock as DDS time.

   -----------------
   -- Participant --
   -----------------

   type Participant is new Ada.Finalization.Limited_Controlled with private;

   Configured_Lease : constant Duration := 0.0;
   --  A participant lease that says "the configuration's" (Create).

   procedure Create
     (This           : in out Participant;
      Domain         : Domain_Id;
      Localhost_Only : Boolean;
      User_Data      : String := "enclave=/;";
      Security       : RCL.Security.Credentials := RCL.Security.Unsecured;
      Lease          : Duration := Configured_Lease)
     with Pre => not Is_Open (This) and then (Lease = Configured_Lease or else Lease >= 0.1);
   --  CYCLONEDDS_URI, when set, is Cyclone's whole configuration (Cyclone
   --  reads it itself). Otherwise, with Localhost_Only, the domain gets a
   --  loopback-only configuration (unicast discovery on 127.0.0.1, no
   --  multicast). Security.Secured: DDS-Security with its Files (Cyclone's
   --  dds.sec.* properties, the plugins of the libddsc loaded); files that
   --  do not verify (a bad signature, an expired certificate) make Create
   --  raise ROS_Exception, Cyclone's own reason on standard error.
   --  Lease: the participant's lease (a Cyclone extension of DDS, the
   --  participant's liveliness QoS): the other participants drop this one
   --  when they have heard nothing from it for Lease; it announces itself
   --  (SPDP) every 0.8 x Lease below 10 s, so a peer that dropped it (a link
   --  cut, then restored) finds it again within that time. Configured_Lease:
   --  the configuration's (Discovery/LeaseDuration, 10 s by default: then
   --  every 8 s).

   function Is_Open (This : Participant) return Boolean;

   function Instance_GUID (This : Participant) return GUID
     with Pre => Is_Open (This);

   overriding procedure Finalize (This : in out Participant);

   ------------
   -- Writer --
   ------------

   type Writer is new Ada.Finalization.Limited_Controlled with private;

   procedure Create
     (This       : in out Writer;
      Owner      : Participant'Class;
      Topic_Name : String;
      Type_Name  : String;
      Profile    : RCL.QoS.Profile;
      User_Data  : String := "")
     with Pre => Is_Open (Owner) and then not Is_Open (This);
   --  Topic_Name is the DDS name ("rt/chatter").

   function Is_Open (This : Writer) return Boolean;

   procedure Write
     (This      : Writer;
      Data      : Byte_Array;
      Timestamp : Time_Ns := Invalid_Time)
     with Pre => Is_Open (This) and then Data'Length >= 4;
   --  Data is CDR with its encapsulation header. A reliable writer blocks
   --  while the history of a reader is full. Invalid_Time stamps now.

   procedure Write_Filled
     (This      : Writer;
      Size      : Ada.Streams.Stream_Element_Count;
      Fill      : not null access procedure
        (Buffer : out Byte_Array; Last : out Ada.Streams.Stream_Element_Offset);
      Timestamp : Time_Ns := Invalid_Time)
     with Pre => Is_Open (This) and then Size >= 4;
   --  Fill writes the CDR straight into the sample's storage (Buffer is
   --  1 .. Size; Buffer (1 .. Last) is published): no intermediate copy, no
   --  stack buffer. An exception in Fill publishes nothing and propagates.

   function Endpoint_GUID (This : Writer) return GUID
     with Pre => Is_Open (This);

   function Matched_Readers (This : Writer) return Natural
     with Pre => Is_Open (This);

   function Topic_Name (This : Writer) return String;
   function Type_Name (This : Writer) return String;

   overriding procedure Finalize (This : in out Writer);

   ------------
   -- Reader --
   ------------

   type Reader is new Ada.Finalization.Limited_Controlled with private;

   procedure Create
     (This        : in out Reader;
      Owner       : Participant'Class;
      Topic_Name  : String;
      Type_Name   : String;
      Profile     : RCL.QoS.Profile;
      User_Data   : String := "";
      Ignore_Self : Boolean := False)
     with Pre => Is_Open (Owner) and then not Is_Open (This);
   --  Ignore_Self: do not receive what this participant writes.

   function Is_Open (This : Reader) return Boolean;

   type Sample_Info is record
      Source_Timestamp : Time_Ns;
      Publisher        : GUID;
      --  The writer's endpoint GUID (Null_GUID if it vanished meanwhile).
   end record;

   procedure Take
     (This    : in out Reader;
      Process : not null access procedure (Data : Byte_Array; Info : Sample_Info);
      Taken   : out Boolean)
     with Pre => Is_Open (This);
   --  Takes one sample, if any, and calls Process with its bytes (valid
   --  only during the call: no copy is made).

   Take_Batch : constant := 64;

   procedure Take_Many
     (This    : in out Reader;
      Process : not null access procedure (Data : Byte_Array; Info : Sample_Info);
      Count   : out Natural)
     with Pre => Is_Open (This), Post => Count <= Take_Batch;
   --  As Take, for up to Take_Batch samples taken in one DDS take (one lock
   --  of the reader's history instead of one per sample): Process is called
   --  for each, in order; Count says how many (0: none was available).
   --  An exception from Process propagates after every taken sample was
   --  released (the samples after the failing one are lost). Call it until
   --  Count = 0 to empty the reader.

   function Take (This : in out Reader; Info : out Sample_Info) return Byte_Array
     with Pre => Is_Open (This);
   --  A copy of the next sample; an empty array when there is none.

   function Endpoint_GUID (This : Reader) return GUID
     with Pre => Is_Open (This);

   function Matched_Writers (This : Reader) return Natural
     with Pre => Is_Open (This);

   function Topic_Name (This : Reader) return String;
   function Type_Name (This : Reader) return String;

   procedure Track_Liveliness (This : in out Reader)
     with Pre => Is_Open (This) and then not Is_Tracking_Liveliness (This);
   --  From now on, queues every liveliness change of the writers This
   --  matches (their QoS lease expiring, a writer asserting itself again)
   --  for Take_Liveliness_Change, after an "alive" change for each writer
   --  matched already. Cyclone reports the changes in its own thread; the
   --  queue holds 1024 of them.

   function Is_Tracking_Liveliness (This : Reader) return Boolean;

   procedure Take_Liveliness_Change
     (This   : in out Reader;
      Writer : out GUID;
      Alive  : out Boolean;
      Found  : out Boolean)
     with Pre => Is_Tracking_Liveliness (This);
   --  The oldest queued change, if any (Found): the writer's endpoint GUID
   --  (Null_GUID when Cyclone no longer knew it) and whether it became
   --  alive (True) or lost its liveliness or vanished (False).

   function Dropped_Liveliness_Changes (This : Reader) return Natural
     with Pre => Is_Tracking_Liveliness (This);
   --  Changes lost because the queue was full.

   overriding procedure Finalize (This : in out Reader);

   ----------------
   -- QoS events --
   ----------------

   type QoS_Events is record
      Deadline_Total        : Interfaces.Unsigned_32 := 0;
      Deadline_Change       : Interfaces.Integer_32 := 0;
      Incompatible_Total    : Interfaces.Unsigned_32 := 0;
      Incompatible_Change   : Interfaces.Integer_32 := 0;
      Last_Policy           : Interfaces.Unsigned_32 := 0;
      --  DDS QoS policy id (11 = reliability, 2 = durability...).
      Liveliness_Lost_Total : Interfaces.Unsigned_32 := 0;
      Liveliness_Lost_Change : Interfaces.Integer_32 := 0;
      Alive_Count           : Interfaces.Unsigned_32 := 0;
      Not_Alive_Count       : Interfaces.Unsigned_32 := 0;
      Alive_Change          : Interfaces.Integer_32 := 0;
      Not_Alive_Change      : Interfaces.Integer_32 := 0;
      Lost_Total            : Interfaces.Unsigned_32 := 0;
      Lost_Change           : Interfaces.Integer_32 := 0;
      Matched_Total         : Interfaces.Unsigned_32 := 0;
      Matched_Change        : Interfaces.Integer_32 := 0;
      Matched_Current       : Interfaces.Unsigned_32 := 0;
      Matched_Current_Change : Interfaces.Integer_32 := 0;
   end record
     with Convention => C;
   --  The event statuses of a writer (deadline offered, incompatible QoS
   --  offered, liveliness lost, matched readers) or a reader (deadline
   --  requested, incompatible QoS requested, liveliness of its writers,
   --  samples lost, matched writers). Totals are cumulative; the "Change"
   --  fields count since the previous read by anyone (prefer differences of
   --  totals).

   procedure Poll_Events (This : Writer; Events : out QoS_Events)
     with Pre => Is_Open (This);
   procedure Poll_Events (This : Reader; Events : out QoS_Events)
     with Pre => Is_Open (This);

   -------------
   -- Waitset --
   -------------

   type Waitset is new Ada.Finalization.Limited_Controlled with private;
   --  Waits for data on readers, or for a wake-up from another task.

   subtype Attach_Key is Positive;

   procedure Create (This : in out Waitset; Owner : Participant'Class)
     with Pre => Is_Open (Owner);

   function Is_Open (This : Waitset) return Boolean;

   procedure Attach (This : in out Waitset; Source : Reader'Class; Key : Attach_Key)
     with Pre => Is_Open (This) and then Is_Open (Source);
   --  Key is reported by Wait when Source has data.

   procedure Detach (This : in out Waitset; Source : Reader'Class)
     with Pre => Is_Open (This) and then Is_Open (Source);

   type Key_Array is array (Positive range <>) of Attach_Key;

   procedure Wait
     (This    : in out Waitset;
      Timeout : Duration;
      Ready   : out Key_Array;
      Last    : out Natural);
   --  Blocks until data, Wake, or Timeout; Ready (Ready'First .. Last) are
   --  the keys of the readers with data (Last = Ready'First - 1: none).
   --  Wake's trigger is cleared on return.

   procedure Wake (This : Waitset);
   --  Makes a current or the next Wait return; callable from any task.

   overriding procedure Finalize (This : in out Waitset);

private

   use Interfaces;

   type Entity_Id is new Integer_32;
   No_Entity : constant Entity_Id := 0;

   type Participant is new Ada.Finalization.Limited_Controlled with record
      Handle : Entity_Id := No_Entity;
      Domain : Entity_Id := No_Entity;
      --  Our own explicitly created Cyclone domain, if any.
   end record;

   type Name_Access is access String;

   type Writer is new Ada.Finalization.Limited_Controlled with record
      Handle  : Entity_Id := No_Entity;
      Topic   : Entity_Id := No_Entity;
      Sertype : System.Address := System.Null_Address;
      Topic_Name, Type_Name : Name_Access;
   end record;

   type Handle_GUID is record
      Handle : Unsigned_64 := 0;
      Id     : GUID := Null_GUID;
   end record;

   type GUID_Cache is array (1 .. 8) of Handle_GUID;
   --  Publication handle -> writer GUID, most recent first.

   type Reader is new Ada.Finalization.Limited_Controlled with record
      Handle    : Entity_Id := No_Entity;
      Topic     : Entity_Id := No_Entity;
      Condition : Entity_Id := No_Entity;
      Cache     : GUID_Cache;
      Topic_Name, Type_Name : Name_Access;
      Liveliness : System.Address := System.Null_Address;
      --  The shim's liveliness tracker, when tracking.
   end record;

   type Waitset is new Ada.Finalization.Limited_Controlled with record
      Handle : Entity_Id := No_Entity;
   end record;

end RCL.DDS;
