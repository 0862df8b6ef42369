with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Sancta.Geometry;
with Sancta.Logging;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Factory;
with Sancta.Runtime.Shutdown;
with Sancta.Runtime.Values;
with Sancta.Simulation.Map_Files;
with Sancta.Team.Agents;
with Sancta.Team.Grid_Costs;
with Sancta.Team.Goal_Trackers;
with Sancta.Team.Missions;

package body Sancta.Team.Components is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;
   use type Agents.Agent_Access;

   Period : constant Ada.Real_Time.Time_Span := Ada.Real_Time.Milliseconds (100);

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Img (X : Real) return String is (Values.Real_Image (Long_Float (X)));

   --  team_member ---------------------------------------------------------------

   type Member_Component is new Base_Component with record
      Agent     : Agents.Agent_Access;
      Tolerance : Real := 0.3;
      Here      : Point := (0.0, 0.0);
      Has_Pose  : Boolean := False;
      Tracker   : Goal_Trackers.Goal_Tracker;
      Last_Pose : Ada.Real_Time.Time := Ada.Real_Time.Time_First;
   end record;

   overriding procedure Start (This : in out Member_Component);
   overriding procedure Stop (This : in out Member_Component);
   overriding procedure Run (This : in out Member_Component; Next : in out Clocks.Time);
   overriding procedure On_Input
     (This : in out Member_Component; Data : String; Item : Values.Value'Class);

   function Leg_Costs (This : Member_Component'Class) return Grid_Costs.Cost_Access is
      World : constant String := This.Option_Text ("world");
   begin
      if This.Option_Text ("costs") = "straight" then
         return null;
      elsif World = "" or else Simulation.Map_Files.World_File (World) = "" then
         raise Constraint_Error with "team_member: costs=""grid"" needs world= (a bundled"
           & " world or a map file), found '" & World & "'";
      end if;
      return Grid_Costs.Create (Simulation.Map_Files.World_File (World),
                                Robot_Radius => Real (This.Option_Real ("robot_radius")));
   end Leg_Costs;

   overriding procedure Start (This : in out Member_Component) is
   begin
      This.Tolerance := Real (This.Option_Real ("tolerance"));
      This.Last_Pose := This.Now - Ada.Real_Time.Seconds (1);
      This.Agent := Agents.Create
        ((Id       => To_Unbounded_String (This.Agent_Id),
          Team     => To_Unbounded_String (This.Option_Text ("team")),
          Is_Robot => True,
          Lease    => Ada.Real_Time.To_Duration (This.Option_Duration ("lease")),
          How      => Agents.Parse_Method (This.Option_Text ("method")),
          Verbose  => True,
          Costs    => Leg_Costs (This),
          others   => <>));
      This.Subscribe ("pose");
   end Start;

   procedure Stop_Agent (Agent : Agents.Agent_Access) is
   begin
      if Agent /= null then
         Agent.Stop;
      end if;
   end Stop_Agent;

   overriding procedure Stop (This : in out Member_Component) is
   begin
      Stop_Agent (This.Agent);
      Base_Component (This).Stop;
   end Stop;

   overriding procedure On_Input
     (This : in out Member_Component; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
      P : constant Pose := Values.Pose_Value (Item).Data;
   begin
      This.Here := (P.X, P.Y);
      This.Has_Pose := True;
      if This.Now - This.Last_Pose > Ada.Real_Time.Milliseconds (500) then
         This.Last_Pose := This.Now;
         This.Agent.Set_Pose (This.Here);
      end if;
   end On_Input;

   overriding procedure Run (This : in out Member_Component; Next : in out Clocks.Time) is
      Found : Boolean;
      Goal  : Point;
      Tid   : Unbounded_String;
      Done  : Boolean;
   begin
      Next := Next + Period;
      if not This.Has_Pose then
         return;
      end if;
      This.Agent.Current_Goal (Found, Goal, Tid);
      case This.Tracker.Decide (Found, Goal, To_String (Tid), This.Here, This.Tolerance) is
         when Goal_Trackers.Nothing =>
            null;
         when Goal_Trackers.Go_Idle =>
            This.Output ("status", Values.To_Value ("idle"));
            This.Output ("goal", Values.Pose_Value'(Data => (This.Here.X, This.Here.Y, 0.0)));
            This.Log (Logging.Info, "idle (round" & This.Agent.Round.Generation'Image
                      & ", plan" & This.Agent.Adopted.Generation'Image & ")");
         when Goal_Trackers.At_Goal =>
            This.Agent.Arrived (To_String (Tid), Done);
            if Done then
               This.Log (Logging.Info, "did " & To_String (Tid));
            end if;
         when Goal_Trackers.New_Goal =>
            This.Output ("status", Values.To_Value ("task " & To_String (Tid)));
            This.Output ("goal", Values.Pose_Value'(Data => (Goal.X, Goal.Y, 0.0)));
            This.Log (Logging.Info, "task " & To_String (Tid) & " goal " & Img (Goal.X) & ","
                      & Img (Goal.Y));
      end case;
   end Run;

   function Create_Member is new Factory.Create_Component (Member_Component);

   --  team_operator ----------------------------------------------------------------

   type Operator_Component is new Base_Component with record
      Agent : Agents.Agent_Access;
      Last  : Unbounded_String;
      Stop_When_Done : Boolean := True;
   end record;

   overriding procedure Start (This : in out Operator_Component);
   overriding procedure Stop (This : in out Operator_Component);
   overriding procedure Run (This : in out Operator_Component; Next : in out Clocks.Time);

   overriding procedure Start (This : in out Operator_Component) is
      M : constant Missions.Mission := Missions.Read (This.Option_Text ("mission"));
   begin
      This.Stop_When_Done := This.Option_Boolean ("stop_when_done");
      This.Agent := Agents.Create
        ((Id       => To_Unbounded_String (This.Agent_Id),
          Team     => To_Unbounded_String (This.Option_Text ("team")),
          Is_Robot => False,
          Lease    => Ada.Real_Time.To_Duration (This.Option_Duration ("lease")),
          Verbose  => False,
          others   => <>));
      This.Agent.Publish_Mission (M);
      This.Log (Logging.Info, "mission " & To_String (M.Name) & " published ("
                & Trim (Natural (M.Tasks.Length)) & " tasks)");
   end Start;

   overriding procedure Stop (This : in out Operator_Component) is
   begin
      Stop_Agent (This.Agent);
      Base_Component (This).Stop;
   end Stop;

   overriding procedure Run (This : in out Operator_Component; Next : in out Clocks.Time) is
      Text : constant String :=
        Trim (This.Agent.Done_Tasks) & "/" & Trim (This.Agent.Mission_Tasks) & " round "
        & Trim (This.Agent.Round.Generation) & " robots"
        & Trim (Natural (This.Agent.Round.Robots.Length));
   begin
      Next := Next + Period * 5;
      if Text /= To_String (This.Last) then
         This.Last := To_Unbounded_String (Text);
         This.Log (Logging.Info, "progress " & Text);
         This.Output ("progress", Values.To_Value (Text));
      end if;
      if This.Stop_When_Done and then This.Agent.All_Done then
         Shutdown.Request ("team_operator: every task of the mission is done", Failure => False);
      end if;
   end Run;

   function Create_Operator is new Factory.Create_Component (Operator_Component);

   --  Option checks (sancta check reports them with the attribute's place).

   function Check_Lease (Text : String) return String is
     (if Long_Float'Value (Text) >= 0.1 then ""
      else "a lease of at least 0.1 s, found '" & Text & "'");

   function Check_World (Text : String) return String is
     (if Text = "" or else Simulation.Map_Files.World_File (Text) /= "" then ""
      else "world '" & Text & "': no such file and no bundled world of that name");

   function Check_Mission (Text : String) return String is
   begin
      declare
         Unused : constant Missions.Mission := Missions.Read (Text);
      begin
         return "";
      end;
   exception
      when E : Missions.Format_Error =>
         return "mission: " & Ada.Exceptions.Exception_Message (E);
   end Check_Mission;

begin
   Factory.Register
     ((Name    => To_Unbounded_String ("team_member"),
       Doc     => To_Unbounded_String ("robot of a team: allocation over DDS, goals of its tasks"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose", Doc => "robot in the world")
                    & Out_Port ("goal", "types.pose", "the current task's point")
                    & Out_Port ("status", "types.string", "idle or the current task"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("team", Text_Option, "team")
                    & Make_Option ("method", Choice_Option, "annealer",
                                   Choices => "annealer auctions")
                    & Make_Option ("lease", Duration_Option, "1.0", Check => Check_Lease'Access)
                    & Make_Option ("tolerance", Real_Option, "0.3")
                    & Make_Option ("costs", Choice_Option, "straight",
                                   Choices => "straight grid")
                    & Make_Option ("world", Text_Option, "", Check => Check_World'Access)
                    & Make_Option ("robot_radius", Real_Option, "0.2"),
       others  => <>),
      Create_Member'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("team_operator"),
       Doc     => To_Unbounded_String ("publishes a mission to a team and follows it"),
       Ports   => Port_Vectors.Empty_Vector
                    & Out_Port ("progress", "types.string", "done/total, round, robots"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("mission", Text_Option, Required => True,
                                   Check => Check_Mission'Access)
                    & Make_Option ("team", Text_Option, "team")
                    & Make_Option ("lease", Duration_Option, "1.0", Check => Check_Lease'Access)
                    & Make_Option ("stop_when_done", Boolean_Option, "true"),
       others  => <>),
      Create_Operator'Access);
end Sancta.Team.Components;
