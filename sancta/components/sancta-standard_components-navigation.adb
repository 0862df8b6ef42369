with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Sancta.Standard_Components.Robot_Messages;
with Sancta.Standard_Components.ROS2;
with Sancta.Logging;
with Sancta.Robot.Controllers;
with Sancta.Robot.Goal_Sequencers;
with Sancta.Robot.Path_Costs;
with Sancta.Robot.Sensors;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Worlds;

package body Sancta.Standard_Components.Navigation is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;

   package RM renames Sancta.Standard_Components.Robot_Messages;

   function Pose_Of (Item : Values.Value'Class) return Pose is (Values.Pose_Value (Item).Data);

   procedure Put_Pose (This : in out Component'Class; Data : String; P : Pose) is
   begin
      This.Output (Data, Values.Pose_Value'(Data => P));
   end Put_Pose;

   function Real_Option (This : Component'Class; Name : String) return Real is
     (Real (This.Option_Real (Name)));

   -----------------
   -- transformer --
   -----------------

   type Transformer is new Base_Component with null record;

   overriding procedure Start (This : in out Transformer);
   overriding procedure On_Input
     (This : in out Transformer; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Transformer) is
   begin
      This.Subscribe ("pose");
   end Start;

   overriding procedure On_Input
     (This : in out Transformer; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
      Origin : constant Pose :=
        (if This.Has_Input ("origin") and then This.Has_Value ("origin")
         then Pose_Of (This.Input ("origin"))
         else (Real_Option (This, "x"), Real_Option (This, "y"), Real_Option (This, "yaw")));
   begin
      Put_Pose (This, "pose", Compose (Origin, Pose_Of (Item)));
   end On_Input;

   function Create_Transformer is new Factory.Create_Component (Transformer);

   --------------
   -- executor --
   --------------

   type Executor is new Base_Component with record
      Plan      : Robot.Goal_Sequencers.Sequencer;
      Tolerance : Real := 0.3;
      Last_Goal : Integer := -1;
      Last_Done : Integer := -1;
   end record;

   overriding procedure Start (This : in out Executor);
   overriding procedure On_Input
     (This : in out Executor; Data : String; Item : Values.Value'Class);

   procedure Assign (This : in out Executor'Class; Text : String) is
   begin
      This.Plan.Assign (RM.Parse_Goals (Text), This.Tolerance);
      This.Last_Goal := -1;
      This.Last_Done := -1;
      This.Log (Logging.Info, "task list: " & Text);
   exception
      when E : RM.Goal_Error =>
         This.Log (Logging.Error, "task list ignored: " & Ada.Exceptions.Exception_Message (E));
   end Assign;

   procedure Report (This : in out Executor'Class) is
      P : Robot.Goal_Sequencers.Sequencer renames This.Plan;
   begin
      if P.Completed /= This.Last_Done then
         This.Last_Done := P.Completed;
         This.Output ("completed", Values.Integer_Value'(Data => Long_Long_Integer (P.Completed)));
         This.Output ("progress", Values.Real_Value'(Data => Long_Float (P.Progress)));
         This.Output ("done", Values.Boolean_Value'(Data => P.Is_Done));
         if P.Is_Done then
            This.Output ("status", Values.To_Value
                           ((if P.Total = 0 then "no task"
                             else "done" & P.Completed'Image & " /" & P.Total'Image)));
            This.Log (Logging.Info, "all" & P.Total'Image & " goals done");
         end if;
      end if;
      if P.Has_Goal and then P.Goal_Index /= This.Last_Goal then
         This.Last_Goal := P.Goal_Index;
         declare
            G : constant Point := P.Current_Goal;
            Text : constant String := "goal" & P.Goal_Index'Image & " /" & P.Total'Image
              & " (" & RM.Goals_Image ([G]) & ")";
         begin
            This.Output ("status", Values.To_Value (Text));
            This.Log (Logging.Info, Text);
         end;
      end if;
      if P.Has_Goal then
         Put_Pose (This, "goal", (P.Current_Goal.X, P.Current_Goal.Y, 0.0));
      end if;
   end Report;

   overriding procedure Start (This : in out Executor) is
   begin
      This.Tolerance := Real_Option (This, "tolerance");
      Assign (This, This.Option_Text ("goals"));
      This.Subscribe ("pose");
      This.Subscribe ("tasks");
   end Start;

   overriding procedure On_Input
     (This : in out Executor; Data : String; Item : Values.Value'Class) is
   begin
      if Data = "tasks" then
         Assign (This, To_String (Values.String_Value (Item).Data));
      else
         This.Plan.Update (Pose_Of (Item));
         Report (This);
      end if;
   end On_Input;

   function Create_Executor is new Factory.Create_Component (Executor);

   ----------------
   -- path_costs --
   ----------------

   type Planner_Access is access all Robot.Path_Costs.Planner;

   package Planner_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Planner_Access);

   protected Planners is
      procedure Add (Agent : String; Map : Planner_Access);
      procedure Remove (Agent : String);
      procedure Cost (Agent : String; From, To : Point; Result : out Real; Found : out Boolean);
      procedure Path (Agent : String; From, To : Point;
                      Result : out Robot.Path_Costs.Point_Vectors.Vector);
      procedure Sight (Agent : String; A, B : Point; Result : out Boolean);
   private
      Maps : Planner_Maps.Map;
   end Planners;
   --  A planner is not for concurrent use: every query goes through here.

   protected body Planners is
      procedure Add (Agent : String; Map : Planner_Access) is
      begin
         Maps.Include (Agent, Map);
      end Add;

      procedure Remove (Agent : String) is
      begin
         Maps.Exclude (Agent);
      end Remove;

      procedure Cost (Agent : String; From, To : Point; Result : out Real; Found : out Boolean) is
      begin
         Found := Maps.Contains (Agent);
         Result := (if Found then Robot.Path_Costs.Cost (Maps (Agent).all, From, To)
                    else Robot.Path_Costs.Unreachable);
      end Cost;

      procedure Path (Agent : String; From, To : Point;
                      Result : out Robot.Path_Costs.Point_Vectors.Vector) is
      begin
         Result := Robot.Path_Costs.Path (Maps (Agent).all, From, To);
      end Path;

      procedure Sight (Agent : String; A, B : Point; Result : out Boolean) is
      begin
         Result := Robot.Path_Costs.Line_Of_Sight (Maps (Agent).all, A, B);
      end Sight;
   end Planners;

   function Cost_Of (Agent : String; From, To : Point) return Real is
      Result : Real;
      Found  : Boolean;
   begin
      Planners.Cost (Agent, From, To, Result, Found);
      if not Found then
         raise Program_Error with "agent " & Agent & " has no running path_costs component";
      end if;
      return Result;
   end Cost_Of;

   type Path_Cost is new Base_Component with record
      Map      : Planner_Access;
      Goal     : Point;
      Has_Goal : Boolean := False;
      Path     : Robot.Path_Costs.Point_Vectors.Vector;
      Next     : Positive := 1;
   end record;

   overriding procedure Start (This : in out Path_Cost);
   overriding procedure Stop (This : in out Path_Cost);
   overriding procedure On_Input
     (This : in out Path_Cost; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Path_Cost) is
      Name : constant String := This.Option_Text ("world");
      File : constant String := Simulation.Map_Files.World_File (Name);
   begin
      if File = "" then
         raise Constraint_Error with "world " & Name & ": no such file or bundled world";
      end if;
      declare
         World : constant Simulation.Worlds.World := Simulation.Map_Files.Load_World (File);
      begin
         This.Map := new Robot.Path_Costs.Planner;
         This.Map.Initialize (Simulation.Worlds.Occupancy (World),
                              Real_Option (This, "robot_radius"));
      end;
      Planners.Add (This.Agent_Id, This.Map);
      This.Subscribe ("goal");
      This.Subscribe ("pose");
   end Start;

   overriding procedure Stop (This : in out Path_Cost) is
   begin
      Base_Component (This).Stop;
      Planners.Remove (This.Agent_Id);
   end Stop;

   overriding procedure On_Input
     (This : in out Path_Cost; Data : String; Item : Values.Value'Class)
   is
      P : constant Pose := Pose_Of (Item);
   begin
      if Data = "goal" then
         if not This.Has_Goal or else Distance (This.Goal, Position (P)) > 1.0E-6 then
            This.Goal := Position (P);
            This.Has_Goal := True;
            This.Path.Clear;
            This.Next := 1;
            if This.Has_Value ("pose") then
               declare
                  Here : constant Point := Position (Pose_Of (This.Input ("pose")));
                  Cost : Real;
                  Found : Boolean;
               begin
                  Planners.Path (This.Agent_Id, Here, This.Goal, This.Path);
                  Planners.Cost (This.Agent_Id, Here, This.Goal, Cost, Found);
                  This.Output ("cost", Values.Real_Value'
                                 (Data => (if Cost = Robot.Path_Costs.Unreachable then -1.0
                                           else Long_Float (Cost))));
                  if This.Path.Is_Empty then
                     This.Log (Logging.Warning, "goal " & RM.Goals_Image ([This.Goal])
                               & " unreachable on the map: heading straight for it");
                  end if;
               end;
            end if;
         end if;
      elsif This.Has_Goal then
         --  Advance along the path: skip waypoints reached or in sight.
         declare
            Here  : constant Point := Position (P);
            Sight : Boolean;
         begin
            while This.Next < Natural (This.Path.Length) loop
               if Distance (Here, This.Path (This.Next)) < 0.4 then
                  This.Next := This.Next + 1;
               else
                  Planners.Sight (This.Agent_Id, Here, This.Path (This.Next + 1), Sight);
                  exit when not Sight;
                  This.Next := This.Next + 1;
               end if;
            end loop;
            declare
               W : constant Point :=
                 (if This.Path.Is_Empty then This.Goal else This.Path (This.Next));
            begin
               Put_Pose (This, "waypoint", (W.X, W.Y, 0.0));
            end;
         end;
      end if;
   end On_Input;

   function Create_Path_Cost is new Factory.Create_Component (Path_Cost);

   ----------------
   -- go_to_goal --
   ----------------

   type Go_To_Goal is new Base_Component with record
      Config : Robot.Controllers.Controller_Config;
   end record;

   overriding procedure Start (This : in out Go_To_Goal);
   overriding procedure On_Input
     (This : in out Go_To_Goal; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Go_To_Goal) is
   begin
      This.Config :=
        (Max_Linear     => Real_Option (This, "max_linear"),
         Max_Angular    => Real_Option (This, "max_angular"),
         Robot_Radius   => Real_Option (This, "radius"),
         Margin         => Real_Option (This, "margin"),
         Goal_Tolerance => Real_Option (This, "tolerance"),
         Look_Ahead     => Real_Option (This, "look_ahead"),
         others         => <>);
      This.Subscribe ("scan");
   end Start;

   overriding procedure On_Input
     (This : in out Go_To_Goal; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
      Command : Robot.Sensors.Twist := (0.0, 0.0);
      Reached : Boolean := True;
   begin
      if This.Has_Value ("pose") and then This.Has_Input ("goal") and then This.Has_Value ("goal")
      then
         declare
            Here : constant Pose := Pose_Of (This.Input ("pose"));
            Goal : constant Point := Position (Pose_Of (This.Input ("goal")));
         begin
            Reached := Robot.Controllers.Reached (This.Config, Here, Goal);
            Command := Robot.Controllers.Command
              (This.Config, Here, Goal, RM.To_Scan (ROS2.Message_Value (Item).Message));
         end;
      end if;
      This.Output ("cmd_vel", ROS2.Message_Value'(Message => RM.Twist_Message (Command)));
      This.Output ("reached", Values.Boolean_Value'(Data => Reached));
   end On_Input;

   function Create_Go_To_Goal is new Factory.Create_Component (Go_To_Goal);

   function Positive_Check (Text : String) return String is
     (if Long_Float'Value (Text) > 0.0 then "" else "expected a positive value, found " & Text);

   function World_Check (Text : String) return String is
     (if Simulation.Map_Files.World_File (Text) /= "" then ""
      else "no such world file or bundled world: '" & Text & "'");

   function Goals_Check (Text : String) return String is (RM.Goals_Problem (Text));

   function Opt (Name : String; Default : String; Check : Option_Check := Positive_Check'Access)
     return Option_Spec is (Make_Option (Name, Real_Option, Default, Check => Check));

begin
   Factory.Register
     ((Name    => To_Unbounded_String ("transformer"),
       Doc     => To_Unbounded_String ("robot pose from its odometry frame to the world frame"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose", Doc => "robot in the odometry frame")
                    & In_Port ("origin", "types.pose", Optional => True,
                               Doc => "odometry frame in the world")
                    & Out_Port ("pose", "types.pose", Doc => "robot in the world"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("x", Real_Option, "0.0")
                    & Make_Option ("y", Real_Option, "0.0")
                    & Make_Option ("yaw", Real_Option, "0.0"),
       others  => <>),
      Create_Transformer'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("executor"),
       Doc     => To_Unbounded_String ("task list to successive goals, progress"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose")
                    & In_Port ("tasks", "types.string", Optional => True,
                               Doc => "x1,y1; x2,y2; ...")
                    & Out_Port ("goal", "types.pose")
                    & Out_Port ("progress", "types.real")
                    & Out_Port ("completed", "types.integer")
                    & Out_Port ("done", "types.boolean")
                    & Out_Port ("status", "types.string"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("goals", Text_Option, "", Check => Goals_Check'Access)
                    & Opt ("tolerance", "0.3"),
       others  => <>),
      Create_Executor'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("path_costs"),
       Doc     => To_Unbounded_String ("A* path costs and waypoints on a world map"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose")
                    & In_Port ("goal", "types.pose")
                    & Out_Port ("waypoint", "types.pose")
                    & Out_Port ("cost", "types.real"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("world", Text_Option, Required => True,
                                   Check => World_Check'Access)
                    & Opt ("robot_radius", "0.25"),
       others  => <>),
      Create_Path_Cost'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("go_to_goal"),
       Doc     => To_Unbounded_String ("go-to-goal control with laser obstacle avoidance"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose")
                    & In_Port ("scan", RM.Scan_Type)
                    & In_Port ("goal", "types.pose", Optional => True)
                    & Out_Port ("cmd_vel", RM.Twist_Type)
                    & Out_Port ("reached", "types.boolean"),
       Options => Option_Vectors.Empty_Vector
                    & Opt ("max_linear", "0.5")
                    & Opt ("max_angular", "1.5")
                    & Opt ("radius", "0.2")
                    & Opt ("margin", "0.12")
                    & Opt ("tolerance", "0.2")
                    & Opt ("look_ahead", "1.0"),
       others  => <>),
      Create_Go_To_Goal'Access);
end Sancta.Standard_Components.Navigation;
