--  A node: one agent of a configuration brought to life, with its own local
--  database, its components (created by the factory in start order) and its
--  periodic scheduler.
--
--     N.Create (Config, Config.Find_Agent ("Ari"), Clock'Unchecked_Access);
--     N.Start;    --  Start of each component in order, first Runs queued
--     ...
--     N.Stop;     --  scheduler stopped, components stopped in reverse order
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Databases;
with Sancta.Runtime.Schedulers;

private with Ada.Containers.Vectors;
private with Ada.Strings.Unbounded;

package Sancta.Runtime.Nodes is

   type Node is tagged limited private;

   procedure Create
     (This   : in out Node;
      Config : Configurations.Configuration;
      Agent  : Positive;
      Clock  : not null Clocks.Clock_Access)
     with Pre => Agent <= Natural (Config.Agents.Length);
   --  Creates the enabled components of Config.Agents (Agent). Raises
   --  Configuration_Error when Config has errors or a creator failed (the
   --  components created so far are kept for Stop).

   procedure Start (This : in out Node; Run_Scheduler_Task : Boolean := True);
   --  Calls Start of every component in start order and queues its first
   --  Run at the current time; then starts the scheduler task (tests pass
   --  False and drive This.Scheduler themselves). A component whose Start
   --  raises is reported; with on_error="retry" the scheduler calls its
   --  Start again after retry_after (then its Run), with "stop" never.

   procedure Stop (This : in out Node);
   --  Stops the scheduler, then every component in reverse start order.
   --  Exceptions of components are logged. Safe to call twice.

   function Id (This : Node) return String;

   function Statistics (This : Node) return String;
   --  The scheduler's per-component statistics (calls, failures, overruns,
   --  run time and lateness), one line per periodic component.

   function Database (This : in out Node) return Databases.Database_Access;

   function Scheduler (This : in out Node) return access Schedulers.Scheduler;

   function Component_Count (This : Node) return Natural;

   function Component (This : Node; Index : Positive) return Components.Component_Access;
   --  In start order.

   function Find (This : Node; Instance_Name : String) return Components.Component_Access;
   --  null when absent.

private

   package Component_Vectors is new Ada.Containers.Vectors
     (Positive, Components.Component_Access, Components."=");

   type Node is tagged limited record
      Name    : Ada.Strings.Unbounded.Unbounded_String;
      Clock   : Clocks.Clock_Access;
      Data    : aliased Databases.Database;
      Sched   : aliased Schedulers.Scheduler;
      Members : Component_Vectors.Vector;
      Started : Natural := 0;
      --  How many components were started (Stop stops those).
      Stopped : Boolean := False;
   end record;

end Sancta.Runtime.Nodes;
