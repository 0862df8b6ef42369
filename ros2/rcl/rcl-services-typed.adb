with Ada.Exceptions;
with Ada.Streams;
with ROSIDL.CDR;
with ROSIDL.Type_Hashes;
with RCL.Contexts;
with RCL.Logging;
with RCL.Pending_Calls;
with RCL.Keyed_Caches;

package body RCL.Services.Typed is

   use Ada.Real_Time;
   use type ROSIDL.UInt64;
   use type ROSIDL.Int64;

   package Requests renames Handling.Request_Handling;
   package Responses renames Handling.Response_Handling;

   procedure Register_Hashes is
   --  For the endpoints' USER_DATA (Jazzy), also when the service's type
   --  is not on the interface search path.
   begin
      ROSIDL.Type_Hashes.Register (Requests.DDS_Type_Name, Requests.Type_Hash);
      ROSIDL.Type_Hashes.Register (Responses.DDS_Type_Name, Responses.Type_Hash);
   end Register_Hashes;

   Slice : constant Duration := 0.1;
   --  Longest single wait for a reply (shutdown is checked in between).

   use RCL.Client_Endpoints;
   --  Deadline_Of, Seconds_Image, Await_Service...

   ------------
   -- Client --
   ------------

   procedure Init
     (This : in out Client;
      Node : RCL.Nodes.Node'Class;
      Name : String;
      QoS  : RCL.QoS.Profile := RCL.QoS.Services_Default)
   is
   begin
      Register_Hashes;
      RCL.Client_Endpoints.Open
        (This.Ends, Node, Name, Requests.DDS_Type_Name, Responses.DDS_Type_Name, QoS);
   end Init;

   function Is_Open (This : Client) return Boolean is (This.Ends.Is_Open);

   function Service_Name (This : Client) return String is
     (RCL.Client_Endpoints.Service_Name (This.Ends));

   function Service_Available (This : Client) return Boolean is
     (RCL.Client_Endpoints.Service_Available (This.Ends));

   procedure Wait_For_Service (This : Client; Timeout : Duration := Forever) is
   begin
      RCL.Client_Endpoints.Await_Service (This.Ends, Deadline_Of (Timeout), Timeout);
   end Wait_For_Service;

   procedure Read_Header
     (Data : RCL.DDS.Byte_Array; GUID : out ROSIDL.UInt64; Sequence : out ROSIDL.Int64)
   --  The request header of a reply (Decode_Error when cut short).
   is
      Header : constant ROSIDL.CDR.Request_Header :=
        ROSIDL.CDR.Request_Header_Of (Data, Responses.Full_Name);
   begin
      GUID := Header.GUID;
      Sequence := Header.Sequence;
   end Read_Header;

   procedure Take_Reply
     (This    : in out Client;
      Process : not null access procedure
        (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info);
      Taken   : out Boolean)
   --  Takes one reply (Taken) and runs Process on it; a malformed one
   --  (Decode_Error from Process) is logged and skipped.
   is
   begin
      RCL.DDS.Take (This.Ends.Replies, Process, Taken);
   exception
      when E : ROSIDL.Decode_Error =>
         RCL.Logging.Warn ("service " & This.Service_Name & ": malformed reply dropped: "
                           & Ada.Exceptions.Exception_Message (E));
         Taken := True;
   end Take_Reply;

   --------------------------
   -- Asynchronous replies --
   --------------------------

   procedure Run_Async (This : in out Client; Data : RCL.DDS.Byte_Array; Sequence : ROSIDL.Int64)
   --  Runs the callback of the asynchronous call Sequence with the reply
   --  Data (this client's); nothing if the call is unknown (late after its
   --  timeout, duplicate). Decode_Error (the call stays pending) when
   --  Data is malformed.
   is
      Resp   : Response;
      Header : ROSIDL.CDR.Request_Header;
   begin
      if Async_Calls.Is_Pending (This.Asyncs, Sequence) then
         Responses.Decode (Data, Resp, Header);
         Async_Calls.Complete (This.Asyncs, Sequence, Resp);
      end if;
   end Run_Async;

   procedure Take_Replies (This : in out Client; Taken : out Natural) is
   --  Reads the replies there are, running asynchronous callbacks (with
   --  This.Lock held); malformed replies are logged and skipped.
      Got : Boolean;

      procedure Process (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info) is
         pragma Unreferenced (Info);
         GUID : ROSIDL.UInt64;
         Seq  : ROSIDL.Int64;
      begin
         Read_Header (Data, GUID, Seq);
         if GUID = This.Ends.Handle then
            Run_Async (This, Data, Seq);
         end if;
      end Process;

   begin
      Taken := 0;
      loop
         Take_Reply (This, Process'Access, Got);
         exit when not Got;
         Taken := Taken + 1;
      end loop;
   end Take_Replies;

   Pump_Slice : constant Duration := 0.02;
   --  Longest wait of the pumping task with the client's lock held (a
   --  synchronous Call waits at most this long for the lock).

   procedure Read_Replies (This : Client_Ref) is
      procedure Read is
         Taken : Natural;
         Ready : RCL.DDS.Key_Array (1 .. 1);
         Last  : Natural;
      begin
         Take_Replies (This.all, Taken);
         if Taken = 0 then
            RCL.DDS.Wait (This.Ends.Waiting, Pump_Slice, Ready, Last);
            Take_Replies (This.all, Taken);
         end if;
      end Read;
   begin
      ROSIDL.Mutexes.Run_Locked (This.Lock, Read'Access);
   end Read_Replies;

   function Service_Name (This : Client_Ref) return String is (Service_Name (This.all));

   procedure Exchange
     (This     : in out Client;
      Req      : Request;
      Resp     : in out Response;
      Timeout  : Duration;
      Deadline : Time)
   --  Call, with This.Lock held.
   is
      Sequence : ROSIDL.Int64;
      Done     : Boolean := False;
      Taken    : Boolean;
      Ready    : RCL.DDS.Key_Array (1 .. 1);
      Last     : Natural;

      procedure Fill
        (Buffer : out RCL.DDS.Byte_Array; Last : out Ada.Streams.Stream_Element_Offset) is
      begin
         Requests.Encode (Req, (GUID => This.Ends.Handle, Sequence => Sequence), Buffer, Last);
      end Fill;

      procedure Process (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info) is
         pragma Unreferenced (Info);
         GUID   : ROSIDL.UInt64;
         Seq    : ROSIDL.Int64;
         Header : ROSIDL.CDR.Request_Header;
      begin
         Read_Header (Data, GUID, Seq);
         if GUID = This.Ends.Handle and then Seq = Sequence then
            Responses.Decode (Data, Resp, Header);
            Done := True;
         elsif GUID = This.Ends.Handle then
            Run_Async (This, Data, Seq);
         end if;
         --  Replies to other clients of this topic, and late replies to
         --  calls that timed out, are dropped.
      end Process;

   begin
      if not This.Available then
         RCL.Client_Endpoints.Await_Service (This.Ends, Deadline, Timeout);
         This.Available := True;
      end if;
      Sequence := RCL.Pending_Calls.Next_Sequence;
      RCL.DDS.Write_Filled
        (This.Ends.Requests, Requests.Encoded_Size (Req, With_Request_Header => True),
         Fill'Access);
      loop
         loop
            Take_Reply (This, Process'Access, Taken);
            exit when Done or else not Taken;
         end loop;
         exit when Done;
         if RCL.Contexts.Is_Shutdown then
            raise ROS_Exception with "shut down while waiting for service "
              & This.Service_Name;
         elsif Clock >= Deadline then
            This.Available := False;
            raise RCL_Timeout with "no response from service " & This.Service_Name
              & " after" & Seconds_Image (Timeout);
         end if;
         RCL.DDS.Wait (This.Ends.Waiting, Duration'Min (Slice, To_Duration (Deadline - Clock)),
                       Ready, Last);
      end loop;
   end Exchange;

   procedure Call
     (This    : in out Client;
      Req     : Request;
      Resp    : in out Response;
      Timeout : Duration := Forever)
   is
      Deadline : constant Time := Deadline_Of (Timeout);

      procedure Call_Locked is
      begin
         Exchange (This, Req, Resp, Timeout, Deadline);
      end Call_Locked;
   begin
      Async_Calls.Check_Not_In_Callback (This.Asyncs);
      ROSIDL.Mutexes.Run_Locked (This.Lock, Call_Locked'Access);
   end Call;

   function Call
     (This    : in out Client;
      Req     : Request;
      Timeout : Duration := Forever) return Response is
   begin
      return Resp : Response do
         This.Call (Req, Resp, Timeout);
      end return;
   end Call;

   ----------------
   -- Call_Async --
   ----------------

   procedure Call_Async
     (This     : in out Client;
      Req      : Request;
      Callback : not null Response_Callback;
      Timeout  : Duration := 60.0)
   is
      procedure Send (Sequence : ROSIDL.Int64) is
         procedure Fill
           (Buffer : out RCL.DDS.Byte_Array; Last : out Ada.Streams.Stream_Element_Offset) is
         begin
            Requests.Encode (Req, (GUID => This.Ends.Handle, Sequence => Sequence), Buffer, Last);
         end Fill;
      begin
         RCL.DDS.Write_Filled
           (This.Ends.Requests, Requests.Encoded_Size (Req, With_Request_Header => True),
            Fill'Access);
      end Send;
   begin
      Async_Calls.Call (This.Asyncs, This'Unchecked_Access, Callback, Timeout, Send'Access);
   end Call_Async;

   function Pending_Async (This : Client) return Natural is (Async_Calls.Count (This.Asyncs));

   overriding procedure Finalize (This : in out Client) is
   begin
      Async_Calls.Stop (This.Asyncs);
      Close (This.Ends);
   end Finalize;

   ------------------------
   -- Per-node clients --
   ------------------------

   type Client_Access is access Client;

   package Client_Caches is new RCL.Keyed_Caches (Client, Client_Access);

   function Call
     (Node    : RCL.Nodes.Node'Class;
      Name    : String;
      Req     : Request;
      Timeout : Duration := Forever) return Response
   is
      procedure Init (Made : in out Client) is
      begin
         Made.Init (Node, Name);
      end Init;
   begin
      return Client_Caches.Find_Or_Make
        (Node.Fully_Qualified_Name & " " & Node.Expand_Service (Name), Init'Access).Call
           (Req, Timeout);
   end Call;

   ------------
   -- Server --
   ------------

   package body Server is

      procedure Answer
        (Server : in out RCL.Services.Server'Class;
         Node   : in out RCL.Nodes.Node'Class;
         Data   : RCL.DDS.Byte_Array;
         Info   : ROSIDL.Message_Info)
      is
         Req    : Request;
         Resp   : Response;
         Header : ROSIDL.CDR.Request_Header;

         procedure Fill
           (Buffer : out RCL.DDS.Byte_Array; Last : out Ada.Streams.Stream_Element_Offset) is
         begin
            Responses.Encode (Resp, Header, Buffer, Last);
         end Fill;

      begin
         Requests.Decode (Data, Req, Header);
         --  (A Decode_Error is logged with the service name by the
         --  executor, and the request dropped.)
         Callback (Node, Req, Resp);
         RCL.Services.Respond_Filled
           (Server, RCL.DDS.GUID (Info.Publisher_GID),
            Responses.Encoded_Size (Resp, With_Request_Header => True), Fill'Access);
      end Answer;

      procedure Serve
        (Node : in out RCL.Nodes.Node'Class;
         Name : String;
         QoS  : RCL.QoS.Profile := RCL.QoS.Services_Default) is
      begin
         Register_Hashes;
         RCL.Services.Open_Raw (Node, Requests.DDS_Type_Name, Responses.DDS_Type_Name,
                                Name, Answer'Access, QoS);
      end Serve;

   end Server;

end RCL.Services.Typed;
