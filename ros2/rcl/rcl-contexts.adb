pragma Unreserve_All_Interrupts;
--  So that SIGINT can be handled (GNAT reserves it by default).

with Ada.Environment_Variables;
with Ada.Interrupts.Names;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with GNAT.OS_Lib;
with RCL.Arguments;
with RCL.Security;

package body RCL.Contexts is

   package Env renames Ada.Environment_Variables;

   type Participant_Access is access RCL.DDS.Participant;
   procedure Free is new Ada.Unchecked_Deallocation (RCL.DDS.Participant, Participant_Access);

   Max_Wakers : constant := 64;
   type Waker_Array is array (1 .. Max_Wakers) of Waitset_Access;

   function Env_Domain return RCL.DDS.Domain_Id is
     (Parse_Domain_Id (Env.Value ("ROS_DOMAIN_ID", "")));

   function Env_Localhost_Only return Boolean is
     (Env.Value ("ROS_LOCALHOST_ONLY", "0") = "1"
      or else Env.Value ("ROS_AUTOMATIC_DISCOVERY_RANGE", "") = "LOCALHOST");

   protected State is
      procedure Init
        (P         : out Participant_Access;
         Dom       : RCL.DDS.Domain_Id;
         Local     : Boolean;
         User_Data : String;
         Secured   : Boolean;
         Files     : RCL.Security.Enclave_Files);
      function Current return Participant_Access;
      function Initialized return Boolean;
      function Domain return RCL.DDS.Domain_Id;
      function Localhost_Only return Boolean;
      procedure Set_Shutdown (Wakers : out Waker_Array);
      function Down return Boolean;
      function Current_Wakers return Waker_Array;
      procedure Register (Hook : Waitset_Access; Key : out Positive);
      procedure Unregister (Key : Positive);
   private
      Part    : Participant_Access;
      Dom_Id  : RCL.DDS.Domain_Id := 0;
      Local   : Boolean := False;
      Is_Down : Boolean := False;
      Hooks   : Waker_Array := [others => null];
   end State;

   function Parse_Domain_Id (Image : String) return RCL.DDS.Domain_Id is
   begin
      if Image = "" then
         return 0;
      end if;
      return RCL.DDS.Domain_Id'Value (Image);
   exception
      when Constraint_Error =>
         raise ROS_Exception with "ROS_DOMAIN_ID: expected an integer in 0 .."
           & RCL.DDS.Domain_Id'Last'Image & ", found """ & Image & """";
   end Parse_Domain_Id;

   function Domain return RCL.DDS.Domain_Id is
     (if State.Initialized then State.Domain else Env_Domain);

   function Localhost_Only return Boolean is
     (if State.Initialized then State.Localhost_Only else Env_Localhost_Only);

   function Is_Initialized return Boolean is (State.Initialized);

   protected body State is
      procedure Init
        (P         : out Participant_Access;
         Dom       : RCL.DDS.Domain_Id;
         Local     : Boolean;
         User_Data : String;
         Secured   : Boolean;
         Files     : RCL.Security.Enclave_Files)
      is
         New_Part : Participant_Access := new RCL.DDS.Participant;
      begin
         if Part = null then
            begin
               RCL.DDS.Create (New_Part.all, Dom, Local, User_Data, Secured, Files);
            exception
               when others =>
                  Free (New_Part);
                  raise;
            end;
            Part := New_Part;
            Dom_Id := Dom;
            State.Local := Local;
         else
            Free (New_Part);
         end if;
         P := Part;
      end Init;

      function Current return Participant_Access is (Part);
      function Initialized return Boolean is (Part /= null);
      function Domain return RCL.DDS.Domain_Id is (Dom_Id);
      function Localhost_Only return Boolean is (Local);

      procedure Set_Shutdown (Wakers : out Waker_Array) is
      begin
         Is_Down := True;
         Wakers := Hooks;
      end Set_Shutdown;

      function Down return Boolean is (Is_Down);
      function Current_Wakers return Waker_Array is (Hooks);

      procedure Register (Hook : Waitset_Access; Key : out Positive) is
      begin
         for I in Hooks'Range loop
            if Hooks (I) = null then
               Hooks (I) := Hook;
               Key := I;
               return;
            end if;
         end loop;
         raise ROS_Exception with "more than" & Max_Wakers'Image & " executors spinning";
      end Register;

      procedure Unregister (Key : Positive) is
      begin
         if Key in Hooks'Range then
            Hooks (Key) := null;
         end if;
      end Unregister;
   end State;

   procedure Ensure
     (P : out Participant_Access; Dom : RCL.DDS.Domain_Id; Local : Boolean)
   is
      --  The participant, created first if need be: secured as the
      --  environment says (RCL.Security), USER_DATA "enclave=<enclave>;".
   begin
      P := State.Current;
      if P = null then
         declare
            Settings : constant RCL.Security.Settings := RCL.Security.Current;
            Secured  : Boolean;
            Files    : RCL.Security.Enclave_Files;
         begin
            RCL.Security.Resolve (Settings, Secured, Files);
            State.Init (P, Dom, Local,
                        "enclave=" & Ada.Strings.Unbounded.To_String (Settings.Enclave) & ";",
                        Secured, Files);
         end;
      end if;
   end Ensure;

   procedure Init is
      P : Participant_Access;
   begin
      RCL.Arguments.Load;
      Install_Signal_Handlers;
      Ensure (P, Env_Domain, Env_Localhost_Only);
   end Init;

   procedure Init (Domain : RCL.DDS.Domain_Id; Localhost_Only : Boolean) is
      P : Participant_Access;
   begin
      RCL.Arguments.Load;
      Install_Signal_Handlers;
      Ensure (P, Domain, Localhost_Only);
   end Init;

   function Participant return not null access RCL.DDS.Participant is
      P : Participant_Access;
   begin
      Ensure (P, Env_Domain, Env_Localhost_Only);
      return P;
   end Participant;

   procedure Shutdown is
      Wakers : Waker_Array;
   begin
      State.Set_Shutdown (Wakers);
      for I in Wakers'Range loop
         if Wakers (I) /= null then
            RCL.DDS.Wake (Wakers (I).all);
         end if;
      end loop;
   end Shutdown;

   function Is_Shutdown return Boolean is (State.Down);

   procedure Wake_Executors is
      Wakers : constant Waker_Array := State.Current_Wakers;
   begin
      for W of Wakers loop
         if W /= null then
            RCL.DDS.Wake (W.all);
         end if;
      end loop;
   end Wake_Executors;

   function Enclave return String is (RCL.Arguments.Enclave);

   procedure Register_Waker (Set : not null Waitset_Access; Key : out Positive) is
   begin
      State.Register (Set, Key);
   end Register_Waker;

   procedure Unregister_Waker (Key : Positive) is
   begin
      State.Unregister (Key);
   end Unregister_Waker;

   -------------
   -- Signals --
   -------------

   protected Signals is
      procedure Handle
        with Interrupt_Handler;
      procedure Installed (Done : out Boolean);
   private
      Count : Natural := 0;
      First : Ada.Real_Time.Time;
      Is_Installed : Boolean := False;
   end Signals;

   protected body Signals is
      procedure Handle is
         pragma Warnings (Off, "potentially blocking operation");
         use type Ada.Real_Time.Time;
         use type Ada.Real_Time.Time_Span;
         Now : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
      begin
         Count := Count + 1;
         if Count > 1 then
            --  A repeated signal (tools such as timeout send two at once):
            --  exit at once only when it comes after a second.
            if Now - First > Ada.Real_Time.Seconds (1) then
               GNAT.OS_Lib.OS_Exit (130);
            end if;
            return;
         end if;
         First := Now;
         --  Runs in GNAT's interrupt server task, not in signal context:
         --  waking the waitsets (a mutex and a condition variable) is safe.
         Shutdown;
      end Handle;

      procedure Installed (Done : out Boolean) is
      begin
         Done := Is_Installed;
         Is_Installed := True;
      end Installed;
   end Signals;

   procedure Install_Signal_Handlers is
      procedure Block_Stop_Signals
        with Import, Convention => C, External_Name => "rclada_block_stop_signals";
      Done : Boolean;
   begin
      Signals.Installed (Done);
      if not Done then
         Ada.Interrupts.Attach_Handler (Signals.Handle'Access, Ada.Interrupts.Names.SIGINT);
         Ada.Interrupts.Attach_Handler (Signals.Handle'Access, Ada.Interrupts.Names.SIGTERM);
         --  The runtime takes the signals with sigwait: they must be
         --  blocked in every thread, including this one (usually the
         --  environment task); Cyclone's threads are started with them
         --  blocked (see csrc).
         Block_Stop_Signals;
      end if;
   exception
      when Program_Error =>
         null;  --  Reserved in this runtime: default signal behaviour stays.
   end Install_Signal_Handlers;

end RCL.Contexts;
