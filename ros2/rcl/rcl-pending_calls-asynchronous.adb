with Ada.Exceptions;
with Ada.Unchecked_Deallocation;
with RCL.Contexts;
with RCL.Logging;

package body RCL.Pending_Calls.Asynchronous is

   use Ada.Real_Time;
   use type Ada.Task_Identification.Task_Id;

   procedure Warn_Lost (Client : Client_Ref; Count : Natural; Why : String) is
   begin
      if Count > 0 then
         RCL.Logging.Warn (Count'Image & " asynchronous call(s) of service "
                           & Service_Name (Client) & " " & Why);
      end if;
   end Warn_Lost;

   -----------
   -- Table --
   -----------

   protected body Table is

      procedure Add
        (Sequence   : ROSIDL.Int64;
         Call       : Pending_Call;
         Client     : Client_Ref;
         Start_Pump : out Boolean) is
      begin
         Pending.Include (Sequence, Call);
         Table.Client := Client;
         Start_Pump := not Pumping and not Stopping;
         Pumping := Pumping or Start_Pump;
      end Add;

      procedure Take (Sequence : ROSIDL.Int64; Callback : out Response_Callback) is
         Position : Call_Maps.Cursor := Pending.Find (Sequence);
      begin
         if Call_Maps.Has_Element (Position) then
            Callback := Call_Maps.Element (Position).Callback;
            Pending.Delete (Position);
         else
            Callback := null;
         end if;
      end Take;

      procedure Remove (Sequence : ROSIDL.Int64) is
      begin
         Pending.Exclude (Sequence);
      end Remove;

      procedure Expire (Now : Time; Expired : out Natural) is
         Position : Call_Maps.Cursor := Pending.First;
         Next     : Call_Maps.Cursor;
      begin
         Expired := 0;
         while Call_Maps.Has_Element (Position) loop
            Next := Call_Maps.Next (Position);
            if Call_Maps.Element (Position).Deadline < Now then
               Pending.Delete (Position);
               Expired := Expired + 1;
            end if;
            Position := Next;
         end loop;
      end Expire;

      procedure Drop_All (Dropped : out Natural) is
      begin
         Dropped := Natural (Pending.Length);
         Pending.Clear;
      end Drop_All;

      procedure Pumping_Done (Done : out Boolean) is
      begin
         Done := Stopping or else Pending.Is_Empty;
         if Done then
            Pumping := False;
         end if;
      end Pumping_Done;

      entry Await_Pump_End when not Pumping is
      begin
         null;
      end Await_Pump_End;

      procedure Stop is
      begin
         Stopping := True;
      end Stop;

      procedure Set_Callback_Task (Id : Ada.Task_Identification.Task_Id) is
      begin
         Running := Id;
      end Set_Callback_Task;

      function Callback_Task return Ada.Task_Identification.Task_Id is (Running);

      function Pumping_Client return Client_Ref is (Client);

      function Is_Pending (Sequence : ROSIDL.Int64) return Boolean is
        (Pending.Contains (Sequence));

      function Count return Natural is (Natural (Pending.Length));

   end Table;

   ----------
   -- Pump --
   ----------

   task body Pump is
      Owner  : Calls_Access;
      Client : Client_Ref;
      Done   : Boolean := False;
      Lost   : Natural;
   begin
      accept Start (Owner : not null Calls_Access) do
         Pump.Owner := Owner;
      end Start;
      Client := Owner.State.Pumping_Client;
      while not Done loop
         begin
            Read_Replies (Client);
         exception
            when E : others =>
               RCL.Logging.Error ("reading the replies of service " & Service_Name (Client)
                                  & ": " & Ada.Exceptions.Exception_Message (E));
         end;
         if RCL.Contexts.Is_Shutdown then
            Owner.State.Drop_All (Lost);
            Warn_Lost (Client, Lost, "dropped: the context is shut down");
         else
            Owner.State.Expire (Clock, Lost);
            Warn_Lost (Client, Lost, "got no response in time");
         end if;
         Owner.State.Pumping_Done (Done);
      end loop;
   end Pump;

   procedure Free is new Ada.Unchecked_Deallocation (Pump, Pump_Access);

   ---------
   -- Add --
   ---------

   procedure Add
     (This     : in out Calls;
      Client   : Client_Ref;
      Sequence : ROSIDL.Int64;
      Callback : not null Response_Callback;
      Timeout  : Duration)
   is
      Deadline : constant Time :=
        (if Timeout >= 1.0E6 then Time_Last else Clock + To_Time_Span (Timeout));
      Start    : Boolean;
   begin
      This.State.Add (Sequence, (Callback, Deadline), Client, Start);
      if Start then
         --  A previous pump may still be ending (after its Pumping_Done).
         declare
            Started : Pump_Access := new Pump;
         begin
            Started.Start (This'Unchecked_Access);
            Free (Started);  --  Freed by GNAT when it terminates (see the spec).
         end;
      end if;
   exception
      when others =>
         This.State.Remove (Sequence);
         raise;
   end Add;

   procedure Call
     (This     : in out Calls;
      Client   : Client_Ref;
      Callback : not null Response_Callback;
      Timeout  : Duration;
      Send     : not null access procedure (Sequence : ROSIDL.Int64))
   is
      Sequence : constant ROSIDL.Int64 := Next_Sequence;
   begin
      This.Add (Client, Sequence, Callback, Timeout);
      Send (Sequence);
   exception
      when others =>
         This.State.Remove (Sequence);
         raise;
   end Call;

   procedure Remove (This : in out Calls; Sequence : ROSIDL.Int64) is
   begin
      This.State.Remove (Sequence);
   end Remove;

   function Is_Pending (This : Calls; Sequence : ROSIDL.Int64) return Boolean is
     (This.State.Is_Pending (Sequence));

   --------------
   -- Complete --
   --------------

   procedure Complete (This : in out Calls; Sequence : ROSIDL.Int64; Resp : Response) is
      Callback : Response_Callback;
      Previous : constant Ada.Task_Identification.Task_Id := This.State.Callback_Task;
   begin
      This.State.Take (Sequence, Callback);
      if Callback = null then
         return;
      end if;
      This.State.Set_Callback_Task (Ada.Task_Identification.Current_Task);
      begin
         Callback (Resp);
      exception
         when E : others =>
            RCL.Logging.Error
              ("response callback of service " & Service_Name (This.State.Pumping_Client)
               & " raised " & Ada.Exceptions.Exception_Information (E));
      end;
      This.State.Set_Callback_Task (Previous);
   end Complete;

   function Count (This : Calls) return Natural is (This.State.Count);

   function In_Callback (This : Calls) return Boolean is
     (This.State.Callback_Task = Ada.Task_Identification.Current_Task);

   procedure Check_Not_In_Callback (This : Calls) is
   begin
      if This.In_Callback then
         raise ROS_Exception with "service " & Service_Name (This.State.Pumping_Client)
           & ": a synchronous call from a response callback of the same client"
           & " would wait for itself";
      end if;
   end Check_Not_In_Callback;

   ----------
   -- Stop --
   ----------

   procedure Stop (This : in out Calls) is
      Dropped : Natural;
   begin
      This.State.Stop;
      This.State.Drop_All (Dropped);
      if Dropped > 0 then
         Warn_Lost (This.State.Pumping_Client, Dropped, "dropped: the client is finalized");
      end if;
      if not This.In_Callback then
         This.State.Await_Pump_End;
      end if;
   exception
      when E : others =>
         RCL.Logging.Error ("stopping the asynchronous calls of a client: "
                            & Ada.Exceptions.Exception_Information (E));
   end Stop;

end RCL.Pending_Calls.Asynchronous;
