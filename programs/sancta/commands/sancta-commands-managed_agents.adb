with Ada.Calendar;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with RCL.Executors.Sequential;
with RCL.Lifecycle;
with RCL.Names;
with RCL.Nodes;
with Sancta.Logging;
with Sancta.Runtime.Component_Hosts;
with Sancta.Runtime.Shutdown;

package body Sancta.Commands.Managed_Agents is

   use Ada.Strings.Unbounded;
   use RCL.Lifecycle;
   package Configurations renames Sancta.Runtime.Configurations;
   package Shutdown renames Sancta.Runtime.Shutdown;

   type Component_Host_Access is access Sancta.Runtime.Component_Hosts.Component_Host;
   procedure Free is new Ada.Unchecked_Deallocation
     (Sancta.Runtime.Component_Hosts.Component_Host, Component_Host_Access);

   type ROS_Node_Access is access RCL.Nodes.Node;

   type Agent is limited record
      Id        : Unbounded_String;
      ROS_Node  : ROS_Node_Access;
      Lifecycle : Managed_Node;
      Runtime   : Component_Host_Access;
      --  Null while unconfigured or finalized.
      Running   : Boolean := False;
      Finalized : Boolean := False;
   end record;

   type Agent_Access is access Agent;
   type Agent_Array is array (Positive range <>) of Agent_Access;
   type Agent_Array_Access is access Agent_Array;

   --  The run's state, set by Run before any callback can happen (the
   --  callbacks run in Run's task, which spins the executor).
   The_Config : access constant Configurations.Configuration;
   The_Clock  : Sancta.Runtime.Clocks.Clock_Access;
   The_Agents : Agent_Array_Access;

   function Node_Name (Agent_Id : String) return String is
     (RCL.Names.Name_Token ("sancta_" & Agent_Id));

   function Agent_Of (Node : RCL.Nodes.Node'Class) return Agent_Access is
   begin
      for A of The_Agents.all loop
         if Node_Name (To_String (A.Id)) = Node.Name then
            return A;
         end if;
      end loop;
      raise Program_Error with "no agent for node " & Node.Name;
   end Agent_Of;

   procedure Log
     (A : Agent; Text : String; Level : Sancta.Logging.Level := Sancta.Logging.Info) is
   begin
      Sancta.Logging.Log ("managed " & To_String (A.Id), Level, Text);
   end Log;

   procedure Discard (A : in out Agent) is
   begin
      if A.Runtime /= null then
         if A.Running then
            A.Runtime.Stop;
            A.Running := False;
         end if;
         Free (A.Runtime);
      end if;
   end Discard;

   function Create (A : in out Agent) return Callback_Return is
   begin
      A.Runtime := new Sancta.Runtime.Component_Hosts.Component_Host;
      A.Runtime.Create
        (The_Config.all, Configurations.Find_Agent (The_Config.all, To_String (A.Id)),
         The_Clock);
      return Success;
   exception
      when E : others =>
         Log (A, "cannot create the components: " & Ada.Exceptions.Exception_Message (E),
              Sancta.Logging.Error);
         Discard (A);
         return Failure;
   end Create;

   function On_Configure (Node : in out RCL.Nodes.Node'Class; Previous : State_Id)
     return Callback_Return
   is
      pragma Unreferenced (Previous);
      A      : constant Agent_Access := Agent_Of (Node);
      Result : constant Callback_Return := Create (A.all);
   begin
      if Result = Success then
         Log (A.all, "configured: components created");
      end if;
      return Result;
   end On_Configure;

   function On_Activate (Node : in out RCL.Nodes.Node'Class; Previous : State_Id)
     return Callback_Return
   is
      pragma Unreferenced (Previous);
      A : constant Agent_Access := Agent_Of (Node);
   begin
      A.Runtime.Start;
      A.Running := True;
      Log (A.all, "active: components started");
      return Success;
   exception
      when E : others =>
         Log (A.all, "cannot start: " & Ada.Exceptions.Exception_Message (E),
              Sancta.Logging.Error);
         return Failure;
   end On_Activate;

   function On_Deactivate (Node : in out RCL.Nodes.Node'Class; Previous : State_Id)
     return Callback_Return
   is
      pragma Unreferenced (Previous);
      A : constant Agent_Access := Agent_Of (Node);
   begin
      Discard (A.all);
      Log (A.all, "inactive: components stopped");
      return Create (A.all);
   end On_Deactivate;

   function On_Cleanup (Node : in out RCL.Nodes.Node'Class; Previous : State_Id)
     return Callback_Return
   is
      pragma Unreferenced (Previous);
      A : constant Agent_Access := Agent_Of (Node);
   begin
      Discard (A.all);
      Log (A.all, "unconfigured: components discarded");
      return Success;
   end On_Cleanup;

   function On_Shutdown (Node : in out RCL.Nodes.Node'Class; Previous : State_Id)
     return Callback_Return
   is
      pragma Unreferenced (Previous);
      A : constant Agent_Access := Agent_Of (Node);
   begin
      Discard (A.all);
      A.Finalized := True;
      Log (A.all, "finalized");
      if (for all B of The_Agents.all => B.Finalized) then
         Shutdown.Request ("every agent finalized");
      end if;
      return Success;
   end On_Shutdown;

   procedure Run
     (Config : Sancta.Runtime.Configurations.Configuration;
      Agents : Sancta.Runtime.Local_Databases.Key_Vectors.Vector;
      Clock  : Sancta.Runtime.Clocks.Clock_Access;
      Limit  : Duration)
   is
      use type Ada.Calendar.Time;
      Kept     : aliased constant Configurations.Configuration := Config;
      Executor : RCL.Executors.Sequential.Executor (Max_Nodes => Natural (Agents.Length));
      Stop_At  : constant Ada.Calendar.Time :=
        Ada.Calendar.Clock + (if Limit > 0.0 then Limit else 1.0E9);
   begin
      The_Config := Kept'Unchecked_Access;
      The_Clock := Clock;
      The_Agents := new Agent_Array (1 .. Natural (Agents.Length));
      for I in The_Agents'Range loop
         The_Agents (I) := new Agent;
         declare
            A : Agent renames The_Agents (I).all;
         begin
            A.Id := To_Unbounded_String (Agents (I));
            A.ROS_Node := new RCL.Nodes.Node'(RCL.Nodes.Init (Node_Name (Agents (I))));
            A.Lifecycle.Init
              (A.ROS_Node.all,
               On_Configure  => On_Configure'Access,
               On_Activate   => On_Activate'Access,
               On_Deactivate => On_Deactivate'Access,
               On_Cleanup    => On_Cleanup'Access,
               On_Shutdown   => On_Shutdown'Access);
            Executor.Add (A.ROS_Node.all);
            Log (A, "managed node /" & Node_Name (Agents (I))
                 & " unconfigured (rclada lifecycle set /" & Node_Name (Agents (I))
                 & " configure)");
         end;
      end loop;
      while not Shutdown.Requested and then Ada.Calendar.Clock < Stop_At loop
         Executor.Spin (During => 0.2);
      end loop;
      for A of The_Agents.all loop
         Discard (A.all);
      end loop;
   end Run;

end Sancta.Commands.Managed_Agents;
