--  The pairing of service requests and replies of one client (a private
--  child of RCL: internal to the library). Each request gets a
--  process-wide sequence number (Next_Sequence, for every client). The
--  dynamic client (RCL.Clients) hands the reply carrying it to the task
--  waiting for it (synchronous calls and futures: Table); the calls with
--  a callback of both clients are the generic child Asynchronous's. A
--  reply whose sequence number is unknown (late after a timeout,
--  duplicate, someone else's) is dropped. One task at a time reads the
--  dynamic client's reply reader (the "leader"); the others wait on their
--  own slot.
with Interfaces;
with ROSIDL.Dynamic;

private with Ada.Containers.Ordered_Maps;

private package RCL.Pending_Calls is

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

   type Outcome is (Delivered, Unknown_Sequence);

   type Call_Map is private;

   protected type Table is

      procedure Add_Sync (Sequence : ROSIDL.Int64; Into : not null Slot_Access);
      --  A synchronous call waiting on Into.

      procedure Remove (Sequence : ROSIDL.Int64);
      --  Forgets a call (after its timeout); no effect when unknown.

      procedure Deliver
        (Sequence : ROSIDL.Int64;
         Response : ROSIDL.Dynamic.Message;
         Result   : out Outcome);
      --  Fills the slot of call Sequence and forgets the call (Delivered).

      function Count return Natural;

      procedure Try_Lead (Got : out Boolean);
      --  Becomes the task reading replies, unless another task is.
      procedure Release;

   private
      Calls   : Call_Map;
      Leading : Boolean := False;
   end Table;

private

   package Maps is new Ada.Containers.Ordered_Maps
     (ROSIDL.Int64, Slot_Access, Interfaces."<");

   type Call_Map is new Maps.Map with null record;

end RCL.Pending_Calls;
