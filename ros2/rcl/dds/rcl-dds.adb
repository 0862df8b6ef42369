with Ada.Environment_Variables;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with Interfaces.C.Strings;

with RCL.DDS.Thin;

package body RCL.DDS is

   package C renames Interfaces.C;
   package CS renames Interfaces.C.Strings;
   use type C.int;
   use type C.ptrdiff_t;
   use type System.Address;

   procedure Free is new Ada.Unchecked_Deallocation (String, Name_Access);

   Localhost_Config : constant String :=
     "<CycloneDDS><Domain Id=""any""><General><Interfaces>"
     & "<NetworkInterface address=""127.0.0.1""/></Interfaces>"
     & "<AllowMulticast>false</AllowMulticast></General><Discovery>"
     & "<ParticipantIndex>auto</ParticipantIndex>"
     & "<MaxAutoParticipantIndex>50</MaxAutoParticipantIndex>"
     & "<Peers><Peer address=""127.0.0.1""/></Peers></Discovery></Domain>"
     & "</CycloneDDS>";
   --  Loopback only: unicast discovery on 127.0.0.1, never multicast.

   ----------------
   -- Error_Text --
   ----------------

   function Error_Text (Code : Integer) return String is
     (CS.Value (Thin.Strretcode (C.int (Code))));

   -----------
   -- Check --
   -----------

   procedure Check (Code : Integer; What : String) is
   begin
      if Code < 0 then
         raise ROS_Exception with What & ": " & Error_Text (Code);
      end if;
   end Check;

   -----------
   -- Image --
   -----------

   function Image (This : GUID) return String is
      Hex    : constant String := "0123456789abcdef";
      Result : String (1 .. 3 * This'Length - 1) := [others => '.'];
      Pos    : Positive := 1;
   begin
      for B of This loop
         Result (Pos)     := Hex (Natural (B / 16) + 1);
         Result (Pos + 1) := Hex (Natural (B mod 16) + 1);
         Pos := Pos + 3;
      end loop;
      return Result;
   end Image;

   ---------
   -- Now --
   ---------

   function Now return Time_Ns is
      function Dds_Time return Integer_64
        with Import, Convention => C, External_Name => "dds_time";
   begin
      return Time_Ns (Dds_Time);
   end Now;

   -------------
   -- Domains --
   -------------

   type Domain_Count is array (Domain_Id) of Natural;
   type Domain_Entities is array (Domain_Id) of Entity_Id;

   protected Domains is
      procedure Acquire (Id : Domain_Id; Localhost_Only : Boolean; Handle : out Entity_Id);
      --  Handle is the Cyclone domain entity we created (No_Entity if the
      --  default configuration is used or the domain already existed).
      procedure Release (Id : Domain_Id; Delete_Domain : out Entity_Id);
   private
      Users   : Domain_Count := [others => 0];
      Created : Domain_Entities := [others => No_Entity];
   end Domains;

   protected body Domains is

      procedure Acquire (Id : Domain_Id; Localhost_Only : Boolean; Handle : out Entity_Id) is
      begin
         if Users (Id) = 0 and then Localhost_Only
           and then Ada.Environment_Variables.Value ("CYCLONEDDS_URI", "") = ""
         then
            declare
               Config : CS.chars_ptr := CS.New_String (Localhost_Config);
               Result : constant C.int :=
                 Thin.Create_Domain (Thin.Domain_Id_T (Id), Config);
            begin
               CS.Free (Config);
               if Result > 0 then
                  Created (Id) := Entity_Id (Result);
               elsif Result /= Thin.Retcode_Precondition_Not_Met then
                  --  Precondition not met: the domain already exists.
                  Check (Integer (Result), "creating the loopback-only DDS domain"
                         & Id'Image);
               end if;
            end;
         end if;
         Users (Id) := Users (Id) + 1;
         Handle := Created (Id);
      end Acquire;

      procedure Release (Id : Domain_Id; Delete_Domain : out Entity_Id) is
      begin
         Delete_Domain := No_Entity;
         if Users (Id) > 0 then
            Users (Id) := Users (Id) - 1;
            if Users (Id) = 0 then
               Delete_Domain := Created (Id);
               Created (Id) := No_Entity;
            end if;
         end if;
      end Release;

   end Domains;

   ---------
   -- QoS --
   ---------

   function To_Dds (D : Duration) return Thin.Duration_T is
     (if D >= RCL.QoS.Infinite then Thin.DDS_Infinity
      else Thin.Duration_T (D * 1_000_000_000.0));

   function Make_Qos
     (Profile : RCL.QoS.Profile; User_Data : String) return Thin.Qos_Ptr
   is
      use RCL.QoS;
      Q : constant Thin.Qos_Ptr := Thin.Create_Qos;
      Xcdr1 : aliased constant Integer_16 := Thin.Data_Representation_XCDR1;
   begin
      case Profile.History is
         when Keep_Last =>
            Thin.Qset_History (Q, Thin.History_Keep_Last, Integer_32 (Profile.Depth));
         when Keep_All =>
            Thin.Qset_History (Q, Thin.History_Keep_All, -1);
         when Middleware_Default =>
            null;
      end case;
      case Profile.Reliability is
         when Reliable =>
            Thin.Qset_Reliability (Q, Thin.Reliability_Reliable, Thin.DDS_Infinity);
         when Best_Effort =>
            Thin.Qset_Reliability (Q, Thin.Reliability_Best_Effort, 0);
         when Middleware_Default =>
            null;
      end case;
      case Profile.Durability is
         when Volatile =>
            Thin.Qset_Durability (Q, Thin.Durability_Volatile);
         when Transient_Local =>
            Thin.Qset_Durability (Q, Thin.Durability_Transient_Local);
         when Middleware_Default =>
            null;
      end case;
      if Profile.Deadline > 0.0 then
         Thin.Qset_Deadline (Q, To_Dds (Profile.Deadline));
      end if;
      if Profile.Lifespan > 0.0 then
         Thin.Qset_Lifespan (Q, To_Dds (Profile.Lifespan));
      end if;
      case Profile.Liveliness is
         when Automatic =>
            Thin.Qset_Liveliness (Q, Thin.Liveliness_Automatic, To_Dds (Profile.Lease));
         when Manual_By_Topic =>
            Thin.Qset_Liveliness
              (Q, Thin.Liveliness_Manual_By_Topic, To_Dds (Profile.Lease));
         when Middleware_Default =>
            null;
      end case;
      if Profile.Destination_Order = By_Source_Timestamp then
         Thin.Qset_Destination_Order (Q, Thin.Destination_Order_By_Source_Timestamp);
      end if;
      Thin.Qset_Writer_Data_Lifecycle (Q, C.C_bool (False));
      Thin.Qset_Data_Representation (Q, 1, Xcdr1'Address);
      if User_Data /= "" then
         Thin.Qset_Userdata (Q, User_Data'Address, User_Data'Length);
      end if;
      return Q;
   end Make_Qos;

   procedure Delete (E : in out Entity_Id) is
      Ignored : C.int;
   begin
      if E /= No_Entity then
         Ignored := Thin.Delete (C.int (E));
         E := No_Entity;
      end if;
   end Delete;

   --  Deletes what a reader or a writer owns: its entity, its topic, its names.
   procedure Delete_Endpoint
     (Handle, Topic : in out Entity_Id; Topic_Name, Type_Name : in out Name_Access) is
   begin
      Delete (Handle);
      Delete (Topic);
      Free (Topic_Name);
      Free (Type_Name);
   end Delete_Endpoint;

   -----------------
   -- Participant --
   -----------------

   function Plugin_Directory return String is
      Size : constant := 4096;
      function Find (Dir : out C.char_array; Length : C.size_t) return C.int
        with Import, Convention => C, External_Name => "rclada_security_plugin_dir";
      Dir : C.char_array (1 .. Size);
   begin
      if Find (Dir, Size) /= 0 then
         raise ROS_Exception with "security: Cyclone's DDS-Security plugins"
           & " (libdds_security_auth.so...) are not installed beside libddsc"
           & " (Debian: package libddsc0debian)";
      end if;
      return C.To_Ada (Dir);
   end Plugin_Directory;

   procedure Set_Security (Q : Thin.Qos_Ptr; Files : RCL.Security.Enclave_Files) is
      use RCL.Security;
      Dir : constant String := Plugin_Directory;

      procedure Property (Name, Value : String) is
         N : CS.chars_ptr := CS.New_String (Name);
         V : CS.chars_ptr := CS.New_String (Value);
      begin
         Thin.Qset_Prop (Q, N, V);
         CS.Free (N);
         CS.Free (V);
      end Property;

      procedure Plugin (Kind, File, Init, Finalize : String) is
      begin
         Property ("dds.sec." & Kind & ".library.path", Dir & "/" & File);
         Property ("dds.sec." & Kind & ".library.init", Init);
         Property ("dds.sec." & Kind & ".library.finalize", Finalize);
      end Plugin;

      function URI (Kind : File_Kind) return String is
        ("file:" & Ada.Strings.Unbounded.To_String (Files (Kind)));
   begin
      Plugin ("auth", "libdds_security_auth.so", "init_authentication",
              "finalize_authentication");
      Plugin ("crypto", "libdds_security_crypto.so", "init_crypto", "finalize_crypto");
      Plugin ("access", "libdds_security_ac.so", "init_access_control",
              "finalize_access_control");
      Property ("dds.sec.auth.identity_ca", URI (Identity_CA));
      Property ("dds.sec.auth.identity_certificate", URI (Certificate));
      Property ("dds.sec.auth.private_key", URI (Private_Key));
      Property ("dds.sec.access.permissions_ca", URI (Permissions_CA));
      Property ("dds.sec.access.governance", URI (Governance));
      Property ("dds.sec.access.permissions", URI (Permissions));
   end Set_Security;

   procedure Create
     (This           : in out Participant;
      Domain         : Domain_Id;
      Localhost_Only : Boolean;
      User_Data      : String := "enclave=/;";
      Security       : RCL.Security.Credentials := RCL.Security.Unsecured;
      Lease          : Duration := Configured_Lease)
   is
      Q      : Thin.Qos_Ptr;
      Result : C.int;
      Dom    : Entity_Id;
   begin
      Domains.Acquire (Domain, Localhost_Only, Dom);
      This.Domain := Dom;
      Q := Thin.Create_Qos;
      Thin.Qset_Userdata (Q, User_Data'Address, User_Data'Length);
      if Lease /= Configured_Lease then
         --  Cyclone accepts only AUTOMATIC for a participant.
         Thin.Qset_Liveliness (Q, Thin.Liveliness_Automatic, To_Dds (Lease));
      end if;
      if Security.Secured then
         begin
            Set_Security (Q, Security.Files);
         exception
            when others =>
               Thin.Delete_Qos (Q);
               This.Finalize;
               raise;
         end;
      end if;
      Result := Thin.Create_Participant (Thin.Domain_Id_T (Domain), Q);
      Thin.Delete_Qos (Q);
      if Result < 0 then
         This.Finalize;
         if Security.Secured then
            raise ROS_Exception with "creating the secured DDS participant on domain"
              & Domain'Image & ": " & Error_Text (Integer (Result))
              & ": Cyclone's security plugins refused the enclave's files "
              & Ada.Strings.Unbounded.To_String (Security.Files (RCL.Security.Permissions))
              & " and the others beside it (a signature that does not verify against"
              & " permissions_ca.cert.pem, an expired or foreign certificate; Cyclone's"
              & " own reason is printed above)";
         end if;
         Check (Integer (Result), "creating the DDS participant on domain" & Domain'Image);
      end if;
      This.Handle := Entity_Id (Result);
      This.Domain := Entity_Id (Domain) + 1;
      --  From here on Domain holds the domain id + 1 (for Release); the
      --  created domain entity is remembered by Domains.
   end Create;

   function Is_Open (This : Participant) return Boolean is (This.Handle > 0);

   function Instance_GUID (This : Participant) return GUID is
      G : Thin.Guid_Bytes;
   begin
      Check (Integer (Thin.Entity_Guid (C.int (This.Handle), G)), "getting a GUID");
      return GUID (G);
   end Instance_GUID;

   overriding procedure Finalize (This : in out Participant) is
      To_Delete : Entity_Id;
   begin
      Delete (This.Handle);
      if This.Domain > 0 then
         Domains.Release (Domain_Id (This.Domain - 1), To_Delete);
         Delete (To_Delete);
         This.Domain := No_Entity;
      end if;
   exception
      when others =>
         null;  --  Finalize never propagates.
   end Finalize;

   ------------
   -- Topics --
   ------------

   procedure Check_Created
     (Result     : C.int;
      What       : String;
      Topic_Name : String;
      Profile    : RCL.QoS.Profile;
      Topic      : in out Entity_Id)
   --  When creating a What ("writer", "reader") on Topic failed (Result < 0):
   --  deletes the Topic made for it and raises ROS_Exception (as Check).
   is
   begin
      if Result < 0 then
         Delete (Topic);
         Check (Integer (Result), "creating a " & What & " on """ & Topic_Name & """ with QoS "
                & RCL.QoS.Image (Profile));
      end if;
   end Check_Created;

   procedure Create_Topic
     (Owner              : Participant'Class;
      Topic_Name, Type_Name : String;
      Topic              : out Entity_Id;
      Sertype            : out System.Address)
   is
      T_Name : CS.chars_ptr := CS.New_String (Topic_Name);
      Y_Name : CS.chars_ptr := CS.New_String (Type_Name);
      Result : constant C.int :=
        Thin.Create_Raw_Topic (C.int (Owner.Handle), T_Name, Y_Name, Thin.Null_Qos, Sertype);
   begin
      CS.Free (T_Name);
      CS.Free (Y_Name);
      Check (Integer (Result),
             "creating topic """ & Topic_Name & """ of type " & Type_Name);
      Topic := Entity_Id (Result);
   end Create_Topic;

   ------------
   -- Writer --
   ------------

   procedure Create
     (This       : in out Writer;
      Owner      : Participant'Class;
      Topic_Name : String;
      Type_Name  : String;
      Profile    : RCL.QoS.Profile;
      User_Data  : String := "")
   is
      Q      : Thin.Qos_Ptr;
      Result : C.int;
   begin
      Create_Topic (Owner, Topic_Name, Type_Name, This.Topic, This.Sertype);
      Q := Make_Qos (Profile, User_Data);
      Result := Thin.Create_Writer
        (C.int (Owner.Handle), C.int (This.Topic), Q, System.Null_Address);
      Thin.Delete_Qos (Q);
      Check_Created (Result, "writer", Topic_Name, Profile, This.Topic);
      This.Handle := Entity_Id (Result);
      This.Topic_Name := new String'(Topic_Name);
      This.Type_Name := new String'(Type_Name);
   end Create;

   function Is_Open (This : Writer) return Boolean is (This.Handle > 0);

   procedure Write
     (This      : Writer;
      Data      : Byte_Array;
      Timestamp : Time_Ns := Invalid_Time)
   is
      Stamp : constant Time_Ns := (if Timestamp = Invalid_Time then Now else Timestamp);
   begin
      Check (Integer (Thin.Write_Raw (C.int (This.Handle), This.Sertype, Data'Address,
                                      Data'Length, Thin.Time_T (Stamp))),
             "publishing on """ & This.Topic_Name.all & """");
   end Write;

   procedure Write_Filled
     (This      : Writer;
      Size      : Ada.Streams.Stream_Element_Count;
      Fill      : not null access procedure
        (Buffer : out Byte_Array; Last : out Ada.Streams.Stream_Element_Offset);
      Timestamp : Time_Ns := Invalid_Time)
   is
      Stamp   : constant Time_Ns := (if Timestamp = Invalid_Time then Now else Timestamp);
      Storage : System.Address;
      Serdata : constant System.Address :=
        Thin.Serdata_New (This.Sertype, C.size_t (Size), Storage);
      Last    : Ada.Streams.Stream_Element_Offset;
   begin
      if Serdata = System.Null_Address then
         raise ROS_Exception with "publishing on """ & This.Topic_Name.all
           & """: no memory for" & Size'Image & " bytes";
      end if;
      declare
         Buffer : Byte_Array (1 .. Size) with Import, Address => Storage;
      begin
         Fill (Buffer, Last);
      exception
         when others =>
            Thin.Serdata_Release (Serdata);
            raise;
      end;
      if Last < 4 or else Last > Size then
         Thin.Serdata_Release (Serdata);
         raise Program_Error with "Write_Filled: Last out of 4 .." & Size'Image;
      end if;
      Check (Integer (Thin.Write_Serdata (C.int (This.Handle), Serdata, C.size_t (Last),
                                          Thin.Time_T (Stamp))),
             "publishing on """ & This.Topic_Name.all & """");
   end Write_Filled;

   function Entity_GUID (Entity : C.int; What : String) return GUID is
      G : Thin.Guid_Bytes;
   begin
      Check (Integer (Thin.Entity_Guid (Entity, G)), "getting a " & What & " GUID");
      return GUID (G);
   end Entity_GUID;

   function Endpoint_GUID (This : Writer) return GUID is
     (Entity_GUID (C.int (This.Handle), "writer"));

   function Matched_Readers (This : Writer) return Natural is
      S : Thin.Matched_Status;
   begin
      Check (Integer (Thin.Get_Publication_Matched_Status (C.int (This.Handle), S)),
             "getting the matched readers of """ & This.Topic_Name.all & """");
      return Natural (S.Current_Count);
   end Matched_Readers;

   function Poll_Writer_Events (Writer : C.int; Events : out QoS_Events) return C.int
     with Import, Convention => C, External_Name => "rclada_poll_writer_events";
   function Poll_Reader_Events (Reader : C.int; Events : out QoS_Events) return C.int
     with Import, Convention => C, External_Name => "rclada_poll_reader_events";

   procedure Poll_Events (This : Writer; Events : out QoS_Events) is
   begin
      Check (Integer (Poll_Writer_Events (C.int (This.Handle), Events)),
             "reading the QoS events of the writer of """ & Topic_Name (This) & """");
   end Poll_Events;

   procedure Poll_Events (This : Reader; Events : out QoS_Events) is
   begin
      Check (Integer (Poll_Reader_Events (C.int (This.Handle), Events)),
             "reading the QoS events of the reader of """ & Topic_Name (This) & """");
   end Poll_Events;

   function Topic_Name (This : Writer) return String is
     (if This.Topic_Name = null then "" else This.Topic_Name.all);
   function Type_Name (This : Writer) return String is
     (if This.Type_Name = null then "" else This.Type_Name.all);

   overriding procedure Finalize (This : in out Writer) is
   begin
      Delete_Endpoint (This.Handle, This.Topic, This.Topic_Name, This.Type_Name);
   exception
      when others =>
         null;
   end Finalize;

   ------------
   -- Reader --
   ------------

   procedure Create
     (This        : in out Reader;
      Owner       : Participant'Class;
      Topic_Name  : String;
      Type_Name   : String;
      Profile     : RCL.QoS.Profile;
      User_Data   : String := "";
      Ignore_Self : Boolean := False)
   is
      Q       : Thin.Qos_Ptr;
      Result  : C.int;
      Sertype : System.Address;
   begin
      Create_Topic (Owner, Topic_Name, Type_Name, This.Topic, Sertype);
      Q := Make_Qos (Profile, User_Data);
      if Ignore_Self then
         Thin.Qset_Ignorelocal (Q, 1);
      end if;
      Result := Thin.Create_Reader
        (C.int (Owner.Handle), C.int (This.Topic), Q, System.Null_Address);
      Thin.Delete_Qos (Q);
      Check_Created (Result, "reader", Topic_Name, Profile, This.Topic);
      This.Handle := Entity_Id (Result);
      Result := Thin.Create_Readcondition (C.int (This.Handle), Thin.DDS_Any_State);
      Check (Integer (Result), "creating a read condition on """ & Topic_Name & """");
      This.Condition := Entity_Id (Result);
      This.Topic_Name := new String'(Topic_Name);
      This.Type_Name := new String'(Type_Name);
   end Create;

   function Is_Open (This : Reader) return Boolean is (This.Handle > 0);

   function Publisher_Of (This : in out Reader; Handle : Unsigned_64) return GUID is
      G : Thin.Guid_Bytes;
   begin
      for I in This.Cache'Range loop
         if This.Cache (I).Handle = Handle then
            return This.Cache (I).Id;
         end if;
      end loop;
      if Thin.Publication_Guid (C.int (This.Handle), Handle, G) /= Thin.Retcode_OK then
         return Null_GUID;
      end if;
      This.Cache (This.Cache'First + 1 .. This.Cache'Last) :=
        This.Cache (This.Cache'First .. This.Cache'Last - 1);
      This.Cache (This.Cache'First) := (Handle, GUID (G));
      return GUID (G);
   end Publisher_Of;

   procedure Deliver
     (This    : in out Reader;
      Serdata : System.Address;
      Raw     : Thin.Raw_Info;
      Process : not null access procedure (Data : Byte_Array; Info : Sample_Info))
   is
      --  Passes one taken sample's bytes to Process in place (no copy); the
      --  caller releases Serdata.
      Size  : Unsigned_32;
      Bytes : constant System.Address := Thin.Serdata_Bytes (Serdata, Size);
      Info  : constant Sample_Info :=
        (Source_Timestamp => Time_Ns (Raw.Source_Timestamp),
         Publisher        => Publisher_Of (This, Raw.Publication_Handle));
   begin
      if Size = 0 or else Bytes = System.Null_Address then
         declare
            Empty : constant Byte_Array (1 .. 0) := [others => 0];
         begin
            Process (Empty, Info);
         end;
      else
         declare
            Data : constant Byte_Array (1 .. Ada.Streams.Stream_Element_Offset (Size))
              with Import, Address => Bytes;
         begin
            Process (Data, Info);
         end;
      end if;
   end Deliver;

   procedure Take
     (This    : in out Reader;
      Process : not null access procedure (Data : Byte_Array; Info : Sample_Info);
      Taken   : out Boolean)
   is
      Serdata : System.Address;
      Raw     : Thin.Raw_Info;
      Result  : constant Integer_32 := Thin.Take_Raw (C.int (This.Handle), Serdata, Raw);
   begin
      Taken := False;
      Check (Integer (Result), "taking from """ & Topic_Name (This) & """");
      if Result = 0 then
         return;
      end if;
      Taken := True;
      begin
         Deliver (This, Serdata, Raw, Process);
      exception
         when others =>
            Thin.Serdata_Release (Serdata);
            raise;
      end;
      Thin.Serdata_Release (Serdata);
   end Take;

   procedure Take_Many
     (This    : in out Reader;
      Process : not null access procedure (Data : Byte_Array; Info : Sample_Info);
      Count   : out Natural)
   is
      Serdata : Thin.Serdata_Array;
      Raw     : Thin.Raw_Info_Array;
      Result  : constant Integer_32 :=
        Thin.Take_Raw_Many (C.int (This.Handle), Serdata, Raw, Take_Batch);
      Done    : Natural := 0;
      --  Samples processed and released.
   begin
      Count := 0;
      Check (Integer (Result), "taking from """ & Topic_Name (This) & """");
      if Result = 0 then
         return;
      end if;
      Count := Natural (Result);
      for I in 1 .. Count loop
         Deliver (This, Serdata (I), Raw (I), Process);
         Thin.Serdata_Release (Serdata (I));
         Done := I;
      end loop;
   exception
      when others =>
         for I in Done + 1 .. Count loop
            Thin.Serdata_Release (Serdata (I));
         end loop;
         raise;
   end Take_Many;

   function Take (This : in out Reader; Info : out Sample_Info) return Byte_Array is
      type Bytes_Access is access Byte_Array;
      procedure Free is new Ada.Unchecked_Deallocation (Byte_Array, Bytes_Access);
      Copy  : Bytes_Access;
      Taken : Boolean;
      procedure Keep (Data : Byte_Array; I : Sample_Info) is
      begin
         Copy := new Byte_Array'(Data);
         Info := I;
      end Keep;
   begin
      Info := (Invalid_Time, Null_GUID);
      Take (This, Keep'Access, Taken);
      if not Taken then
         return [1 .. 0 => 0];
      end if;
      return Result : constant Byte_Array := Copy.all do
         Free (Copy);
      end return;
   end Take;

   function Endpoint_GUID (This : Reader) return GUID is
     (Entity_GUID (C.int (This.Handle), "reader"));

   function Matched_Writers (This : Reader) return Natural is
      S : Thin.Matched_Status;
   begin
      Check (Integer (Thin.Get_Subscription_Matched_Status (C.int (This.Handle), S)),
             "getting the matched writers of """ & Topic_Name (This) & """");
      return Natural (S.Current_Count);
   end Matched_Writers;

   function Topic_Name (This : Reader) return String is
     (if This.Topic_Name = null then "" else This.Topic_Name.all);
   function Type_Name (This : Reader) return String is
     (if This.Type_Name = null then "" else This.Type_Name.all);

   procedure Track_Liveliness (This : in out Reader) is
   begin
      This.Liveliness := Thin.Liveliness_Attach (C.int (This.Handle));
      if This.Liveliness = System.Null_Address then
         raise ROS_Exception with "cannot track the liveliness of the writers of "
           & This.Topic_Name.all;
      end if;
   end Track_Liveliness;

   function Is_Tracking_Liveliness (This : Reader) return Boolean is
     (This.Liveliness /= System.Null_Address);

   procedure Take_Liveliness_Change
     (This   : in out Reader;
      Writer : out GUID;
      Alive  : out Boolean;
      Found  : out Boolean)
   is
      G : Thin.Guid_Bytes;
      A : C.int;
   begin
      Found := Thin.Liveliness_Take (This.Liveliness, G, A) = 1;
      Writer := (if Found then GUID (G) else Null_GUID);
      Alive := Found and then A = 1;
   end Take_Liveliness_Change;

   function Dropped_Liveliness_Changes (This : Reader) return Natural is
     (Natural (Thin.Liveliness_Dropped (This.Liveliness)));

   overriding procedure Finalize (This : in out Reader) is
   begin
      if This.Liveliness /= System.Null_Address then
         Thin.Liveliness_Detach (C.int (This.Handle), This.Liveliness);
         This.Liveliness := System.Null_Address;
      end if;
      Delete (This.Condition);
      Delete_Endpoint (This.Handle, This.Topic, This.Topic_Name, This.Type_Name);
   exception
      when others =>
         null;
   end Finalize;

   -------------
   -- Waitset --
   -------------

   procedure Create (This : in out Waitset; Owner : Participant'Class) is
      Result : constant C.int := Thin.Create_Waitset (C.int (Owner.Handle));
   begin
      Check (Integer (Result), "creating a waitset");
      This.Handle := Entity_Id (Result);
      --  Attached to itself (key 0, never reported) so that Wake, which sets
      --  its trigger, ends a Wait.
      Check (Integer (Thin.Waitset_Attach (Result, Result, 0)),
             "attaching a waitset to itself");
   end Create;

   function Is_Open (This : Waitset) return Boolean is (This.Handle > 0);

   procedure Attach (This : in out Waitset; Source : Reader'Class; Key : Attach_Key) is
   begin
      Check (Integer (Thin.Waitset_Attach (C.int (This.Handle), C.int (Source.Condition),
                                           Thin.Attach_T (Key))),
             "attaching """ & Topic_Name (Source) & """ to a waitset");
   end Attach;

   procedure Detach (This : in out Waitset; Source : Reader'Class) is
   begin
      Check (Integer (Thin.Waitset_Detach (C.int (This.Handle), C.int (Source.Condition))),
             "detaching """ & Topic_Name (Source) & """ from a waitset");
   end Detach;

   procedure Wait
     (This    : in out Waitset;
      Timeout : Duration;
      Ready   : out Key_Array;
      Last    : out Natural)
   is
      Xs     : Thin.Attach_Array (1 .. Integer'Max (Ready'Length, 1)) := [others => 0];
      Result : C.int;
   begin
      Last := Ready'First - 1;
      Result := Thin.Waitset_Wait
        (C.int (This.Handle), Xs'Address, C.size_t (Ready'Length),
         To_Dds (Duration'Max (Timeout, 0.0)));
      Check (Integer (Result), "waiting on a waitset");
      declare
         Ignored : C.int;
      begin
         Ignored := Thin.Waitset_Set_Trigger (C.int (This.Handle), C.C_bool (False));
      end;
      for I in 1 .. Integer'Min (Integer (Result), Ready'Length) loop
         if Xs (I) > 0 then
            Last := Last + 1;
            Ready (Last) := Attach_Key (Xs (I));
         end if;
      end loop;
   end Wait;

   procedure Wake (This : Waitset) is
      Ignored : C.int;
   begin
      if This.Handle > 0 then
         Ignored := Thin.Waitset_Set_Trigger (C.int (This.Handle), C.C_bool (True));
      end if;
   end Wake;

   overriding procedure Finalize (This : in out Waitset) is
   begin
      Delete (This.Handle);
   exception
      when others =>
         null;
   end Finalize;

end RCL.DDS;
