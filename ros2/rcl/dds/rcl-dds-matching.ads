--  The DDS discovery data, as ROS 2 reads it: the built-in topics
--  DCPSParticipant / DCPSPublication / DCPSSubscription (every participant
--  and endpoint discovered, with its QoS and USER_DATA), the USER_DATA of
--  the endpoints a reader or writer matched, and rmw_cyclonedds's service
--  conventions on top of them (client and service ids, "is the service
--  available"). RCL's graph queries, services and clients are built on it;
--  a program working at the DDS layer (RCL.DDS) uses it the same way.
--  Wraps csrc/rclada_matching.c.
--  Example:
--     P : Participant;
--     Create (P, Domain => 0, Localhost_Only => True);
--     for E of Builtin (P, Publications) loop
--        Put_Line (To_String (E.Topic_Name) & " : " & To_String (E.Type_Name));
--     end loop;
with Ada.Strings.Unbounded;

package RCL.DDS.Matching is

   use Ada.Strings.Unbounded;

   function Instance_Handle (This : Writer) return Interfaces.Unsigned_64
     with Pre => Is_Open (This);
   --  The writer's DDS instance handle (the "guid" of a request header).

   type Key_Lookup is (Found, No_Key, Gone);

   type Key_Value (Lookup : Key_Lookup := Gone) is record
      case Lookup is
         when Found         => Value : Unbounded_String;
         when No_Key | Gone => null;
      end case;
   end record;
   --  Gone: no such matched writer; No_Key: it has no such key.

   function Writer_Key (This : Reader; Writer_GUID : GUID; Key : String) return Key_Value
     with Pre => Is_Open (This);
   --  The USER_DATA value of Key ("clientid") of the writer matched by This
   --  whose GUID is Writer_GUID.

   function Has_Matched_Reader (This : Writer; Key, Value : String) return Boolean
     with Pre => Is_Open (This);
   --  A reader matched by This carries Key=Value in its USER_DATA.

   function Service_Available
     (Request_Writer : Writer; Reply_Reader : Reader) return Boolean
     with Pre => Is_Open (Request_Writer) and then Is_Open (Reply_Reader);
   --  rmw_cyclonedds's rule: a matched request reader and a matched reply
   --  writer with the same serviceid (without ids: both matched).

   type Builtin_Topic is (Participants, Publications, Subscriptions);

   type Endpoint is record
      Topic_Name, Type_Name : Unbounded_String;
      --  Empty for participants.
      Key, Participant_Key  : GUID;
      Reliability           : Integer;  --  0 best effort, 1 reliable, -1 unset
      Durability            : Integer;  --  0 volatile, 1 transient local, ...
      History               : Integer;  --  0 keep last, 1 keep all
      Depth                 : Integer;
      Deadline, Lifespan    : Time_Ns;  --  Time_Ns'Last: infinite
      Liveliness            : Integer;  --  0 automatic, 1 by participant, 2 by topic
      Lease                 : Time_Ns;
      User_Data             : Unbounded_String;
   end record;

   type Endpoint_Array is array (Positive range <>) of Endpoint;

   function Builtin (Owner : Participant'Class; Which : Builtin_Topic) return Endpoint_Array
     with Pre => Is_Open (Owner);
   --  Every alive participant or endpoint Owner has discovered (its own
   --  included), read from a fresh built-in reader.

   function User_Data_Value (User_Data, Key : String) return String;
   --  The value of Key in "k1=v1;k2=v2;" ("" when absent).

   function Id_Image (Prefix : GUID; Counter : Interfaces.Unsigned_32) return String;
   --  A client/service id as rmw_cyclonedds prints it: the 12-byte prefix
   --  of Prefix then Counter big-endian, in hexadecimal without leading
   --  zeros, the first byte in a field of two (space-filled), "." between.

   function New_Id (Owner : Participant'Class) return String
     with Pre => Is_Open (Owner);
   --  Id_Image of Owner's GUID and the next value of a process-wide counter
   --  (for "clientid=" / "serviceid=").

end RCL.DDS.Matching;
