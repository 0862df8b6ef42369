with Ada.Calendar;
with Ada.Containers.Ordered_Sets;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with ROSIDL.CDR;
with RCL.Contexts;
with RCL.DDS.Matching;
with RCL.Graph;
with RCL.Logging;

package body RCL.Services is

   use Ada.Strings.Unbounded;
   use type Ada.Calendar.Time;
   use type RCL.DDS.Matching.Key_Lookup;
   use type RCL.DDS.GUID;

   Deep_History : constant := 1000;
   --  The request reader keeps at least this many requests, so that a burst
   --  from many clients is not cut by a KEEP_LAST history before the node
   --  spins (depth does not affect matching).

   function Request_Topic (Service_Name : String) return String is
     ("rq" & Service_Name & "Request");

   function Reply_Topic (Service_Name : String) return String is
     ("rr" & Service_Name & "Reply");

   function "<" (L, R : RCL.DDS.GUID) return Boolean is
     (RCL.DDS.Image (L) < RCL.DDS.Image (R));

   package GUID_Sets is new Ada.Containers.Ordered_Sets (RCL.DDS.GUID, "<", RCL.DDS."=");

   protected type GUID_Set is
      --  Deliver may run in several executor tasks at once.
      function Contains (G : RCL.DDS.GUID) return Boolean;
      procedure Include (G : RCL.DDS.GUID);
   private
      Set : GUID_Sets.Set;
   end GUID_Set;

   protected body GUID_Set is
      function Contains (G : RCL.DDS.GUID) return Boolean is (Set.Contains (G));
      procedure Include (G : RCL.DDS.GUID) is
      begin
         Set.Include (G);
      end Include;
   end GUID_Set;

   type Service_Handler is new RCL.Nodes.Handler with record
      Support  : ROSIDL.Typesupport.Service_Support;
      Callback : Services.Callback;
      Name     : Unbounded_String;
      Replies  : RCL.DDS.Writer;
      Requests : RCL.Nodes.Subscription_Access;
      --  The node's subscription holding the request reader.
      Ready    : GUID_Set;
      --  Request writers whose client's reply reader is known to be
      --  matched: their replies are written without checking again (a
      --  reply to a client gone meanwhile is harmless).
   end record;

   overriding procedure Deliver
     (This : in out Service_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info);

   --------------------
   -- Client_Present --
   --------------------

   function Client_Present
     (This : in out Service_Handler; Requester : RCL.DDS.GUID) return Boolean
   --  rmw_cyclonedds's check_for_response_reader, waiting up to
   --  Reply_Match_Wait: True when the reply may be written.
   is
      Result   : RCL.DDS.Matching.Key_Lookup;
      Id       : Unbounded_String;
      Deadline : constant Ada.Calendar.Time := Ada.Calendar.Clock + Reply_Match_Wait;
   begin
      if Requester = RCL.DDS.Null_GUID then
         return True;  --  Writer unknown to the reader's cache: answer anyway.
      elsif This.Ready.Contains (Requester) then
         return True;
      end if;
      loop
         RCL.DDS.Matching.Writer_Key
           (This.Requests.Reader, Requester, "clientid", Result, Id);
         case Result is
            when RCL.DDS.Matching.Gone =>
               return False;
            when RCL.DDS.Matching.No_Key =>
               return True;  --  An old client without id: assume it is ready.
            when RCL.DDS.Matching.Found =>
               if RCL.DDS.Matching.Has_Matched_Reader
                    (This.Replies, "clientid", To_String (Id))
               then
                  This.Ready.Include (Requester);
                  return True;
               end if;
         end case;
         exit when Ada.Calendar.Clock >= Deadline;
         delay 0.01;
      end loop;
      RCL.Logging.Warn ("service " & To_String (This.Name)
                        & ": the reply reader of client " & To_String (Id)
                        & " is not matched after" & Reply_Match_Wait'Image
                        & " s; reply dropped");
      return False;
   end Client_Present;

   -------------
   -- Deliver --
   -------------

   overriding procedure Deliver
     (This : in out Service_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      use ROSIDL.Typesupport;
      Request  : ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (Request_Support (This.Support));
      Response : ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (Response_Support (This.Support));
      Header   : ROSIDL.CDR.Request_Header;
   begin
      begin
         ROSIDL.CDR.Decode (Data, Request, Header);
      exception
         when E : ROSIDL.Decode_Error =>
            RCL.Logging.Warn ("service " & To_String (This.Name)
                              & ": malformed request dropped: "
                              & Ada.Exceptions.Exception_Message (E));
            return;
      end;
      This.Callback (Node, Request, Response);
      if Client_Present (This, RCL.DDS.GUID (Info.Publisher_GID)) then
         RCL.DDS.Write (This.Replies, ROSIDL.CDR.Encode (Response, Header));
      end if;
   end Deliver;

   -----------
   -- Serve --
   -----------

   procedure Free is new Ada.Unchecked_Deallocation
     (RCL.Nodes.Handler'Class, RCL.Nodes.Handler_Access);

   procedure Serve
     (Node     : in out RCL.Nodes.Node'Class;
      Support  : ROSIDL.Typesupport.Service_Support;
      Name     : String;
      Callback : not null access procedure
        (Node     : in out RCL.Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message);
      QoS      : RCL.QoS.Profile := RCL.QoS.Services_Default)
   is
      use ROSIDL.Typesupport;
      Stored : constant Services.Callback with Import, Address => Callback'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
      FQ     : constant String := Node.Expand (Name);
      Id     : constant String :=
        "serviceid="
        & RCL.DDS.Matching.New_Id (RCL.Contexts.Participant.all) & ";";
      H      : RCL.Nodes.Handler_Access := new Service_Handler;
      S      : Service_Handler renames Service_Handler (H.all);
   begin
      S.Support := Support;
      S.Callback := Stored;
      S.Name := To_Unbounded_String (FQ);
      RCL.DDS.Create (S.Replies, RCL.Contexts.Participant.all, Reply_Topic (FQ),
                      DDS_Type_Name (Response_Support (Support)), QoS,
                      User_Data => RCL.Graph.Endpoint_User_Data
                                     (DDS_Type_Name (Response_Support (Support)), Id));
      RCL.Graph.Add_Writer (Node.Graph_Id, RCL.DDS.Endpoint_GUID (S.Replies));
      Node.Add_Endpoint
        (Type_Name => DDS_Type_Name (Request_Support (Support)),
         DDS_Topic => Request_Topic (FQ),
         Name      => FQ,
         User_Data => Id,
         Handle    => H,
         QoS       => (QoS with delta Depth => Positive'Max (QoS.Depth, Deep_History)),
         Added     => S.Requests);
   exception
      when others =>
         Free (H);  --  (Add_Endpoint did not keep it.)
         raise;
   end Serve;

end RCL.Services;
