with Ada.Unchecked_Deallocation;

package body RCL.Executors.Pools is

   type Bytes_Access is access RCL.DDS.Byte_Array;
   procedure Free is new Ada.Unchecked_Deallocation (RCL.DDS.Byte_Array, Bytes_Access);

   type Work_Kind is (Sample, Tick, Stop);

   type Work (Kind : Work_Kind := Stop) is record
      Node : Node_Access;
      case Kind is
         when Sample =>
            Sub  : RCL.Nodes.Subscription_Access;
            Data : Bytes_Access;
            Info : ROSIDL.Message_Info;
         when Tick =>
            Timer   : RCL.Nodes.Timer_Entry;
            Elapsed : Duration;
         when Stop =>
            null;
      end case;
   end record;

   type Work_Array is array (Positive range <>) of Work;

   protected type Work_Queue (Capacity : Positive) is
      entry Put (Item : Work);
      entry Get (Item : out Work);
      --  The item counts as in flight until Done.
      procedure Done;
      entry Wait_Idle;
   private
      Items     : Work_Array (1 .. Capacity);
      First     : Positive := 1;
      Count     : Natural := 0;
      In_Flight : Natural := 0;
   end Work_Queue;

   protected body Work_Queue is
      entry Put (Item : Work) when Count < Capacity is
      begin
         Items ((First - 1 + Count) mod Capacity + 1) := Item;
         Count := Count + 1;
      end Put;

      entry Get (Item : out Work) when Count > 0 is
      begin
         Item := Items (First);
         First := First mod Capacity + 1;
         Count := Count - 1;
         In_Flight := In_Flight + 1;
      end Get;

      procedure Done is
      begin
         In_Flight := In_Flight - 1;
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
               Queue.Done;
               exit;
            when Sample =>
               Run_Subscription (Item.Node, Item.Sub, Item.Data.all, Item.Info);
               Free (Item.Data);
            when Tick =>
               Run_Timer (Item.Node, Item.Timer, Item.Elapsed);
         end case;
         Queue.Done;
      end loop;
   exception
      when others =>
         Queue.Done;  --  Run_* never propagate; be safe anyway.
   end Runner;

   type Runner_Access is access Runner;
   type Runner_Set is array (Positive range <>) of Runner_Access;

   procedure Free is new Ada.Unchecked_Deallocation (Runner, Runner_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Runner_Set, Runner_Set_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Work_Queue, Queue_Access);

   procedure Start
     (This       : in out Pool;
      Queue_Size : Positive;
      Threads    : Positive;
      Priority   : System.Priority) is
   begin
      if This.Queue = null then
         This.Queue := new Work_Queue (Queue_Size);
         This.Runners := new Runner_Set (1 .. Threads);
         for R of This.Runners.all loop
            R := new Runner (This.Queue, Priority);
         end loop;
      end if;
   end Start;

   function Started (This : Pool) return Boolean is (This.Queue /= null);

   procedure Put_Sample
     (This : in out Pool;
      Node : not null Node_Access;
      Sub  : not null RCL.Nodes.Subscription_Access;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is
   begin
      This.Queue.Put ((Kind => Sample, Node => Node, Sub => Sub,
                       Data => new RCL.DDS.Byte_Array'(Data), Info => Info));
   end Put_Sample;

   procedure Put_Timer
     (This    : in out Pool;
      Node    : not null Node_Access;
      Timer   : RCL.Nodes.Timer_Entry;
      Elapsed : Duration) is
   begin
      This.Queue.Put ((Kind => Tick, Node => Node, Timer => Timer, Elapsed => Elapsed));
   end Put_Timer;

   procedure Flush (This : in out Pool) is
   begin
      if This.Queue /= null then
         This.Queue.Wait_Idle;
      end if;
   end Flush;

   procedure Shutdown (This : in out Pool) is
   begin
      if This.Queue = null then
         return;
      end if;
      This.Queue.Wait_Idle;
      for I in This.Runners'Range loop
         This.Queue.Put ((Kind => Stop, Node => null));
      end loop;
      for R of This.Runners.all loop
         while not R'Terminated loop
            delay 0.001;
         end loop;
         Free (R);
      end loop;
      Free (This.Runners);
      Free (This.Queue);
   end Shutdown;

end RCL.Executors.Pools;
