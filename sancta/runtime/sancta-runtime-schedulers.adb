with Ada.Exceptions;
with Sancta.Logging;
with Sancta.Runtime.Tasks;

package body Sancta.Runtime.Schedulers is

   use Ada.Strings.Unbounded;
   use type Components.Component_Access;

   function Micros (D : Time_Span) return String is
      S : constant String := Long_Long_Integer'Image
        (Long_Long_Integer (To_Duration (D) * 1_000_000.0));
   begin
      return S (S'First + 1 .. S'Last);
   end Micros;

   protected body Queue is
      procedure Add (Item : Components.Component_Access; Due : Clocks.Time) is
      begin
         Members.Append (Member'(Item => Item, Stats => <>));
         Seq := Seq + 1;
         Entries.Insert ((Due, Seq, Members.Last_Index));
      end Add;

      procedure Put_Back (Index : Positive; Due : Clocks.Time) is
      begin
         Seq := Seq + 1;
         Entries.Insert ((Due, Seq, Index));
      end Put_Back;

      procedure Pop_Due (Now : Clocks.Time; Found : out Boolean; Next : out Queue_Entry) is
      begin
         Found := not Entries.Is_Empty and then Entries.First_Element.Due <= Now;
         if Found then
            Next := Entries.First_Element;
            Entries.Delete_First;
         else
            Next := (Now, 0, 1);
         end if;
      end Pop_Due;

      function Next_Due return Clocks.Time is
        (if Entries.Is_Empty then Components.Never else Entries.First_Element.Due);

      function Length return Natural is (Natural (Entries.Length));

      function Get (Index : Positive) return Member is (Members (Index));

      procedure Set_Stats (Index : Positive; Stats : Statistics) is
      begin
         Members (Index).Stats := Stats;
      end Set_Stats;

      function Find (Item : Components.Component_Access) return Natural is
      begin
         for I in Members.First_Index .. Members.Last_Index loop
            if Members (I).Item = Item then
               return I;
            end if;
         end loop;
         return 0;
      end Find;

      function Members_Count return Natural is (Natural (Members.Length));

      procedure Request_Stop is
      begin
         Stopping := True;
      end Request_Stop;

      function Stop_Requested return Boolean is (Stopping);
   end Queue;

   procedure Initialize
     (This          : in out Scheduler;
      Clock         : not null Clocks.Clock_Access;
      Name          : String;
      Keep_Up_Limit : Time_Span := Milliseconds (100)) is
   begin
      This.Clock := Clock;
      This.Name := To_Unbounded_String (Name);
      This.Keep_Up_Limit := Keep_Up_Limit;
   end Initialize;

   function Now (This : Scheduler) return Clocks.Time is (This.Clock.Now);

   procedure Add
     (This : in out Scheduler; Item : not null Components.Component_Access; Due : Clocks.Time) is
   begin
      This.Calls.Add (Item, Due);
   end Add;

   function Next_Due (This : Scheduler) return Clocks.Time is (This.Calls.Next_Due);

   function Queued (This : Scheduler) return Natural is (This.Calls.Length);

   procedure Run_One (This : in out Scheduler; Call : Queue_Entry) is
      M        : Member := This.Calls.Get (Call.Index);
      Item     : Components.Component_Access renames M.Item;
      Started  : constant Clocks.Time := This.Clock.Now;
      Lateness : constant Time_Span := Started - Call.Due;
      Next     : Clocks.Time := Call.Due;
      Section  : constant String := "scheduler " & To_String (This.Name);
   begin
      if Item.Failed then
         return;
         --  Stopped after a failure (maybe in a listener): no more calls.
      end if;
      M.Stats.Calls := M.Stats.Calls + 1;
      M.Stats.Total_Lateness := M.Stats.Total_Lateness + Lateness;
      if Lateness > M.Stats.Max_Lateness then
         M.Stats.Max_Lateness := Lateness;
      end if;
      if Lateness > This.Keep_Up_Limit then
         M.Stats.Late_Calls := M.Stats.Late_Calls + 1;
         if not This.Warned_Once or else Started - This.Last_Warning >= Seconds (5) then
            Logging.Log (Section, Logging.Warning,
                         "cannot keep up: " & Item.Name & " started " & Micros (Lateness)
                         & " us late");
            This.Warned_Once := True;
            This.Last_Warning := Started;
         end if;
      end if;
      Item.Lock;
      begin
         if not Item.Started then
            --  Its Start failed earlier (retry policy): try it again first.
            Item.Start;
            Item.Set_Started;
         end if;
         Item.Run (Next);
         Item.Unlock;
      exception
         when E : others =>
            Item.Report_Failure ((if Item.Started then "Run" else "Start"), E);
            Item.Unlock;
            M.Stats.Failures := M.Stats.Failures + 1;
            Next := (if Item.Failed then Components.Never
                     else This.Clock.Now + Item.Ctx.Retry_After);
      end;
      declare
         Finished : constant Clocks.Time := This.Clock.Now;
         Took     : constant Time_Span := Finished - Started;
      begin
         M.Stats.Total_Run := M.Stats.Total_Run + Took;
         if Took > M.Stats.Max_Run then
            M.Stats.Max_Run := Took;
         end if;
         if Next /= Components.Never and then Next <= Finished then
            M.Stats.Overruns := M.Stats.Overruns + 1;
            if M.Stats.Overruns = 1 or else M.Stats.Overruns mod 100 = 0 then
               Logging.Log (Section, Logging.Warning,
                            "overrun: " & Item.Name & " took " & Micros (Took)
                            & " us and its next call is already" & " "
                            & Micros (Finished - Next) & " us late (overruns:"
                            & M.Stats.Overruns'Image & ")");
            end if;
         end if;
      end;
      This.Calls.Set_Stats (Call.Index, M.Stats);
      if Next /= Components.Never and then not Item.Failed then
         This.Calls.Put_Back (Call.Index, Next);
      end if;
   end Run_One;

   procedure Run_Due (This : in out Scheduler) is
      Limit : constant Clocks.Time := This.Clock.Now;
      Found : Boolean;
      Call  : Queue_Entry;
   begin
      loop
         This.Calls.Pop_Due (Limit, Found, Call);
         exit when not Found;
         Run_One (This, Call);
      end loop;
   end Run_Due;

   procedure Step (This : in out Scheduler) is
      Due : constant Clocks.Time := This.Calls.Next_Due;
   begin
      if Due /= Components.Never then
         This.Clock.Wait_Until (Due);
      end if;
      This.Run_Due;
   end Step;

   task body Runner is
      Poll : constant Time_Span := Milliseconds (100);
   begin
      loop
         exit when Owner.Calls.Stop_Requested;
         declare
            Due  : constant Clocks.Time := Owner.Calls.Next_Due;
            Wake : constant Clocks.Time := Owner.Clock.Now + Poll;
         begin
            Owner.Clock.Wait_Until (if Due < Wake then Due else Wake);
         end;
         exit when Owner.Calls.Stop_Requested;
         Owner.Run_Due;
         Tasks.Report_Ended;
      end loop;
   exception
      when E : others =>
         Logging.Log ("scheduler " & To_String (Owner.Name), Logging.Error,
                      "scheduler task failed: " & Ada.Exceptions.Exception_Information (E));
   end Runner;

   procedure Start (This : in out Scheduler) is
   begin
      if This.Worker = null then
         This.Worker := new Runner (This'Unchecked_Access);
      end if;
   end Start;

   procedure Stop (This : in out Scheduler) is
   begin
      This.Calls.Request_Stop;
      if This.Worker /= null then
         Tasks.Await_Termination (This.Worker'Identity);
      end if;
   end Stop;

   function Stats (This : Scheduler; Item : not null Components.Component_Access)
     return Statistics
   is
      Index : constant Natural := This.Calls.Find (Item);
   begin
      return (if Index = 0 then (others => <>) else This.Calls.Get (Index).Stats);
   end Stats;

   function Report (This : Scheduler) return String is
      Result : Unbounded_String;
   begin
      for I in 1 .. This.Calls.Members_Count loop
         declare
            M : constant Member := This.Calls.Get (I);
            S : Statistics renames M.Stats;
            N : constant Integer := Integer'Max (1, S.Calls);
         begin
            Append (Result, M.Item.Name & ": calls" & S.Calls'Image & ", failures"
                    & S.Failures'Image & ", overruns" & S.Overruns'Image & ", late"
                    & S.Late_Calls'Image & ", run mean/max " & Micros (S.Total_Run / N) & "/"
                    & Micros (S.Max_Run) & " us, lateness mean/max "
                    & Micros (S.Total_Lateness / N) & "/" & Micros (S.Max_Lateness) & " us"
                    & ASCII.LF);
         end;
      end loop;
      return To_String (Result);
   end Report;

end Sancta.Runtime.Schedulers;
