package body RCL.Pending_Calls is

   use type Ada.Real_Time.Time;
   use type ROSIDL.Int64;

   protected Sequences is
      procedure Next (Value : out ROSIDL.Int64);
   private
      Last : ROSIDL.Int64 := 0;
   end Sequences;

   protected body Sequences is
      procedure Next (Value : out ROSIDL.Int64) is
      begin
         Last := Last + 1;
         Value := Last;
      end Next;
   end Sequences;

   function Next_Sequence return ROSIDL.Int64 is
      Value : ROSIDL.Int64;
   begin
      Sequences.Next (Value);
      return Value;
   end Next_Sequence;

   protected body Slot is

      entry Wait when Is_Filled is
      begin
         null;
      end Wait;

      procedure Fill (Response : ROSIDL.Dynamic.Message) is
      begin
         Stored := Response;
         Is_Filled := True;
      end Fill;

      function Filled return Boolean is (Is_Filled);

      function Response return ROSIDL.Dynamic.Message is (Stored);

   end Slot;

   protected body Table is

      procedure Add_Sync (Sequence : ROSIDL.Int64; Into : not null Slot_Access) is
      begin
         Calls.Include (Sequence, (Into => Into, Callback => null,
                                   Deadline => Ada.Real_Time.Time_Last));
      end Add_Sync;

      procedure Add_Async
        (Sequence      : ROSIDL.Int64;
         Callback      : not null Response_Callback;
         Deadline      : Ada.Real_Time.Time;
         Start_Pumping : out Boolean) is
      begin
         Calls.Include (Sequence, (Into => null, Callback => Callback, Deadline => Deadline));
         Asyncs := Asyncs + 1;
         Start_Pumping := not Pumping and not Stopping;
         Pumping := Pumping or Start_Pumping;
      end Add_Async;

      procedure Remove (Sequence : ROSIDL.Int64) is
         Position : Maps.Cursor := Calls.Find (Sequence);
      begin
         if Maps.Has_Element (Position) then
            if Maps.Element (Position).Callback /= null then
               Asyncs := Asyncs - 1;
            end if;
            Calls.Delete (Position);
         end if;
      end Remove;

      procedure Deliver
        (Sequence : ROSIDL.Int64;
         Response : ROSIDL.Dynamic.Message;
         Result   : out Outcome;
         Callback : out Response_Callback)
      is
         Position : Maps.Cursor := Calls.Find (Sequence);
      begin
         Callback := null;
         if not Maps.Has_Element (Position) then
            Result := Unknown_Sequence;
            return;
         end if;
         declare
            Call : constant Pending_Call := Maps.Element (Position);
         begin
            Calls.Delete (Position);
            if Call.Callback /= null then
               Asyncs := Asyncs - 1;
               Callback := Call.Callback;
               Result := Run_Callback;
            else
               Call.Into.Fill (Response);
               Result := Delivered;
            end if;
         end;
      end Deliver;

      procedure Expire (Now : Ada.Real_Time.Time; Expired : out Natural) is
         Position : Maps.Cursor := Calls.First;
         Next     : Maps.Cursor;
      begin
         Expired := 0;
         while Maps.Has_Element (Position) loop
            Next := Maps.Next (Position);
            if Maps.Element (Position).Callback /= null
              and then Maps.Element (Position).Deadline < Now
            then
               Calls.Delete (Position);
               Asyncs := Asyncs - 1;
               Expired := Expired + 1;
            end if;
            Position := Next;
         end loop;
      end Expire;

      procedure Pumping_Done (Done : out Boolean) is
      begin
         Done := Asyncs = 0 or Stopping;
         if Done then
            Pumping := False;
         end if;
      end Pumping_Done;

      procedure Stop is
      begin
         Stopping := True;
      end Stop;

      function Async_Count return Natural is (Asyncs);
      function Count return Natural is (Natural (Calls.Length));

      procedure Try_Lead (Got : out Boolean) is
      begin
         Got := not Leading;
         Leading := True;
      end Try_Lead;

      procedure Release is
      begin
         Leading := False;
      end Release;

   end Table;

end RCL.Pending_Calls;
