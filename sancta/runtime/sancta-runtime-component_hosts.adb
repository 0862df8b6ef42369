with Ada.Exceptions;
with Ada.Real_Time;
with Sancta.Logging;
with Sancta.Runtime.Factory;
with Sancta.Runtime.Tasks;
with Sancta.Runtime.XML_Trees;

package body Sancta.Runtime.Component_Hosts is

   use Ada.Strings.Unbounded;
   use type Components.Port_Direction;
   use type Ada.Real_Time.Time;

   procedure Create
     (This   : in out Component_Host;
      Config : Configurations.Configuration;
      Agent  : Positive;
      Clock  : not null Clocks.Clock_Access)
   is
      A : Configurations.Agent renames Config.Agents (Agent);
   begin
      if Configurations.Error_Count (Config) > 0 then
         raise Configuration_Error with To_String (Config.File) & ":1:1: the configuration has"
           & Configurations.Error_Count (Config)'Image & " error(s); run 'sancta check'";
      end if;
      This.Name := A.Id;
      This.Clock := Clock;
      This.Sched.Initialize (Clock, To_String (A.Id));
      for I of A.Instances loop
         if I.Enabled then
            declare
               Ctx : Components.Context :=
                 (Agent_Id      => A.Id,
                  Agent_Kind    => A.Kind,
                  Instance_Name => I.Name,
                  Database      => This.Data'Unchecked_Access,
                  Clock         => Clock,
                  Options       => I.Options,
                  Policy        => I.Policy,
                  Retry_After   => Ada.Real_Time.To_Time_Span (I.Retry_After),
                  others        => <>);
            begin
               for B of I.Bindings loop
                  if B.Direction = Components.Input then
                     Ctx.Inputs.Include (To_String (B.Data), To_String (B.Key));
                  else
                     Ctx.Outputs.Include (To_String (B.Data), To_String (B.Key));
                     Ctx.Output_Types.Include (To_String (B.Data), To_String (B.Type_Name));
                  end if;
               end loop;
               This.Members.Append (Factory.Create (To_String (I.Component), Ctx));
            exception
               when E : others =>
                  raise Configuration_Error with XML_Trees.Image (I.Where)
                    & ": cannot create component " & To_String (I.Name) & " of agent "
                    & To_String (A.Id) & ": " & Ada.Exceptions.Exception_Message (E);
            end;
         end if;
      end loop;
   end Create;

   procedure Start (This : in out Component_Host; Run_Scheduler_Task : Boolean := True) is
   begin
      for C of This.Members loop
         This.Started := This.Started + 1;
         begin
            C.Lock;
            C.Start;
            C.Set_Started;
            C.Unlock;
            Logging.Log (This.Id, Logging.Debug, "started " & C.Name);
            This.Sched.Add (C, This.Clock.Now);
         exception
            when E : others =>
               C.Report_Failure ("Start", E);
               C.Unlock;
               if not C.Failed then
                  --  Retry policy: the scheduler calls Start again, then Run.
                  This.Sched.Add (C, This.Clock.Now + C.Ctx.Retry_After);
               end if;
         end;
      end loop;
      Logging.Log (This.Id, Logging.Info,
                   "agent " & This.Id & " started with" & This.Members.Length'Image
                   & " component(s)");
      if Run_Scheduler_Task then
         This.Sched.Start;
      end if;
   end Start;

   procedure Stop (This : in out Component_Host) is
   begin
      if This.Stopped then
         return;
      end if;
      This.Stopped := True;
      This.Sched.Stop;
      for I in reverse 1 .. This.Started loop
         declare
            C : constant Components.Component_Access := This.Members (I);
         begin
            C.Lock;
            C.Stop;
            C.Unlock;
            Logging.Log (This.Id, Logging.Debug, "stopped " & C.Name);
         exception
            when E : others =>
               C.Unlock;
               Logging.Log (This.Id, Logging.Error,
                            "component " & C.Name & " failed to stop: "
                            & Ada.Exceptions.Exception_Message (E));
         end;
      end loop;
      Tasks.Report_Ended;
      Logging.Log (This.Id, Logging.Info, "agent " & This.Id & " stopped");
      if Logging.Enabled (This.Id, Logging.Debug) then
         Logging.Log (This.Id, Logging.Debug, "statistics:" & ASCII.LF & This.Statistics);
      end if;
   end Stop;

   function Statistics (This : Component_Host) return String is (This.Sched.Report);

   function Id (This : Component_Host) return String is (To_String (This.Name));

   function Database (This : in out Component_Host) return Local_Databases.Database_Access is
     (This.Data'Unchecked_Access);

   function Scheduler (This : in out Component_Host) return access Schedulers.Scheduler is
     (This.Sched'Unchecked_Access);

   function Component_Count (This : Component_Host) return Natural is
     (Natural (This.Members.Length));

   function Component
     (This : Component_Host; Index : Positive) return Components.Component_Access is
     (This.Members (Index));

   function Find
     (This : Component_Host; Instance_Name : String) return Components.Component_Access is
   begin
      for C of This.Members loop
         if C.Name = Instance_Name then
            return C;
         end if;
      end loop;
      return null;
   end Find;

end Sancta.Runtime.Component_Hosts;
