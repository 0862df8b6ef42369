--  Private child: the thin binding to the part of Cyclone DDS's C API that
--  RCL.DDS uses, plus the raw-CDR shim of csrc/rclada_raw_cdr.c. C return
--  codes stay integers here; RCL.DDS checks them and raises.
with Interfaces.C;
with Interfaces.C.Strings;
with System;

private package RCL.DDS.Thin is

   use type C.int;

   subtype Entity_T is C.int;
   --  dds_entity_t: > 0 an entity, < 0 an error code.
   subtype Return_T is C.int;
   subtype Time_T is Integer_64;
   subtype Duration_T is Integer_64;
   subtype Instance_Handle_T is Unsigned_64;
   subtype Domain_Id_T is Unsigned_32;
   subtype Attach_T is C.ptrdiff_t;

   type Qos_Ptr is new System.Address;
   Null_Qos : constant Qos_Ptr := Qos_Ptr (System.Null_Address);

   DDS_Infinity       : constant Duration_T := Integer_64'Last;
   DDS_Domain_Default : constant Domain_Id_T := 16#FFFF_FFFF#;
   Retcode_OK         : constant Return_T := 0;
   Retcode_Precondition_Not_Met : constant Return_T := -4;
   Retcode_Timeout    : constant Return_T := -10;

   DDS_Any_State      : constant Unsigned_32 := 16#7F#;
   --  DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ANY_INSTANCE_STATE.

   --  QoS policy kinds (dds_public_qosdefs.h).
   History_Keep_Last       : constant C.int := 0;
   History_Keep_All        : constant C.int := 1;
   Reliability_Best_Effort : constant C.int := 0;
   Reliability_Reliable    : constant C.int := 1;
   Durability_Volatile     : constant C.int := 0;
   Durability_Transient_Local : constant C.int := 1;
   Liveliness_Automatic    : constant C.int := 0;
   Liveliness_Manual_By_Participant : constant C.int := 1;
   Liveliness_Manual_By_Topic : constant C.int := 2;
   Data_Representation_XCDR1 : constant Integer_16 := 0;

   type Matched_Status is record
      Total_Count          : Unsigned_32;
      Total_Count_Change   : Integer_32;
      Current_Count        : Unsigned_32;
      Current_Count_Change : Integer_32;
      Last_Handle          : Instance_Handle_T;
   end record
     with Convention => C;
   --  dds_publication_matched_status_t and dds_subscription_matched_status_t.

   type Raw_Info is record
      Source_Timestamp   : Integer_64;
      Publication_Handle : Unsigned_64;
   end record
     with Convention => C;
   --  struct rclada_raw_info.

   type Guid_Bytes is array (1 .. 16) of Unsigned_8
     with Convention => C;

   type Attach_Array is array (Positive range <>) of Attach_T
     with Convention => C;

   function Strretcode (Code : Return_T) return C.Strings.chars_ptr
     with Import, Convention => C, External_Name => "dds_strretcode";

   function Create_Domain
     (Domain : Domain_Id_T; Config : C.Strings.chars_ptr) return Entity_T
     with Import, Convention => C, External_Name => "rclada_dds_create_domain";
   --  dds_create_domain with SIGINT/SIGTERM blocked meanwhile (shim).

   function Create_Participant (Domain : Domain_Id_T; Qos : Qos_Ptr) return Entity_T
     with Import, Convention => C, External_Name => "rclada_dds_create_participant";
   --  dds_create_participant (no listener) with SIGINT/SIGTERM blocked
   --  meanwhile, so Cyclone's threads leave them to the Ada runtime (shim).

   function Delete (Entity : Entity_T) return Return_T
     with Import, Convention => C, External_Name => "dds_delete";

   function Create_Writer
     (Participant_Or_Publisher : Entity_T; Topic : Entity_T; Qos : Qos_Ptr;
      Listener : System.Address) return Entity_T
     with Import, Convention => C, External_Name => "dds_create_writer";

   function Create_Reader
     (Participant_Or_Subscriber : Entity_T; Topic : Entity_T; Qos : Qos_Ptr;
      Listener : System.Address) return Entity_T
     with Import, Convention => C, External_Name => "dds_create_reader";

   function Create_Readcondition
     (Reader : Entity_T; Mask : Unsigned_32) return Entity_T
     with Import, Convention => C, External_Name => "dds_create_readcondition";

   function Create_Guardcondition (Owner : Entity_T) return Entity_T
     with Import, Convention => C, External_Name => "dds_create_guardcondition";

   function Set_Guardcondition
     (Guard : Entity_T; Triggered : C.C_bool) return Return_T
     with Import, Convention => C, External_Name => "dds_set_guardcondition";

   function Take_Guardcondition
     (Guard : Entity_T; Triggered : out C.C_bool) return Return_T
     with Import, Convention => C, External_Name => "dds_take_guardcondition";

   function Create_Waitset (Owner : Entity_T) return Entity_T
     with Import, Convention => C, External_Name => "dds_create_waitset";

   function Waitset_Attach
     (Waitset : Entity_T; Entity : Entity_T; X : Attach_T) return Return_T
     with Import, Convention => C, External_Name => "dds_waitset_attach";

   function Waitset_Detach (Waitset : Entity_T; Entity : Entity_T) return Return_T
     with Import, Convention => C, External_Name => "dds_waitset_detach";

   function Waitset_Set_Trigger (Waitset : Entity_T; Trigger : C.C_bool) return Return_T
     with Import, Convention => C, External_Name => "dds_waitset_set_trigger";

   function Waitset_Wait
     (Waitset : Entity_T; Xs : System.Address; Nxs : C.size_t;
      Reltimeout : Duration_T) return Return_T
     with Import, Convention => C, External_Name => "dds_waitset_wait";

   function Get_Publication_Matched_Status
     (Writer : Entity_T; Status : out Matched_Status) return Return_T
     with Import, Convention => C,
          External_Name => "dds_get_publication_matched_status";

   function Get_Subscription_Matched_Status
     (Reader : Entity_T; Status : out Matched_Status) return Return_T
     with Import, Convention => C,
          External_Name => "dds_get_subscription_matched_status";

   function Get_Instance_Handle
     (Entity : Entity_T; Handle : out Instance_Handle_T) return Return_T
     with Import, Convention => C, External_Name => "dds_get_instance_handle";

   --  QoS ------------------------------------------------------------------

   function Create_Qos return Qos_Ptr
     with Import, Convention => C, External_Name => "dds_create_qos";

   procedure Delete_Qos (Qos : Qos_Ptr)
     with Import, Convention => C, External_Name => "dds_delete_qos";

   procedure Qset_Userdata (Qos : Qos_Ptr; Value : System.Address; Size : C.size_t)
     with Import, Convention => C, External_Name => "dds_qset_userdata";

   procedure Qset_Prop (Qos : Qos_Ptr; Name, Value : C.Strings.chars_ptr)
     with Import, Convention => C, External_Name => "dds_qset_prop";

   procedure Qset_History (Qos : Qos_Ptr; Kind : C.int; Depth : Integer_32)
     with Import, Convention => C, External_Name => "dds_qset_history";

   procedure Qset_Reliability
     (Qos : Qos_Ptr; Kind : C.int; Max_Blocking_Time : Duration_T)
     with Import, Convention => C, External_Name => "dds_qset_reliability";

   procedure Qset_Durability (Qos : Qos_Ptr; Kind : C.int)
     with Import, Convention => C, External_Name => "dds_qset_durability";

   Destination_Order_By_Source_Timestamp : constant C.int := 1;
   procedure Qset_Destination_Order (Qos : Qos_Ptr; Kind : C.int)
     with Import, Convention => C, External_Name => "dds_qset_destination_order";

   procedure Qset_Deadline (Qos : Qos_Ptr; Deadline : Duration_T)
     with Import, Convention => C, External_Name => "dds_qset_deadline";

   procedure Qset_Lifespan (Qos : Qos_Ptr; Lifespan : Duration_T)
     with Import, Convention => C, External_Name => "dds_qset_lifespan";

   procedure Qset_Liveliness
     (Qos : Qos_Ptr; Kind : C.int; Lease_Duration : Duration_T)
     with Import, Convention => C, External_Name => "dds_qset_liveliness";

   procedure Qset_Writer_Data_Lifecycle (Qos : Qos_Ptr; Autodispose : C.C_bool)
     with Import, Convention => C,
          External_Name => "dds_qset_writer_data_lifecycle";

   procedure Qset_Data_Representation
     (Qos : Qos_Ptr; N : Unsigned_32; Values : System.Address)
     with Import, Convention => C,
          External_Name => "dds_qset_data_representation";

   procedure Qset_Ignorelocal (Qos : Qos_Ptr; Kind : C.int)
     with Import, Convention => C, External_Name => "dds_qset_ignorelocal";
   --  0 none, 1 participant, 2 process.

   --  The raw-CDR shim (csrc/rclada_raw_cdr.h) -------------------------------

   function Create_Raw_Topic
     (Participant : Entity_T; Topic_Name, Type_Name : C.Strings.chars_ptr;
      Qos : Qos_Ptr; Sertype : out System.Address) return Entity_T
     with Import, Convention => C,
          External_Name => "rclada_dds_create_raw_topic";

   function Write_Raw
     (Writer : Entity_T; Sertype : System.Address; Bytes : System.Address;
      Size : C.size_t; Timestamp : Time_T) return Return_T
     with Import, Convention => C, External_Name => "rclada_dds_write_raw";

   function Serdata_New
     (Sertype : System.Address; Size : C.size_t; Buffer : out System.Address)
      return System.Address
     with Import, Convention => C, External_Name => "rclada_dds_serdata_new";

   function Write_Serdata
     (Writer : Entity_T; Serdata : System.Address; Used : C.size_t; Timestamp : Time_T)
      return Return_T
     with Import, Convention => C, External_Name => "rclada_dds_write_serdata";

   function Take_Raw
     (Reader : Entity_T; Serdata : out System.Address; Info : out Raw_Info)
      return Integer_32
     with Import, Convention => C, External_Name => "rclada_dds_take_raw";

   Take_Max : constant := 64;
   --  RCLADA_TAKE_MAX.
   type Serdata_Array is array (1 .. Take_Max) of System.Address
     with Convention => C;
   type Raw_Info_Array is array (1 .. Take_Max) of Raw_Info
     with Convention => C;

   function Take_Raw_Many
     (Reader  : Entity_T;
      Serdata : out Serdata_Array;
      Info    : out Raw_Info_Array;
      Max     : Integer_32) return Integer_32
     with Import, Convention => C, External_Name => "rclada_dds_take_raw_many";

   function Serdata_Bytes
     (Serdata : System.Address; Size : out Unsigned_32) return System.Address
     with Import, Convention => C, External_Name => "rclada_dds_serdata_bytes";

   procedure Serdata_Release (Serdata : System.Address)
     with Import, Convention => C,
          External_Name => "rclada_dds_serdata_release";

   function Publication_Guid
     (Reader : Entity_T; Handle : Instance_Handle_T; Guid : out Guid_Bytes)
      return Return_T
     with Import, Convention => C,
          External_Name => "rclada_dds_publication_guid";

   function Entity_Guid (Entity : Entity_T; Guid : out Guid_Bytes) return Return_T
     with Import, Convention => C, External_Name => "rclada_dds_entity_guid";

   --  Liveliness of matched writers (shim, rclada_liveliness.h).

   function Liveliness_Attach (Reader : Entity_T) return System.Address
     with Import, Convention => C, External_Name => "rclada_liveliness_attach";

   function Liveliness_Take
     (Tracker : System.Address; Guid : out Guid_Bytes; Alive : out C.int) return C.int
     with Import, Convention => C, External_Name => "rclada_liveliness_take";

   function Liveliness_Dropped (Tracker : System.Address) return C.unsigned
     with Import, Convention => C, External_Name => "rclada_liveliness_dropped";

   procedure Liveliness_Detach (Reader : Entity_T; Tracker : System.Address)
     with Import, Convention => C, External_Name => "rclada_liveliness_detach";

end RCL.DDS.Thin;
