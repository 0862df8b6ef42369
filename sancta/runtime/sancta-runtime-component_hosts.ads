--  A component host: one agent of a configuration brought to life, with its
--  own local database, its components (created by the factory in start
--  order) and its periodic scheduler. (Not a ROS 2 node: RCL.Nodes is the
--  ROS 2 library's.)
--
--     Host.Create (Config, Config.Find_Agent ("Ari"), Clock'Unchecked_Access);
--     Host.Start;  --  Start of each component in order, first Runs queued
--     ...
--     Host.Stop;   --  scheduler stopped, components stopped in reverse order
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Schedulers;

private with Ada.Containers.Vectors;
private with Ada.Strings.Unbounded;

package Sancta.Runtime.Component_Hosts is

   type Component_Host is tagged limited private;

   procedure Create
     (This   : in out Component_Host;
      Config : Configurations.Configuration;
      Agent  : Positive;
      Clock  : not null Clocks.Clock_Access)
     with Pre => Agent <= Natural (Config.Agents.Length);
   --  Creates the enabled components of Config.Agents (Agent). Raises
   --  Configuration_Error when Config has errors or a creator failed (the
   --  components created so far are kept for Stop).

   procedure Start (This : in out Component_Host; Run_Scheduler_Task : Boolean := True);
   --  Calls Start of every component in start order and queues its first
   --  Run at the current time; then starts the scheduler task (tests pass
   --  False and drive This.Scheduler themselves). A component whose Start
   --  raises is reported; with on_error="retry" the scheduler calls its
   --  Start again after retry_after (then its Run), with "stop" never.

   procedure Stop (This : in out Component_Host);
   --  Stops the scheduler, then every component in reverse start order.
   --  Exceptions of components are logged. Safe to call twice.

   function Id (This : Component_Host) return String;

   function Statistics (This : Component_Host) return String;
   --  The scheduler's per-component statistics (calls, failures, overruns,
   --  run time and lateness), one line per periodic component.

   function Database (This : in out Component_Host) return Local_Databases.Database_Access;

   function Scheduler (This : in out Component_Host) return access Schedulers.Scheduler;

   function Component_Count (This : Component_Host) return Natural;

   function Component (This : Component_Host; Index : Positive) return Components.Component_Access;
   --  In start order.

   function Find (This : Component_Host; Instance_Name : String) return Components.Component_Access;
   --  null when absent.

private

   package Component_Vectors is new Ada.Containers.Vectors
     (Positive, Components.Component_Access, Components."=");

   type Component_Host is tagged limited record
      Name    : Ada.Strings.Unbounded.Unbounded_String;
      Clock   : Clocks.Clock_Access;
      Data    : aliased Local_Databases.Database;
      Sched   : aliased Schedulers.Scheduler;
      Members : Component_Vectors.Vector;
      Started : Natural := 0;
      --  How many components were started (Stop stops those).
      Stopped : Boolean := False;
   end record;

end Sancta.Runtime.Component_Hosts;
