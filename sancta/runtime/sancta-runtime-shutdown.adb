with Ada.Calendar;
with Ada.Interrupts.Names;
with Ada.Strings.Unbounded;

package body Sancta.Runtime.Shutdown is

   use Ada.Strings.Unbounded;

   protected State is
      procedure Set (Text : String; Bad : Boolean);
      entry Wait_For;
      function Is_Set return Boolean;
      function Is_Failure return Boolean;
      function Text return String;
      procedure Clear;
      procedure On_Interrupt;
      pragma Interrupt_Handler (On_Interrupt);
   private
      Flag    : Boolean := False;
      Bad_End : Boolean := False;
      Why     : Unbounded_String;
   end State;

   protected body State is
      procedure Set (Text : String; Bad : Boolean) is
      begin
         if not Flag then
            Why := To_Unbounded_String (Text);
         end if;
         Flag := True;
         Bad_End := Bad_End or else Bad;
      end Set;

      entry Wait_For when Flag is
      begin
         null;
      end Wait_For;

      function Is_Set return Boolean is (Flag);
      function Is_Failure return Boolean is (Bad_End);
      function Text return String is (To_String (Why));

      procedure Clear is
      begin
         Flag := False;
         Bad_End := False;
         Why := Null_Unbounded_String;
      end Clear;

      procedure On_Interrupt is
      begin
         Set ("interrupted (Ctrl-C)", False);
      end On_Interrupt;
   end State;

   procedure Request (Reason : String; Failure : Boolean := False) is
   begin
      State.Set (Reason, Failure);
   end Request;

   function Requested return Boolean is (State.Is_Set);
   function Failed return Boolean is (State.Is_Failure);
   function Reason return String is (State.Text);

   type Condition_Entry is record
      Check  : Condition;
      Reason : Unbounded_String;
   end record;

   type Condition_Array is array (1 .. 8) of Condition_Entry;

   protected Conditions is
      procedure Add (Check : Condition; Reason : String);
      function Get return Condition_Array;
   private
      List : Condition_Array;
      Count : Natural := 0;
   end Conditions;

   protected body Conditions is
      procedure Add (Check : Condition; Reason : String) is
      begin
         if Count = List'Last then
            raise Program_Error with "too many shutdown conditions";
         end if;
         Count := Count + 1;
         List (Count) := (Check, To_Unbounded_String (Reason));
      end Add;

      function Get return Condition_Array is (List);
   end Conditions;

   procedure Add_Condition (Check : not null Condition; Reason : String) is
   begin
      Conditions.Add (Check, Reason);
   end Add_Condition;

   procedure Poll_Conditions is
   begin
      for C of Conditions.Get loop
         if C.Check /= null and then C.Check.all then
            Request (To_String (C.Reason));
         end if;
      end loop;
   end Poll_Conditions;

   procedure Wait (Timeout : Duration; Done : out Boolean) is
      use Ada.Calendar;
      Deadline : constant Time := Clock + Timeout;
   begin
      loop
         Poll_Conditions;
         select
            State.Wait_For;
            Done := True;
            return;
         or
            delay until (if Deadline - Clock > 0.1 then Clock + 0.1 else Deadline);
         end select;
         if Clock >= Deadline then
            Poll_Conditions;
            Done := State.Is_Set;
            return;
         end if;
      end loop;
   end Wait;

   procedure Catch_Interrupt (Attached : out Boolean) is
   begin
      if Ada.Interrupts.Is_Reserved (Ada.Interrupts.Names.SIGINT) then
         Attached := False;
      else
         Ada.Interrupts.Attach_Handler
           (State.On_Interrupt'Access, Ada.Interrupts.Names.SIGINT);
         Attached := True;
      end if;
   end Catch_Interrupt;

   procedure Reset is
   begin
      State.Clear;
   end Reset;

end Sancta.Runtime.Shutdown;
