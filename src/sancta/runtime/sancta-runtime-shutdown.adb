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

   procedure Wait (Timeout : Duration; Done : out Boolean) is
   begin
      select
         State.Wait_For;
         Done := True;
      or
         delay Timeout;
         Done := False;
      end select;
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
