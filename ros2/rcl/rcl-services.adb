with Ada.Calendar;
with Ada.Exceptions;
with Ada.Unchecked_Deallocation;
with RCL.DDS.Matching;
with RCL.Graph;
with RCL.Graph_Announcements;
with RCL.Logging;
with RCL.Process_Context;

package body RCL.Services is

   use Ada.Strings.Unbounded;

   use type Ada.Calendar.Time;
   use type RCL.DDS.GUID;

   Deep_History : constant := 1000;
   --  The request reader keeps at least this many requests, so that a burst
   --  from many clients is not cut by a KEEP_LAST history before the node
   --  spins (depth does not affect matching).

   function Request_Topic (Service_Name : String) return String is
     ("rq" & Service_Name & "Request");

   function Reply_Topic (Service_Name : String) return String is
     ("rr" & Service_Name & "Reply");

   function "<" (L, R : RCL.DDS.GUID) return Boolean is (ROSIDL."<" (L, R));
   --  Byte by byte (no image built: Ready is looked up for every reply).

   protected body GUID_Set is
      function Contains (G : RCL.DDS.GUID) return Boolean is (Set.Contains (G));
      procedure Include (G : RCL.DDS.GUID) is
      begin
         Set.Include (G);
      end Include;
   end GUID_Set;

   type Service_Handler is new Server with record
      Callback : Services.Callback;
   end record;

   overriding procedure On_Request
     (This    : in out Service_Handler;
      Node    : in out RCL.Nodes.Node'Class;
      Request : ROSIDL.Dynamic.Message;
      Id      : Request_Id);

   type Raw_Callback is access procedure
     (Server : in out Services.Server'Class;
      Node   : in out RCL.Nodes.Node'Class;
      Data   : RCL.DDS.Byte_Array;
      Info   : ROSIDL.Message_Info);

   type Raw_Handler is new Server with record
      On_Request : Raw_Callback;
   end record;
   --  Open_Raw's servers: the requests are not decoded here.

   overriding procedure Deliver
     (This : in out Raw_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info);

   overriding procedure On_Request
     (This    : in out Raw_Handler;
      Node    : in out RCL.Nodes.Node'Class;
      Request : ROSIDL.Dynamic.Message;
      Id      : Request_Id);

   function Support (This : Server'Class) return ROSIDL.Typesupport.Service_Support is
     (This.Support);

   function Name (This : Server'Class) return String is (To_String (This.Name));

   --------------------
   -- Client_Present --
   --------------------

   function Client_Present
     (This : in out Server'Class; Requester : RCL.DDS.GUID) return Boolean
   --  rmw_cyclonedds's check_for_response_reader, waiting up to
   --  Reply_Match_Wait: True when the reply may be written.
   is
      Id       : Unbounded_String;
      Deadline : constant Ada.Calendar.Time := Ada.Calendar.Clock + Reply_Match_Wait;
   begin
      if Requester = RCL.DDS.Null_GUID then
         return True;  --  Writer unknown to the reader's cache: answer anyway.
      elsif This.Ready.Contains (Requester) then
         return True;
      end if;
      loop
         declare
            Client_Id : constant RCL.DDS.Matching.Key_Value :=
              RCL.DDS.Matching.Writer_Key (This.Requests.Reader, Requester, "clientid");
         begin
            case Client_Id.Lookup is
               when RCL.DDS.Matching.Gone =>
                  return False;
               when RCL.DDS.Matching.No_Key =>
                  return True;  --  An old client without id: assume it is ready.
               when RCL.DDS.Matching.Found =>
                  Id := Client_Id.Value;
                  if RCL.DDS.Matching.Has_Matched_Reader
                       (This.Replies, "clientid", To_String (Id))
                  then
                     This.Ready.Include (Requester);
                     return True;
                  end if;
            end case;
         end;
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
     (This : in out Server;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      use ROSIDL.Typesupport;
      Request : ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (Request_Support (This.Support));
      Id      : Request_Id;
   begin
      begin
         ROSIDL.CDR.Decode (Data, Request, Id.Header);
      exception
         when E : ROSIDL.Decode_Error =>
            RCL.Logging.Warn ("service " & To_String (This.Name)
                              & ": malformed request dropped: "
                              & Ada.Exceptions.Exception_Message (E));
            return;
      end;
      Id.Requester := RCL.DDS.GUID (Info.Publisher_GID);
      Server'Class (This).On_Request (Node, Request, Id);
   end Deliver;

   procedure Respond
     (This     : in out Server'Class;
      Id       : Request_Id;
      Response : ROSIDL.Dynamic.Message) is
   begin
      if Client_Present (This, Id.Requester) then
         RCL.DDS.Write (This.Replies, ROSIDL.CDR.Encode (Response, Id.Header));
      end if;
   end Respond;

   procedure Respond_Filled
     (This      : in out Server'Class;
      Requester : RCL.DDS.GUID;
      Size      : Ada.Streams.Stream_Element_Count;
      Fill      : not null access procedure
        (Buffer : out RCL.DDS.Byte_Array; Last : out Ada.Streams.Stream_Element_Offset)) is
   begin
      if Client_Present (This, Requester) then
         RCL.DDS.Write_Filled (This.Replies, Size, Fill);
      end if;
   end Respond_Filled;

   overriding procedure Deliver
     (This : in out Raw_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is
   begin
      This.On_Request (This, Node, Data, Info);
   end Deliver;

   overriding procedure On_Request
     (This    : in out Raw_Handler;
      Node    : in out RCL.Nodes.Node'Class;
      Request : ROSIDL.Dynamic.Message;
      Id      : Request_Id) is
   begin
      raise Program_Error with "raw service " & To_String (This.Name)
        & ": requests are not decoded here";
   end On_Request;

   overriding procedure On_Request
     (This    : in out Service_Handler;
      Node    : in out RCL.Nodes.Node'Class;
      Request : ROSIDL.Dynamic.Message;
      Id      : Request_Id)
   is
      Response : ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Response_Support (This.Support));
   begin
      This.Callback (Node, Request, Response);
      This.Respond (Id, Response);
   end On_Request;

   -----------
   -- Serve --
   -----------

   procedure Free is new Ada.Unchecked_Deallocation
     (RCL.Nodes.Handler'Class, RCL.Nodes.Handler_Access);

   procedure Open_Endpoints
     (Node          : in out RCL.Nodes.Node'Class;
      Handler       : not null Server_Access;
      Request_Type  : String;
      Response_Type : String;
      Name          : String;
      QoS           : RCL.QoS.Profile)
   is
      FQ : constant String := Node.Expand_Service (Name);
      Id : constant String :=
        "serviceid=" & RCL.DDS.Matching.New_Id (RCL.Process_Context.Participant.all) & ";";
      S  : Server'Class renames Handler.all;
   begin
      S.Name := To_Unbounded_String (FQ);
      RCL.DDS.Create (S.Replies, RCL.Process_Context.Participant.all, Reply_Topic (FQ),
                      Response_Type, QoS,
                      User_Data => RCL.Graph.Endpoint_User_Data (Response_Type, Id));
      RCL.Graph_Announcements.Add_Writer
        (RCL.Node_Entities.Graph_Id (Node), RCL.DDS.Endpoint_GUID (S.Replies));
      RCL.Node_Entities.Add_Endpoint
        (Node,
         Type_Name => Request_Type,
         DDS_Topic => Request_Topic (FQ),
         Name      => FQ,
         User_Data => Id,
         Handle    => RCL.Node_Entities.Handler_Access (Handler),
         QoS       => (QoS with delta Depth => Positive'Max (QoS.Depth, Deep_History)),
         Added     => S.Requests);
   end Open_Endpoints;

   procedure Open
     (Node    : in out RCL.Nodes.Node'Class;
      Handler : not null Server_Access;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Services_Default)
   is
      use ROSIDL.Typesupport;
   begin
      Handler.Support := Support;
      Open_Endpoints (Node, Handler, DDS_Type_Name (Request_Support (Support)),
                      DDS_Type_Name (Response_Support (Support)), Name, QoS);
   end Open;

   procedure Open_Raw
     (Node          : in out RCL.Nodes.Node'Class;
      Request_Type  : String;
      Response_Type : String;
      Name          : String;
      On_Request    : not null access procedure
        (Server : in out Services.Server'Class;
         Node   : in out RCL.Nodes.Node'Class;
         Data   : RCL.DDS.Byte_Array;
         Info   : ROSIDL.Message_Info);
      QoS           : RCL.QoS.Profile := RCL.QoS.Services_Default)
   is
      Stored : constant Raw_Callback with Import, Address => On_Request'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
      H : RCL.Nodes.Handler_Access := new Raw_Handler;
   begin
      Raw_Handler (H.all).On_Request := Stored;
      Open_Endpoints (Node, Server_Access (H), Request_Type, Response_Type, Name, QoS);
   exception
      when others =>
         Free (H);  --  (Add_Endpoint did not keep it.)
         raise;
   end Open_Raw;

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
      Stored : constant Services.Callback with Import, Address => Callback'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
      H : RCL.Nodes.Handler_Access := new Service_Handler;
   begin
      Service_Handler (H.all).Callback := Stored;
      Open (Node, Server_Access (H), Support, Name, QoS);
   exception
      when others =>
         Free (H);  --  (Add_Endpoint did not keep it.)
         raise;
   end Serve;

end RCL.Services;
