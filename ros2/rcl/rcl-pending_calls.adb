package body RCL.Pending_Calls is

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
         Calls.Include (Sequence, Into);
      end Add_Sync;

      procedure Remove (Sequence : ROSIDL.Int64) is
      begin
         Calls.Exclude (Sequence);
      end Remove;

      procedure Deliver
        (Sequence : ROSIDL.Int64;
         Response : ROSIDL.Dynamic.Message;
         Result   : out Outcome)
      is
         Position : Maps.Cursor := Calls.Find (Sequence);
      begin
         if Maps.Has_Element (Position) then
            Maps.Element (Position).Fill (Response);
            Calls.Delete (Position);
            Result := Delivered;
         else
            Result := Unknown_Sequence;
         end if;
      end Deliver;

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
