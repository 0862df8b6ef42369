with Ada.Containers.Indefinite_Ordered_Maps;
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
with Sancta.Team.Replicated_Databases;
with Sancta.Team.Grid_Costs;
with Sancta.Team.Goal_Trackers;
with Sancta.Team.Missions;
with Sancta.Team.Networks;

package body Sancta.Team.Team_Components is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;
   use type Agents.Agent_Access;
   use type Agents.Method;
   use type Networks.Network_Access;
   use type Replicated_Databases.Team_Database_Access;

   Period : constant Ada.Real_Time.Time_Span := Ada.Real_Time.Milliseconds (100);

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Img (X : Real) return String is (Values.Real_Image (Long_Float (X)));

   --  The team parts of each SANCTA agent (Table 1 of the paper) -------------------
   --
   --  network and global_database make the agent's team network and its
   --  replicated database; annealer and bidder choose its allocation; the
   --  team_member / team_operator of the same agent, started after them, use
   --  what they made (and make their own when the agent has none).

   type Parts is record
      Has_Net  : Boolean := False;
      Team     : Unbounded_String;
      Lease    : Duration := 1.0;
      Groups   : Unbounded_String;
      --  The network component's settings.
      Has_Db   : Boolean := False;
      Net      : Networks.Network_Access;
      Db       : Replicated_Databases.Team_Database_Access;
      --  Made by the agent's team_member / team_operator (or by the network
      --  component itself when the agent has neither).
      Has_How  : Boolean := False;
      How      : Agents.Method := Agents.Annealing;
      Budget   : Duration := 0.25;
      Rounds   : Natural := 3;
   end record;

   package Part_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Parts);

   protected Registry is
      procedure Update
        (Agent_Id : String; Process : not null access procedure (P : in out Parts));
      function Get (Agent_Id : String) return Parts;
   private
      Known : Part_Maps.Map;
   end Registry;

   protected body Registry is
      procedure Update
        (Agent_Id : String; Process : not null access procedure (P : in out Parts)) is
         P : Parts := (if Known.Contains (Agent_Id) then Known (Agent_Id) else (others => <>));
      begin
         Process (P);
         Known.Include (Agent_Id, P);
      end Update;

      function Get (Agent_Id : String) return Parts is
        (if Known.Contains (Agent_Id) then Known (Agent_Id) else (others => <>));
   end Registry;

   procedure Make_Parts (Agent_Id : String; Net : out Networks.Network_Access;
                         Db : out Replicated_Databases.Team_Database_Access) is
      --  The agent's network and database (not started) from the network
      --  component's settings, registered for the other components.
      P : constant Parts := Registry.Get (Agent_Id);

      procedure Set (Q : in out Parts) is
      begin
         Q.Net := Net;
         Q.Db := Db;
      end Set;
   begin
      Net := Networks.Create (Agent_Id, Groups => To_String (P.Groups), Lease => P.Lease,
                              Team => To_String (P.Team));
      Db := null;
      if P.Has_Db then
         Db := new Replicated_Databases.Team_Database (Net);
         Db.Attach;
      end if;
      Registry.Update (Agent_Id, Set'Access);
   end Make_Parts;

   function Check_Lease (Text : String) return String;

   --  network: the agent's team network (Sancta.Team.Networks).

   type Network_Component is new Base_Component with null record;

   overriding procedure Start (This : in out Network_Component);
   overriding procedure Stop (This : in out Network_Component);
   overriding procedure Run (This : in out Network_Component; Next : in out Clocks.Time);

   overriding procedure Start (This : in out Network_Component) is
      Groups : constant String := This.Option_Text ("groups");

      procedure Set (P : in out Parts) is
      begin
         P.Has_Net := True;
         P.Team := To_Unbounded_String (This.Option_Text ("team"));
         P.Lease := Ada.Real_Time.To_Duration (This.Option_Duration ("lease"));
         P.Groups := To_Unbounded_String
           (if Groups /= "" then Groups
            elsif To_String (This.Ctx.Agent_Kind) = "operator" then "operators"
            else "robots");
      end Set;
   begin
      Registry.Update (This.Agent_Id, Set'Access);
   end Start;

   overriding procedure Stop (This : in out Network_Component) is
      Net : constant Networks.Network_Access := Registry.Get (This.Agent_Id).Net;
   begin
      if Net /= null then
         Net.Stop;
      end if;
      Base_Component (This).Stop;
   end Stop;

   overriding procedure Run (This : in out Network_Component; Next : in out Clocks.Time) is
      Net  : Networks.Network_Access := Registry.Get (This.Agent_Id).Net;
      Db   : Replicated_Databases.Team_Database_Access;
      Text : Unbounded_String;
   begin
      Next := Next + Ada.Real_Time.Milliseconds (500);
      if Net = null then
         --  No team_member / team_operator in this agent: the network (and
         --  the database) on their own.
         Make_Parts (This.Agent_Id, Net, Db);
         Net.Start;
      end if;
      for M of Net.Members loop
         Append (Text, (if Text = Null_Unbounded_String then "" else ",") & M);
      end loop;
      This.Output ("members", Values.To_Value (To_String (Text)));
   end Run;

   function Create_Network is new Factory.Create_Component (Network_Component);

   --  global_database: the replicated team database (Sancta.Team.Replicated_Databases).

   type Database_Component is new Base_Component with record
      Last_Size : Integer := -1;
      Pending   : Networks.Name_Vectors.Vector;
      --  Puts before the database is made.
   end record;

   overriding procedure Start (This : in out Database_Component);
   overriding procedure Run (This : in out Database_Component; Next : in out Clocks.Time);
   overriding procedure On_Input
     (This : in out Database_Component; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Database_Component) is
      procedure Set (P : in out Parts) is
      begin
         if not P.Has_Net then
            raise Constraint_Error with "global_database: agent " & This.Agent_Id
              & " has no network component before it";
         end if;
         P.Has_Db := True;
      end Set;
   begin
      Registry.Update (This.Agent_Id, Set'Access);
      This.Subscribe ("put");
   end Start;

   procedure Put
     (Db : Replicated_Databases.Team_Database_Access; Text : String; This : Database_Component)
   is
      Eq : constant Natural := Ada.Strings.Fixed.Index (Text, "=");
   begin
      if Eq <= Text'First or else not Networks.Is_Key (Text (Text'First .. Eq - 1)) then
         This.Log (Logging.Warning, "put: expected KEY=VALUE, found '" & Text & "'");
      else
         Db.Put (Text (Text'First .. Eq - 1), Text (Eq + 1 .. Text'Last));
      end if;
   end Put;

   overriding procedure On_Input
     (This : in out Database_Component; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
      Db : constant Replicated_Databases.Team_Database_Access := Registry.Get (This.Agent_Id).Db;
   begin
      if Db = null then
         This.Pending.Append (To_Unbounded_String (Item.Image));
      else
         Put (Db, Item.Image, This);
      end if;
   end On_Input;

   overriding procedure Run (This : in out Database_Component; Next : in out Clocks.Time) is
      Db : constant Replicated_Databases.Team_Database_Access := Registry.Get (This.Agent_Id).Db;
   begin
      Next := Next + Ada.Real_Time.Milliseconds (250);
      if Db = null then
         return;
      end if;
      for Text of This.Pending loop
         Put (Db, To_String (Text), This);
      end loop;
      This.Pending.Clear;
      declare
         Size : constant Natural := Natural (Db.Keys.Length);
      begin
         if Size /= This.Last_Size then
            This.Last_Size := Size;
            This.Output ("size", Values.Integer_Value'(Data => Long_Long_Integer (Size)));
         end if;
      end;
   end Run;

   function Create_Database is new Factory.Create_Component (Database_Component);

   --  annealer, bidder: the agent's allocation method.

   procedure Choose_Allocator (This : Base_Component'Class; How : Agents.Method) is
      procedure Set (P : in out Parts) is
      begin
         if P.Has_How then
            raise Constraint_Error with "agent " & This.Agent_Id
              & " has two allocators (annealer, bidder): keep one";
         end if;
         P.Has_How := True;
         P.How := How;
         if How = Agents.Annealing then
            P.Budget := Ada.Real_Time.To_Duration (This.Option_Duration ("budget"));
            P.Rounds := Natural (This.Option_Integer ("rounds"));
         end if;
      end Set;
   begin
      Registry.Update (This.Agent_Id, Set'Access);
   end Choose_Allocator;

   type Annealer_Component is new Base_Component with null record;
   type Bidder_Component is new Base_Component with null record;

   overriding procedure Start (This : in out Annealer_Component);
   overriding procedure Start (This : in out Bidder_Component);

   overriding procedure Start (This : in out Annealer_Component) is
   begin
      Choose_Allocator (This, Agents.Annealing);
   end Start;

   overriding procedure Start (This : in out Bidder_Component) is
   begin
      Choose_Allocator (This, Agents.Auctions);
   end Start;

   function Create_Annealer is new Factory.Create_Component (Annealer_Component);
   function Create_Bidder is new Factory.Create_Component (Bidder_Component);

   function Agent_Of
     (This : Base_Component'Class; Config : Agents.Agent_Config) return Agents.Agent_Access
   is
      --  The team agent on the parts the agent's components declare, or on
      --  its own network and database when it has none.
      P   : constant Parts := Registry.Get (This.Agent_Id);
      C   : Agents.Agent_Config := Config;
      Net : Networks.Network_Access;
      Db  : Replicated_Databases.Team_Database_Access;
   begin
      if P.Has_How then
         C.How := P.How;
         C.Budget := P.Budget;
         C.Rounds := P.Rounds;
      end if;
      if not P.Has_Net then
         return Agents.Create (C);
      elsif not P.Has_Db then
         raise Constraint_Error with "agent " & This.Agent_Id
           & ": a network component needs a global_database component after it";
      end if;
      C.Lease := P.Lease;
      C.Team := P.Team;
      Make_Parts (This.Agent_Id, Net, Db);
      return Agents.Create (C, Net, Db);
   end Agent_Of;

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
      This.Agent := Agent_Of
        (This, (Id       => To_Unbounded_String (This.Agent_Id),
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
      This.Agent := Agent_Of
        (This, (Id       => To_Unbounded_String (This.Agent_Id),
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

   procedure Register_Bidder (Name : String) is
   begin
      Factory.Register
        ((Name    => To_Unbounded_String (Name),
          Doc     => To_Unbounded_String
                       ("allocation by sequential single-item auctions for the agent's"
                        & " team_member" & (if Name = "auctions" then " (the bidder's other name)"
                                            else "")),
          Ports   => Port_Vectors.Empty_Vector,
          Options => Option_Vectors.Empty_Vector,
          others  => <>),
         Create_Bidder'Access);
   end Register_Bidder;

begin
   Factory.Register
     ((Name    => To_Unbounded_String ("network"),
       Doc     => To_Unbounded_String
                    ("the agent's team network: messages, presence and DDS liveliness"
                     & " on /sancta/<team>/"),
       Ports   => Port_Vectors.Empty_Vector
                    & Out_Port ("members", "types.string",
                                "ids of the members heard (itself included), e.g. ""operator,r1"""),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("team", Text_Option, "team")
                    & Make_Option ("lease", Duration_Option, "1.0", Check => Check_Lease'Access)
                    & Make_Option ("groups", Text_Option, "",
                                   Doc => "comma-separated; default robots, or operators"
                                          & " for an operator agent"),
       others  => <>),
      Create_Network'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("global_database"),
       Doc     => To_Unbounded_String
                    ("the replicated team database on the agent's network (after it)"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("put", "types.string", Optional => True,
                               Doc => """key=value"": written to the team database")
                    & Out_Port ("size", "types.integer", "keys held by this replica"),
       Options => Option_Vectors.Empty_Vector,
       others  => <>),
      Create_Database'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("annealer"),
       Doc     => To_Unbounded_String
                    ("allocation by distributed annealing for the agent's team_member"),
       Ports   => Port_Vectors.Empty_Vector,
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("budget", Duration_Option, "0.25",
                                   Doc => "wall-clock seconds per annealing attempt")
                    & Make_Option ("rounds", Integer_Option, "3",
                                   Doc => "improvement attempts from the best proposal"),
       others  => <>),
      Create_Annealer'Access);
   Register_Bidder ("bidder");
   Register_Bidder ("auctions");
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
end Sancta.Team.Team_Components;
