with Ada.Exceptions;
with Ada.Streams;
with ROSIDL.CDR;
with ROSIDL.Static.Impl.Wire;
with ROSIDL.Type_Hashes;
with RCL.Client_Endpoints;
with RCL.Contexts;
with RCL.DDS.Matching;
with RCL.Logging;
with RCL.Node_Entities;
with RCL.Pending_Calls;
with RCL.Keyed_Caches;
with RCL.Process_Context;

package body RCL.Services.Typed is

   use Ada.Real_Time;
   use Ada.Strings.Unbounded;
   use type Ada.Streams.Stream_Element_Offset;
   use type ROSIDL.UInt64;
   use type ROSIDL.Int64;
   use type ROSIDL.CDR.Byte_Order;

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

   function Deadline_Of (Timeout : Duration) return Time is
     (if Timeout >= 1.0E6 then Time_Last else Clock + To_Time_Span (Timeout));

   function Seconds_Image (Timeout : Duration) return String is
     (if Timeout >= 1.0E6 then "ever" else Duration'Image (Timeout) & " s");

   ------------
   -- Client --
   ------------

   procedure Init
     (This : in out Client;
      Node : RCL.Nodes.Node'Class;
      Name : String;
      QoS  : RCL.QoS.Profile := RCL.QoS.Services_Default)
   is
      FQ : constant String := Node.Expand_Service (Name);
   begin
      Register_Hashes;
      RCL.Client_Endpoints.Open_Endpoints
        (Node, FQ, Requests.DDS_Type_Name, Responses.DDS_Type_Name, QoS,
         This.Requests, This.Replies, This.Handle);
      This.Node := RCL.Node_Entities.Graph_Id (Node);
      This.Name := To_Unbounded_String (FQ);
      RCL.DDS.Create (This.Waiting, RCL.Process_Context.Participant.all);
      RCL.DDS.Attach (This.Waiting, This.Replies, 1);
      This.Open := True;
   end Init;

   function Is_Open (This : Client) return Boolean is (This.Open);

   function Service_Name (This : Client) return String is (To_String (This.Name));

   function Service_Available (This : Client) return Boolean is
     (RCL.DDS.Matching.Service_Available (This.Requests, This.Replies));

   function Available_Before (This : Client; Deadline : Time) return Boolean is
   begin
      loop
         if This.Service_Available then
            return True;
         end if;
         exit when Clock >= Deadline or else RCL.Contexts.Is_Shutdown;
         delay until (if Deadline < Clock + Milliseconds (10) then Deadline
                      else Clock + Milliseconds (10));
      end loop;
      return This.Service_Available;
   end Available_Before;

   procedure Wait_For_Service (This : Client; Timeout : Duration := Forever) is
   begin
      if not Available_Before (This, Deadline_Of (Timeout)) then
         raise RCL_Timeout with "service " & To_String (This.Name)
           & " not available after" & Seconds_Image (Timeout);
      end if;
   end Wait_For_Service;

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
         Start : constant Ada.Streams.Stream_Element_Offset :=
           Data'First + ROSIDL.CDR.Encapsulation_Size;
         C     : ROSIDL.Static.Impl.Wire.Cursor :=
           (Pos => Start, Origin => Start,
            Swap => ROSIDL.CDR.Byte_Order_Of (Data) /= ROSIDL.CDR.Native_Order);
         GUID  : ROSIDL.UInt64;
         Seq   : ROSIDL.Int64;
      begin
         ROSIDL.Static.Impl.Wire.Get_Request_Header (Data, C, GUID, Seq, Responses.Full_Name);
         if GUID = This.Handle then
            Run_Async (This, Data, Seq);
         end if;
      end Process;

   begin
      Taken := 0;
      loop
         begin
            RCL.DDS.Take (This.Replies, Process'Access, Got);
         exception
            when E : ROSIDL.Decode_Error =>
               RCL.Logging.Warn ("service " & To_String (This.Name)
                                 & ": malformed reply dropped: "
                                 & Ada.Exceptions.Exception_Message (E));
               Got := True;
         end;
         exit when not Got;
         Taken := Taken + 1;
      end loop;
   end Take_Replies;

   Pump_Slice : constant Duration := 0.02;
   --  Longest wait of the pumping task with the client's lock held (a
   --  synchronous Call waits at most this long for the lock).

   procedure Read_Replies (This : Client_Ref) is
      Taken : Natural;
      Ready : RCL.DDS.Key_Array (1 .. 1);
      Last  : Natural;
   begin
      This.Lock.Seize;
      begin
         Take_Replies (This.all, Taken);
         if Taken = 0 then
            RCL.DDS.Wait (This.Waiting, Pump_Slice, Ready, Last);
            Take_Replies (This.all, Taken);
         end if;
      exception
         when others =>
            This.Lock.Release;
            raise;
      end;
      This.Lock.Release;
   end Read_Replies;

   function Service_Name (This : Client_Ref) return String is (To_String (This.Name));

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
         Requests.Encode (Req, (GUID => This.Handle, Sequence => Sequence), Buffer, Last);
      end Fill;

      procedure Process (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info) is
         pragma Unreferenced (Info);
         Start    : constant Ada.Streams.Stream_Element_Offset :=
           Data'First + ROSIDL.CDR.Encapsulation_Size;
         C        : ROSIDL.Static.Impl.Wire.Cursor :=
           (Pos => Start, Origin => Start,
            Swap => ROSIDL.CDR.Byte_Order_Of (Data) /= ROSIDL.CDR.Native_Order);
         GUID     : ROSIDL.UInt64;
         Seq      : ROSIDL.Int64;
         Header   : ROSIDL.CDR.Request_Header;
      begin
         ROSIDL.Static.Impl.Wire.Get_Request_Header (Data, C, GUID, Seq, Responses.Full_Name);
         if GUID = This.Handle and then Seq = Sequence then
            Responses.Decode (Data, Resp, Header);
            Done := True;
         elsif GUID = This.Handle then
            Run_Async (This, Data, Seq);
         end if;
         --  Replies to other clients of this topic, and late replies to
         --  calls that timed out, are dropped.
      end Process;

   begin
      if not This.Available then
         if not Available_Before (This, Deadline) then
            raise RCL_Timeout with "service " & To_String (This.Name)
              & " not available after" & Seconds_Image (Timeout);
         end if;
         This.Available := True;
      end if;
      Sequence := RCL.Pending_Calls.Next_Sequence;
      RCL.DDS.Write_Filled (This.Requests, Requests.Encoded_Size (Req, With_Request_Header => True),
                            Fill'Access);
      loop
         loop
            begin
               RCL.DDS.Take (This.Replies, Process'Access, Taken);
            exception
               when E : ROSIDL.Decode_Error =>
                  RCL.Logging.Warn ("service " & To_String (This.Name)
                                    & ": malformed reply dropped: "
                                    & Ada.Exceptions.Exception_Message (E));
                  Taken := True;
            end;
            exit when Done or else not Taken;
         end loop;
         exit when Done;
         if RCL.Contexts.Is_Shutdown then
            raise ROS_Exception with "shut down while waiting for service "
              & To_String (This.Name);
         elsif Clock >= Deadline then
            This.Available := False;
            raise RCL_Timeout with "no response from service " & To_String (This.Name)
              & " after" & Seconds_Image (Timeout);
         end if;
         RCL.DDS.Wait (This.Waiting, Duration'Min (Slice, To_Duration (Deadline - Clock)),
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
   begin
      Async_Calls.Check_Not_In_Callback (This.Asyncs);
      This.Lock.Seize;
      begin
         Exchange (This, Req, Resp, Timeout, Deadline);
      exception
         when others =>
            This.Lock.Release;
            raise;
      end;
      This.Lock.Release;
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
      Sequence : constant ROSIDL.Int64 := RCL.Pending_Calls.Next_Sequence;

      procedure Fill
        (Buffer : out RCL.DDS.Byte_Array; Last : out Ada.Streams.Stream_Element_Offset) is
      begin
         Requests.Encode (Req, (GUID => This.Handle, Sequence => Sequence), Buffer, Last);
      end Fill;

   begin
      Async_Calls.Add (This.Asyncs, This'Unchecked_Access, Sequence, Callback, Timeout);
      RCL.DDS.Write_Filled (This.Requests, Requests.Encoded_Size (Req, With_Request_Header => True),
                            Fill'Access);
   exception
      when others =>
         Async_Calls.Remove (This.Asyncs, Sequence);
         raise;
   end Call_Async;

   function Pending_Async (This : Client) return Natural is (Async_Calls.Count (This.Asyncs));

   overriding procedure Finalize (This : in out Client) is
   begin
      Async_Calls.Stop (This.Asyncs);
      if This.Open then
         This.Open := False;
         RCL.Client_Endpoints.Close_Endpoints (This.Node, This.Requests, This.Replies);
      end if;
   exception
      when others =>
         This.Open := False;
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
