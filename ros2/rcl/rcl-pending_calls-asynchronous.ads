--  The asynchronous calls of one service client, for RCL.Clients (dynamic
--  messages) and RCL.Services.Typed (generated records): the calls still
--  waiting for their response (sequence number -> callback, deadline),
--  and the task that reads the client's replies while any is pending (the
--  "pump": started by the first pending call, ending when none is).
--  Generic over what a completed call delivers (Response) and over the
--  client, which reads its own replies (Read_Replies) and hands those of
--  asynchronous calls to Complete.
--
--  Rules kept for both clients: a callback runs in the pump or in a
--  synchronous call of the same client that reads the reply (Complete
--  runs it in the calling task), never in the node's executor; an
--  exception in it is logged; a call not answered by its deadline is
--  forgotten with a warning (`N asynchronous call(s) of service S got no
--  response in time`); after the context shuts down, or when the client
--  stops the pump (Stop, from its Finalize), the pending calls are dropped
--  with a warning and the pump ends. A callback must not make a
--  synchronous call of its own client (Check_Not_In_Callback).
--  How a client uses it: Call_Async adds the call (Add) and then sends
--  the request; every reply of the client that is not a synchronous
--  call's goes to Complete; Finalize stops the pump (Stop) before closing
--  the replies reader; a synchronous call first checks that it is not
--  made from a callback of the same client (Check_Not_In_Callback).
private with Ada.Containers.Ordered_Maps;
private with Ada.Real_Time;
private with Ada.Task_Identification;

generic
   type Response (<>) is limited private;
   type Response_Callback is access procedure (Resp : Response);
   type Client_Ref is private;
   --  Designates the client (its pump reads through it).
   with procedure Read_Replies (Client : Client_Ref);
   --  Reads the client's replies there are, waiting a short while (tens
   --  of milliseconds) for some; those of asynchronous calls go to
   --  Complete. An exception is logged by the pump, which goes on.
   with function Service_Name (Client : Client_Ref) return String;
package RCL.Pending_Calls.Asynchronous is

   type Calls is tagged limited private;
   --  Must be stopped (Stop) before the client's replies reader closes.

   procedure Add
     (This     : in out Calls;
      Client   : Client_Ref;
      Sequence : ROSIDL.Int64;
      Callback : not null Response_Callback;
      Timeout  : Duration);
   --  A call whose request is about to be sent (Remove it if sending
   --  fails); starts the pump if none runs. Timeout >= 1.0E6: never
   --  forgotten.

   procedure Call
     (This     : in out Calls;
      Client   : Client_Ref;
      Callback : not null Response_Callback;
      Timeout  : Duration;
      Send     : not null access procedure (Sequence : ROSIDL.Int64));
   --  A client's Call_Async: a new sequence number (Next_Sequence), the
   --  call added (Add), then Send (Sequence) sends the request; the call is
   --  forgotten if Send raises (the exception propagates).

   procedure Remove (This : in out Calls; Sequence : ROSIDL.Int64);
   --  Forgets a call; no effect when unknown.

   function Is_Pending (This : Calls; Sequence : ROSIDL.Int64) return Boolean;
   --  Whether a reply with this sequence number has a callback to run (a
   --  reply that has none need not be decoded).

   procedure Complete (This : in out Calls; Sequence : ROSIDL.Int64; Resp : Response);
   --  Forgets call Sequence and runs its callback with Resp in the
   --  calling task (an exception is logged); nothing when the call is
   --  unknown (answered already, forgotten after its timeout, or a
   --  synchronous call's).

   function Count (This : Calls) return Natural;
   --  The asynchronous calls still waiting for their response.

   function In_Callback (This : Calls) return Boolean;
   --  The calling task runs a callback of these calls.

   procedure Check_Not_In_Callback (This : Calls);
   --  ROS_Exception when In_Callback (a synchronous call of the client
   --  from its own callback would wait for itself: the callback holds the
   --  client's reading). Allocates nothing.

   procedure Stop (This : in out Calls);
   --  Drops the pending calls (a warning says how many) and waits for the
   --  pump's end (for the client's Finalize: never raises); Add starts no
   --  pump afterwards. From a callback of these calls (a client finalized
   --  by its own callback) it does not wait: the pump would wait for itself.

private

   type Pending_Call is record
      Callback : Response_Callback;
      Deadline : Ada.Real_Time.Time;
   end record;

   package Call_Maps is new Ada.Containers.Ordered_Maps
     (ROSIDL.Int64, Pending_Call, Interfaces."<");

   protected type Table is

      procedure Add
        (Sequence   : ROSIDL.Int64;
         Call       : Pending_Call;
         Client     : Client_Ref;
         Start_Pump : out Boolean);
      --  Start_Pump: no pump runs; the caller must start one (which
      --  reads through Client and ends through Pumping_Done). Client is
      --  the same for every call.

      procedure Take (Sequence : ROSIDL.Int64; Callback : out Response_Callback);
      --  The callback of call Sequence, forgotten; null if unknown.

      procedure Remove (Sequence : ROSIDL.Int64);

      procedure Expire (Now : Ada.Real_Time.Time; Expired : out Natural);
      --  Forgets the calls whose deadline is before Now.

      procedure Drop_All (Dropped : out Natural);

      procedure Pumping_Done (Done : out Boolean);
      --  Done (and no pump any more) when no call is pending or Stop was
      --  called. The pump's last use of the table: it touches nothing of
      --  its client afterwards.

      entry Await_Pump_End;
      --  Returns when no pump runs.

      procedure Stop;
      --  Add starts no pump from now on; Pumping_Done says Done.

      procedure Set_Callback_Task (Id : Ada.Task_Identification.Task_Id);

      function Callback_Task return Ada.Task_Identification.Task_Id;
      function Pumping_Client return Client_Ref;
      function Is_Pending (Sequence : ROSIDL.Int64) return Boolean;
      function Count return Natural;

   private
      Pending  : Call_Maps.Map;
      Client   : Client_Ref;
      Pumping  : Boolean := False;
      Stopping : Boolean := False;
      Running  : Ada.Task_Identification.Task_Id :=
        Ada.Task_Identification.Null_Task_Id;
      --  The task running a callback (one at a time: callbacks run while
      --  the client's replies are being read, by one task at a time).
   end Table;

   type Calls_Access is access all Calls;

   task type Pump is
      entry Start (Owner : not null Calls_Access);
   end Pump;
   --  Reads replies while asynchronous calls are pending. Its owner comes
   --  by an entry, not a discriminant: a discriminant is stored in the
   --  task object, which is freed at once (below).

   type Pump_Access is access Pump;
   --  A pump is freed as soon as it is started: GNAT frees its control
   --  block when it terminates. No pointer to it is kept: when the
   --  access type's master (the scope of the instance) completes before
   --  the client is finalized, the runtime frees the ended pumps, and a
   --  kept pointer would dangle. Stop waits for the pump's end through
   --  the table (Await_Pump_End), not through Pump'Terminated.

   type Calls is tagged limited record
      State : Table;
   end record;

end RCL.Pending_Calls.Asynchronous;
