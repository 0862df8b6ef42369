pragma Unreserve_All_Interrupts;
--  So that SIGINT can be handled (GNAT reserves it by default).

with Ada.Environment_Variables;
with Ada.Interrupts.Names;
with Ada.Real_Time;
with GNAT.OS_Lib;
with RCL.Arguments;
with RCL.Process_Context;

package body RCL.Contexts is

   package Env renames Ada.Environment_Variables;

   function Env_Domain return RCL.DDS.Domain_Id is
     (Parse_Domain_Id (Env.Value ("ROS_DOMAIN_ID", "")));

   function Env_Localhost_Only return Boolean is
     (Env.Value ("ROS_LOCALHOST_ONLY", "0") = "1"
      or else Env.Value ("ROS_AUTOMATIC_DISCOVERY_RANGE", "") = "LOCALHOST");

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
     (if Process_Context.Is_Initialized then Process_Context.Domain else Env_Domain);

   function Localhost_Only return Boolean is
     (if Process_Context.Is_Initialized then Process_Context.Localhost_Only
      else Env_Localhost_Only);

   function Is_Initialized return Boolean is (Process_Context.Is_Initialized);

   procedure Init is
   begin
      RCL.Arguments.Load;
      Install_Signal_Handlers;
      Process_Context.Ensure_Participant (Env_Domain, Env_Localhost_Only);
   end Init;

   procedure Init (Domain : RCL.DDS.Domain_Id; Localhost_Only : Boolean) is
   begin
      RCL.Arguments.Load;
      Install_Signal_Handlers;
      Process_Context.Ensure_Participant (Domain, Localhost_Only);
   end Init;

   procedure Init (Participant_Lease : Duration) is
   begin
      RCL.Arguments.Load;
      Install_Signal_Handlers;
      Process_Context.Ensure_Participant (Env_Domain, Env_Localhost_Only, Participant_Lease);
   end Init;

   procedure Shutdown is
   begin
      Process_Context.Shutdown;
   end Shutdown;

   function Is_Shutdown return Boolean is (Process_Context.Is_Shutdown);

   function Enclave return String is (RCL.Arguments.Enclave);

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
