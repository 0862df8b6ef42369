with Ada.Unchecked_Deallocation;

package body RCL.Executors.Concurrent is

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

   procedure Free is new Ada.Unchecked_Deallocation (Runner, Runner_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Work_Queue, Queue_Access);

   procedure Start (This : in out Executor) is
   begin
      if not This.Started then
         This.Queue := new Work_Queue (This.Queue_Size);
         for I in This.Pool'Range loop
            This.Pool (I) := new Runner (This.Queue, This.Priority);
         end loop;
         This.Started := True;
      end if;
   end Start;

   overriding procedure Dispatch_Sample
     (This : in out Executor;
      Node : not null Node_Access;
      Sub  : not null RCL.Nodes.Subscription_Access)
   is
      procedure Queue_It (Data : RCL.DDS.Byte_Array; Info : RCL.DDS.Sample_Info) is
      begin
         This.Queue.Put
           ((Kind => Sample, Node => Node, Sub => Sub,
             Data => new RCL.DDS.Byte_Array'(Data), Info => To_Info (Info)));
      end Queue_It;
      Taken : Boolean := True;
   begin
      Start (This);
      while Taken loop
         RCL.DDS.Take (Sub.Reader, Queue_It'Access, Taken);
      end loop;
   end Dispatch_Sample;

   overriding procedure Dispatch_Timer
     (This    : in out Executor;
      Node    : not null Node_Access;
      Timer   : RCL.Nodes.Timer_Entry;
      Elapsed : Duration) is
   begin
      Start (This);
      This.Queue.Put ((Kind => Tick, Node => Node, Timer => Timer, Elapsed => Elapsed));
   end Dispatch_Timer;

   overriding procedure Flush (This : in out Executor) is
   begin
      if This.Started then
         This.Queue.Wait_Idle;
      end if;
   end Flush;

   procedure Shutdown (This : in out Executor) is
   begin
      if not This.Started then
         return;
      end if;
      This.Queue.Wait_Idle;
      for I in This.Pool'Range loop
         This.Queue.Put ((Kind => Stop, Node => null));
      end loop;
      for I in This.Pool'Range loop
         while not This.Pool (I)'Terminated loop
            delay 0.001;
         end loop;
         Free (This.Pool (I));
      end loop;
      Free (This.Queue);
      This.Started := False;
   end Shutdown;

   function Is_Shut_Down (This : Executor) return Boolean is (not This.Started);

   overriding procedure Finalize (This : in out Executor) is
   begin
      Shutdown (This);
      Executors.Executor (This).Finalize;
   exception
      when others =>
         null;
   end Finalize;

end RCL.Executors.Concurrent;
