with Ada.Unchecked_Deallocation;

package body RCL.Executors.Pools is

   type Bytes_Access is access RCL.DDS.Byte_Array;
   procedure Free is new Ada.Unchecked_Deallocation (RCL.DDS.Byte_Array, Bytes_Access);

   type Work_Kind is (Sample, Tick, Stop);

   type Work (Kind : Work_Kind := Stop) is record
      Node : Node_Access;
      case Kind is
         when Sample =>
            Sub  : Subscription_Work;
            Data : Bytes_Access;
            Info : ROSIDL.Message_Info;
         when Tick =>
            Timer   : Timer_Work;
            Elapsed : Duration;
         when Stop =>
            null;
      end case;
   end record;

   type Work_Array is array (Positive range <>) of Work;

   --  Callback groups: a work item of a mutually exclusive group waits in
   --  the queue while another item of the same group (same node, same
   --  group id) is in flight; items behind it in the queue may pass it.

   type Group_Key is record
      Node      : Node_Access;
      Group     : Natural := 0;
      Exclusive : Boolean := False;
   end record;

   function Key_Of (Item : Work) return Group_Key is
     (case Item.Kind is
         when Sample => (Item.Node, Item.Sub.Group.Id, Item.Sub.Group.Exclusive),
         when Tick   => (Item.Node, Item.Timer.Group.Id, Item.Timer.Group.Exclusive),
         when Stop   => (Node => null, Group => 0, Exclusive => False));

   type Key_Array is array (Positive range <>) of Group_Key;

   protected type Work_Queue (Capacity : Positive) is
      entry Put (Item : Work);
      entry Get (Item : out Work);
      --  The first item in queue order whose group is free; it counts as
      --  in flight until Done.
      procedure Done (Item : Work);
      entry Wait_Idle;
   private
      procedure Count_Runnable;
      Items     : Work_Array (1 .. Capacity);
      Count     : Natural := 0;
      --  Items (1 .. Count), oldest first.
      Running   : Key_Array (1 .. Capacity);
      In_Flight : Natural := 0;
      --  Running (1 .. In_Flight): the groups of the items in flight.
      Runnable  : Natural := 0;
      --  Items whose group is free (the barrier of Get).
   end Work_Queue;

   protected body Work_Queue is

      function Busy (Key : Group_Key) return Boolean is
        (Key.Exclusive
         and then (for some I in 1 .. In_Flight =>
                     Running (I).Node = Key.Node and then Running (I).Group = Key.Group));

      procedure Count_Runnable is
      begin
         Runnable := 0;
         for I in 1 .. Count loop
            if not Busy (Key_Of (Items (I))) then
               Runnable := Runnable + 1;
            end if;
         end loop;
      end Count_Runnable;

      entry Put (Item : Work) when Count < Capacity is
      begin
         Count := Count + 1;
         Items (Count) := Item;
         Count_Runnable;
      end Put;

      entry Get (Item : out Work) when Runnable > 0 is
      begin
         for I in 1 .. Count loop
            if not Busy (Key_Of (Items (I))) then
               Item := Items (I);
               Items (I .. Count - 1) := Items (I + 1 .. Count);
               Count := Count - 1;
               In_Flight := In_Flight + 1;
               Running (In_Flight) := Key_Of (Item);
               exit;
            end if;
         end loop;
         Count_Runnable;
      end Get;

      procedure Done (Item : Work) is
         Key : constant Group_Key := Key_Of (Item);
      begin
         for I in 1 .. In_Flight loop
            if Running (I) = Key then
               Running (I) := Running (In_Flight);
               In_Flight := In_Flight - 1;
               exit;
            end if;
         end loop;
         Count_Runnable;
      end Done;

      entry Wait_Idle when Count = 0 and then In_Flight = 0 is
      begin
         null;
      end Wait_Idle;
   end Work_Queue;

   task type Runner (Queue : not null Queue_Access; Prio : System.Priority)
     with Priority => Prio;

   task body Runner is
      Item : Work;
   begin
      loop
         Queue.Get (Item);
         case Item.Kind is
            when Stop =>
               Queue.Done (Item);
               exit;
            when Sample =>
               Run_Subscription (Item.Node, Item.Sub, Item.Data.all, Item.Info);
               Free (Item.Data);
            when Tick =>
               Run_Timer (Item.Node, Item.Timer, Item.Elapsed);
         end case;
         Queue.Done (Item);
      end loop;
   exception
      when others =>
         Queue.Done (Item);  --  Run_* never propagate; be safe anyway.
   end Runner;

   type Runner_Access is access Runner;
   type Runner_Set is array (Positive range <>) of Runner_Access;

   procedure Free is new Ada.Unchecked_Deallocation (Runner, Runner_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Runner_Set, Runner_Set_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Work_Queue, Queue_Access);

   type Pool is new Task_Pool_State with record
      Queue   : Queue_Access;
      Runners : Runner_Set_Access;
   end record;

   procedure Free is new Ada.Unchecked_Deallocation
     (Task_Pool_State'Class, Task_Pool_State_Access);

   procedure Start
     (This       : in out Task_Pool;
      Queue_Size : Positive;
      Threads    : Positive;
      Priority   : System.Priority) is
   begin
      if This.State = null then
         declare
            Made : constant Queue_Access := new Work_Queue (Queue_Size);
            P    : constant Task_Pool_State_Access :=
              new Pool'(Queue => Made, Runners => new Runner_Set (1 .. Threads));
         begin
            for R of Pool (P.all).Runners.all loop
               R := new Runner (Made, Priority);
            end loop;
            This.State := P;
         end;
      end if;
   end Start;

   function Started (This : Task_Pool) return Boolean is (This.State /= null);

   function Queue (This : Task_Pool) return Queue_Access is
     (Pool (This.State.all).Queue)
     with Pre => Started (This);

   procedure Put_Sample
     (This : in out Task_Pool;
      Node : not null Node_Access;
      Sub  : Subscription_Work;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is
   begin
      Queue (This).Put ((Kind => Sample, Node => Node, Sub => Sub,
                         Data => new RCL.DDS.Byte_Array'(Data), Info => Info));
   end Put_Sample;

   procedure Put_Timer
     (This    : in out Task_Pool;
      Node    : not null Node_Access;
      Timer   : Timer_Work;
      Elapsed : Duration) is
   begin
      Queue (This).Put ((Kind => Tick, Node => Node, Timer => Timer, Elapsed => Elapsed));
   end Put_Timer;

   procedure Flush (This : in out Task_Pool) is
   begin
      if Started (This) then
         Queue (This).Wait_Idle;
      end if;
   end Flush;

   procedure Shutdown (This : in out Task_Pool) is
   begin
      if not Started (This) then
         return;
      end if;
      declare
         P : Pool renames Pool (This.State.all);
      begin
         P.Queue.Wait_Idle;
         for I in P.Runners'Range loop
            P.Queue.Put ((Kind => Stop, Node => null));
         end loop;
         for R of P.Runners.all loop
            while not R'Terminated loop
               delay 0.001;
            end loop;
            Free (R);
         end loop;
         Free (P.Runners);
         Free (P.Queue);
      end;
      Free (This.State);
   end Shutdown;

end RCL.Executors.Pools;
