with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with RCL.DDS;
with ROSIDL.CDR;
with RCL.Contexts;
with RCL.Logging;
with RCL.Keyed_Caches;

package body RCL.Clients is

   use type RCL.Pending_Calls.Slot_Access;

   use Ada.Real_Time;
   use type ROSIDL.UInt64;
   use type RCL.Pending_Calls.Outcome;

   Slice : constant Duration := 0.05;
   --  Longest single wait of the task reading replies.

   function Earliest (A, B : Time) return Time is (if A < B then A else B);

   use RCL.Client_Endpoints;
   --  Deadline_Of, Seconds_Image, Await_Service...

   ----------
   -- Init --
   ----------

   procedure Init
     (This    : in out Client;
      Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      QoS     : RCL.QoS.Profile := RCL.QoS.Services_Default)
   is
      use ROSIDL.Typesupport;
   begin
      This.Support := Support;
      RCL.Client_Endpoints.Open
        (This.Ends, Node, Name, DDS_Type_Name (Request_Support (Support)),
         DDS_Type_Name (Response_Support (Support)), QoS);
   end Init;

   function Is_Open (This : Client) return Boolean is (This.Ends.Is_Open);

   function Service_Name (This : Client) return String is
     (RCL.Client_Endpoints.Service_Name (This.Ends));

   function Service_Available (This : Client) return Boolean is
     (RCL.Client_Endpoints.Service_Available (This.Ends));

   function Wait_For_Service (This : Client; Timeout : Duration := Forever) return Boolean is
     (RCL.Client_Endpoints.Available_Before (This.Ends, Deadline_Of (Timeout)));

   procedure Wait_For_Service (This : Client; Timeout : Duration := Forever) is
   begin
      RCL.Client_Endpoints.Await_Service (This.Ends, Deadline_Of (Timeout), Timeout);
   end Wait_For_Service;

   -----------------
   -- Take_Replies --
   -----------------

   procedure Take_Replies (This : in out Client; Taken : out Natural) is
      --  Takes every reply available and hands it to its call. Whose reply
      --  it is comes first (the header): replies to the other clients of
      --  this topic are dropped undecoded, so that a malformed one is not
      --  reported here.
      use ROSIDL.Typesupport;
      Info : RCL.DDS.Sample_Info;
   begin
      Taken := 0;
      loop
         declare
            Data : constant RCL.DDS.Byte_Array := RCL.DDS.Take (This.Ends.Replies, Info);
         begin
            exit when Data'Length = 0;
            Taken := Taken + 1;
            if ROSIDL.CDR.Request_Header_Of
                 (Data, Full_Name (Response_Support (This.Support))).GUID = This.Ends.Handle
            then
               declare
                  Response : ROSIDL.Dynamic.Message :=
                    ROSIDL.Dynamic.Init (Response_Support (This.Support));
                  Header   : ROSIDL.CDR.Request_Header;
                  Result   : RCL.Pending_Calls.Outcome;
               begin
                  ROSIDL.CDR.Decode (Data, Response, Header);
                  This.Calls.Deliver (Header.Sequence, Response, Result);
                  if Result = RCL.Pending_Calls.Unknown_Sequence then
                     Async_Calls.Complete (This.Asyncs, Header.Sequence, Response);
                  end if;
               end;
            end if;
            --  Late replies (Unknown_Sequence) are dropped.
         exception
            when E : ROSIDL.Decode_Error =>
               RCL.Logging.Warn ("service " & This.Service_Name
                                 & ": malformed reply dropped: "
                                 & Ada.Exceptions.Exception_Message (E));
         end;
      end loop;
   end Take_Replies;

   procedure Pump_Once (This : in out Client; Until_Time : Time) is
      --  Reads replies, waiting for them until Until_Time (at most Slice).
      Ready : RCL.DDS.Key_Array (1 .. 1);
      Last  : Natural;
      Taken : Natural;
   begin
      Take_Replies (This, Taken);
      if Taken = 0 then
         RCL.DDS.Wait (This.Ends.Waiting,
                       Duration'Min (Slice, To_Duration (Until_Time - Clock)), Ready, Last);
         Take_Replies (This, Taken);
      end if;
   end Pump_Once;

   procedure Read_Or_Wait
     (This : in out Client; Until_Time : Time; Into : RCL.Pending_Calls.Slot_Access)
   is
      --  Reads replies until Until_Time (at most Slice) unless another task
      --  is reading them; then waits for Into's response (if Into is not
      --  null) at most 2 ms.
      Got : Boolean;
   begin
      This.Calls.Try_Lead (Got);
      if Got then
         begin
            Pump_Once (This, Until_Time);
         exception
            when others =>
               This.Calls.Release;
               raise;
         end;
         This.Calls.Release;
      elsif Into = null then
         delay until Earliest (Until_Time, Clock + Milliseconds (2));
      else
         select
            Into.Wait;
         or
            delay until Earliest (Until_Time, Clock + Milliseconds (2));
         end select;
      end if;
   end Read_Or_Wait;

   procedure Read_Replies (This : Client_Ref) is
   begin
      Read_Or_Wait (This.all, Clock + To_Time_Span (Slice), Into => null);
   end Read_Replies;

   function Service_Name (This : Client_Ref) return String is (Service_Name (This.all));

   ----------
   -- Send --
   ----------

   procedure Send
     (This : in out Client; Request : ROSIDL.Dynamic.Message; Sequence : ROSIDL.Int64)
   is
      use ROSIDL.Typesupport;
   begin
      if ROSIDL.Dynamic.Type_Name (Request)
        /= Full_Name (Request_Support (This.Support))
      then
         raise ROS_Exception with "service " & This.Service_Name & " takes "
           & Full_Name (Request_Support (This.Support)) & " requests, not "
           & ROSIDL.Dynamic.Type_Name (Request);
      end if;
      RCL.DDS.Write (This.Ends.Requests,
                     ROSIDL.CDR.Encode (Request, (GUID => This.Ends.Handle, Sequence => Sequence)));
   end Send;

   ----------
   -- Call --
   ----------

   procedure Free is new Ada.Unchecked_Deallocation
     (RCL.Pending_Calls.Slot, RCL.Pending_Calls.Slot_Access);

   function Call
     (This    : in out Client;
      Request : ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever) return ROSIDL.Dynamic.Message
   is
      Deadline : constant Time := Deadline_Of (Timeout);
      Sequence : constant ROSIDL.Int64 := RCL.Pending_Calls.Next_Sequence;
      Into     : RCL.Pending_Calls.Slot_Access;
   begin
      Async_Calls.Check_Not_In_Callback (This.Asyncs);
      RCL.Client_Endpoints.Await_Service (This.Ends, Deadline, Timeout);
      Into := new RCL.Pending_Calls.Slot;
      This.Calls.Add_Sync (Sequence, Into);
      begin
         Send (This, Request, Sequence);
         while not Into.Filled loop
            if RCL.Contexts.Is_Shutdown then
               raise ROS_Exception with "shut down while waiting for service "
                 & This.Service_Name;
            elsif Clock >= Deadline then
               raise RCL_Timeout with "no response from service " & This.Service_Name
                 & " after" & Seconds_Image (Timeout);
            end if;
            Read_Or_Wait (This, Deadline, Into);
         end loop;
      exception
         when others =>
            This.Calls.Remove (Sequence);
            Free (Into);
            raise;
      end;
      return Response : constant ROSIDL.Dynamic.Message := Into.Response do
         Free (Into);
      end return;
   end Call;

   ----------------
   -- Call_Async --
   ----------------

   procedure Call_Async
     (This     : in out Client;
      Request  : ROSIDL.Dynamic.Message;
      Callback : not null Response_Callback;
      Timeout  : Duration := 60.0)
   is
      procedure Send_Request (Sequence : ROSIDL.Int64) is
      begin
         Send (This, Request, Sequence);
      end Send_Request;
   begin
      Async_Calls.Call (This.Asyncs, This'Unchecked_Access, Callback, Timeout,
                        Send_Request'Access);
   end Call_Async;

   function Pending_Async (This : Client) return Natural is (Async_Calls.Count (This.Asyncs));

   function Pending_Calls (This : Client) return Natural is
     (This.Calls.Count + Async_Calls.Count (This.Asyncs));

   -------------
   -- Futures --
   -------------

   procedure Call_Future
     (This    : in out Client;
      Request : ROSIDL.Dynamic.Message;
      Into    : in out Future)
   is
      Sequence : constant ROSIDL.Int64 := RCL.Pending_Calls.Next_Sequence;
   begin
      Into.Call.Into := new RCL.Pending_Calls.Slot;
      Into.Call.Owner := This'Unchecked_Access;
      Into.Call.Sequence := Sequence;
      This.Calls.Add_Sync (Sequence, Into.Call.Into);
      Send (This, Request, Sequence);
   exception
      when others =>
         This.Calls.Remove (Sequence);
         Free (Into.Call.Into);
         Into.Call.Owner := null;
         raise;
   end Call_Future;

   function Is_Pending (F : Future) return Boolean is (F.Call.Into /= null);

   function Is_Ready (F : Future) return Boolean is
     (F.Call.Into /= null and then F.Call.Into.Filled);

   function Response (F : Future) return ROSIDL.Dynamic.Message is (F.Call.Into.Response);

   function Read_Replies (F : in out Future; Until_Time : Time) return Boolean is
      --  Reads replies (or waits for the task reading them) until F is
      --  ready or Until_Time: True when ready.
   begin
      Async_Calls.Check_Not_In_Callback (F.Call.Owner.Asyncs);
      loop
         if F.Call.Into.Filled then
            return True;
         elsif Clock >= Until_Time then
            return False;
         end if;
         Read_Or_Wait (F.Call.Owner.all, Until_Time, F.Call.Into);
      end loop;
   end Read_Replies;

   function Wait (F : in out Future; Timeout : Duration := Forever) return Future_Return_Code is
      Deadline : constant Time := Deadline_Of (Timeout);
   begin
      loop
         if RCL.Contexts.Is_Shutdown then
            return Interrupted;
         elsif Read_Replies (F, Earliest (Deadline, Clock + Milliseconds (100))) then
            return Success;
         elsif Clock >= Deadline then
            return Timed_Out;
         end if;
      end loop;
   end Wait;

   function Spin_Until_Complete
     (Node    : in out RCL.Nodes.Node'Class;
      F       : in out Future;
      Timeout : Duration := Forever) return Future_Return_Code
   is
      Deadline : constant Time := Deadline_Of (Timeout);
   begin
      loop
         if Read_Replies (F, Clock) then
            return Success;
         elsif RCL.Contexts.Is_Shutdown then
            return Interrupted;
         elsif Clock >= Deadline then
            return Timed_Out;
         end if;
         Node.Spin (During => (if Deadline = Time_Last then 0.01
                               else Duration'Max
                                 (0.0, Duration'Min (0.01, To_Duration (Deadline - Clock)))));
         if Read_Replies (F, Earliest (Deadline, Clock + Milliseconds (10))) then
            return Success;
         end if;
      end loop;
   end Spin_Until_Complete;

   overriding procedure Finalize (This : in out Future_Call) is
   begin
      if This.Into /= null then
         if This.Owner /= null then
            This.Owner.Calls.Remove (This.Sequence);
         end if;
         Free (This.Into);
      end if;
      This.Owner := null;
   exception
      when others =>
         null;
   end Finalize;

   --------------
   -- Finalize --
   --------------

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

   function Client_For
     (Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String) return Client_Access
   is
      procedure Init (Made : in out Client) is
      begin
         Made.Init (Node, Support, Name);
      end Init;
   begin
      return Client_Caches.Find_Or_Make
        (Node.Fully_Qualified_Name & " " & Node.Expand_Service (Name) & " "
         & ROSIDL.Typesupport.Full_Name (Support), Init'Access);
   end Client_For;

   function Call
     (Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      Request : ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever) return ROSIDL.Dynamic.Message
   is
      C : constant Client_Access := Client_For (Node, Support, Name);
   begin
      return C.Call (Request, Timeout);
   end Call;

   procedure Wait_For_Service
     (Node    : RCL.Nodes.Node'Class;
      Support : ROSIDL.Typesupport.Service_Support;
      Name    : String;
      Timeout : Duration := Forever)
   is
      C : constant Client_Access := Client_For (Node, Support, Name);
   begin
      C.Wait_For_Service (Timeout);
   end Wait_For_Service;

end RCL.Clients;
