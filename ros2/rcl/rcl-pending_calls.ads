--  The pairing of service requests and replies of one client
--  (RCL.Clients; a private child of RCL: internal to the library). Each
--  request gets a process-wide sequence number; the reply carrying it is
--  handed to the task waiting for it (synchronous call) or returned with
--  its callback (asynchronous call). A reply whose sequence number is
--  unknown (late after a timeout, duplicate, someone else's) is reported
--  and dropped. One task at a time reads the reply reader (the "leader");
--  the others wait on their own slot.
with Ada.Real_Time;
with Interfaces;
with ROSIDL.Dynamic;

private with Ada.Containers.Ordered_Maps;

private package RCL.Pending_Calls is

   type Response_Callback is access procedure (Response : ROSIDL.Dynamic.Message);
   --  What an asynchronous call runs with its response (the same profile
   --  as RCL.Clients.Response_Callback, which converts to it).

   function Next_Sequence return ROSIDL.Int64;
   --  1, 2, 3... for the whole process (as rmw_cyclonedds).

   protected type Slot is
      entry Wait;
      --  Returns once Fill has been called.
      procedure Fill (Response : ROSIDL.Dynamic.Message);
      function Filled return Boolean;
      function Response return ROSIDL.Dynamic.Message;
   private
      Is_Filled : Boolean := False;
      Stored    : ROSIDL.Dynamic.Message;
   end Slot;

   type Slot_Access is access Slot;

   type Outcome is (Delivered, Run_Callback, Unknown_Sequence);

   type Call_Map is private;

   protected type Table is

      procedure Add_Sync (Sequence : ROSIDL.Int64; Into : not null Slot_Access);
      --  A synchronous call waiting on Into.

      procedure Add_Async
        (Sequence      : ROSIDL.Int64;
         Callback      : not null Response_Callback;
         Deadline      : Ada.Real_Time.Time;
         Start_Pumping : out Boolean);
      --  Start_Pumping: no task is pumping replies for asynchronous calls;
      --  the caller must start one (which ends through Pumping_Done).

      procedure Remove (Sequence : ROSIDL.Int64);
      --  Forgets a call (after its timeout); no effect when unknown.

      procedure Deliver
        (Sequence : ROSIDL.Int64;
         Response : ROSIDL.Dynamic.Message;
         Result   : out Outcome;
         Callback : out Response_Callback);
      --  Fills the slot of a synchronous call (Delivered) or returns the
      --  callback of an asynchronous one (Run_Callback, Callback set); the
      --  call is forgotten in both cases.

      procedure Expire (Now : Ada.Real_Time.Time; Expired : out Natural);
      --  Forgets the asynchronous calls whose deadline is before Now.

      procedure Pumping_Done (Done : out Boolean);
      --  Done (and no pumping task any more) when no asynchronous call is
      --  pending or Stop was called.

      procedure Stop;
      --  Pumping_Done returns True from now on.

      function Async_Count return Natural;
      function Count return Natural;

      procedure Try_Lead (Got : out Boolean);
      --  Becomes the task reading replies, unless another task is.
      procedure Release;

   private
      Calls    : Call_Map;
      Asyncs   : Natural := 0;
      Leading  : Boolean := False;
      Pumping  : Boolean := False;
      Stopping : Boolean := False;
   end Table;

private

   type Pending_Call is record
      Into     : Slot_Access;
      Callback : Response_Callback;
      Deadline : Ada.Real_Time.Time;
   end record;

   package Maps is new Ada.Containers.Ordered_Maps
     (ROSIDL.Int64, Pending_Call, Interfaces."<");

   type Call_Map is new Maps.Map with null record;

end RCL.Pending_Calls;
