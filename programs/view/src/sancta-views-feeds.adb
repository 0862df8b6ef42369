with Ada.Containers.Indefinite_Holders;
with Ada.Containers.Indefinite_Vectors;
with Ada.Exceptions;
with Ada.Numerics.Generic_Elementary_Functions;
with Interfaces;
with RCL.Contexts;
with RCL.Nodes;
with RCL.QoS;
with ROSIDL;
with ROSIDL.Definitions;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Sancta.Geometry;
with Sancta.Robot.Grids;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Worlds;
with Sancta.Team.Agents;
with Sancta.Team.Missions;

package body Sancta.Views.Feeds is

   use Sancta.Geometry;
   use ROSIDL.Dynamic;
   use type Sancta.Team.Agents.Agent_Access;
   use type Interfaces.Unsigned_32;
   use type ROSIDL.Definitions.Element_Kind;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   --  Requests of the operator (from the window's task) ---------------------

   type Request_Kind is (Control, Mission, Scans);
   type Request (Length : Natural) is record
      Kind  : Request_Kind;
      Robot : Unbounded_String;
      Text  : String (1 .. Length);
      --  The command, or the mission file.
   end record;
   package Request_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Request);

   protected Requests is
      procedure Add (R : Request);
      procedure Take (Found : out Boolean; Holder : out Request_Vectors.Vector);
      procedure Ask_Stop;
      function Stopping return Boolean;
   private
      Queue     : Request_Vectors.Vector;
      Stop_Flag : Boolean := False;
   end Requests;

   protected body Requests is
      procedure Add (R : Request) is
      begin
         Queue.Append (R);
      end Add;

      procedure Take (Found : out Boolean; Holder : out Request_Vectors.Vector) is
      begin
         Found := not Queue.Is_Empty;
         Holder := Queue;
         Queue.Clear;
      end Take;

      procedure Ask_Stop is
      begin
         Stop_Flag := True;
      end Ask_Stop;

      function Stopping return Boolean is (Stop_Flag);
   end Requests;

   procedure Request_Control (Command, Robot : String) is
   begin
      Requests.Add ((Command'Length, Control, To_Unbounded_String (Robot), Command));
   end Request_Control;

   procedure Request_Mission (File : String) is
   begin
      Requests.Add ((File'Length, Mission, Null_Unbounded_String, File));
   end Request_Mission;

   procedure Show_Scans is
   begin
      Requests.Add ((0, Scans, Null_Unbounded_String, ""));
   end Show_Scans;

   --  Decoding --------------------------------------------------------------

   Invalid : constant Real := 1.0E300;
   --  Stands for NaN and infinities (Scenes drops coordinates beyond 1e6).

   function Element_Of (A : Float64_Array; K : Positive) return Real is
     (if A (K)'Valid then Real (A (K)) else Invalid);
   function Element_Of (A : Float32_Array; K : Positive) return Real is
     (if A (K)'Valid then Real (A (K)) else Invalid);

   function Float_Of (F : Field_Ref) return Real;
   --  Non-finite floats are read without reading them as numbers
   --  (validity checks of the debug build would raise on a copy).

   function Float_Of (F : Field_Ref) return Real is
   begin
      if Field_Type_Of (F).Kind = ROSIDL.Definitions.Float32_Kind then
         declare
            R : constant Float32_Ref := F.As_Float32;
         begin
            return (if R.Element.all'Valid then Real (R.Element.all) else Invalid);
         end;
      else
         declare
            R : constant Float64_Ref := F.As_Float64;
         begin
            return (if R.Element.all'Valid then Real (R.Element.all) else Invalid);
         end;
      end if;
   end Float_Of;

   function Strings_Of (F : Field_Ref) return Scenes.Text_Vectors.Vector is
      List   : constant Array_Ref := F.As_Array;
      Result : Scenes.Text_Vectors.Vector;
   begin
      for I in 1 .. Natural'Min (List.Length, Scenes.Max_Tasks) loop
         Result.Append (List.Element (I).Get_String);
      end loop;
      return Result;
   end Strings_Of;

   procedure On_Robot
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
      S : Scenes.Robot_Sample;
   begin
      S.Robot := To_Unbounded_String (Msg ("robot").Get_String);
      S.Where := (Float_Of (Msg ("x")), Float_Of (Msg ("y")), Float_Of (Msg ("yaw")));
      S.Status := To_Unbounded_String (Msg ("status").Get_String);
      S.Current_Task := To_Unbounded_String (Msg ("current_task").Get_String);
      S.Round := Natural (ROSIDL.UInt32'(Msg ("round").As_UInt32) mod 2 ** 30);
      S.Plan_Round := Natural (ROSIDL.UInt32'(Msg ("plan_round").As_UInt32) mod 2 ** 30);
      S.Done := Strings_Of (Msg ("done"));
      S.Tour := Strings_Of (Msg ("tour"));
      for C of Msg ("choices").Get_UInt32_Array loop
         S.Choices.Append (Positive (ROSIDL.UInt32'Max (1, C) mod 2 ** 30));
      end loop;
      S.Planned_Cost := Float_Of (Msg ("planned_cost"));
      S.Distance := Float_Of (Msg ("distance"));
      Scene_Store.Update_Robot (S);
   end On_Robot;

   procedure On_Plan
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
      S     : Scenes.Plan_Sample;
      Tasks : constant Array_Ref := Msg ("tasks").As_Array;
   begin
      S.Team := To_Unbounded_String (Msg ("team").Get_String);
      S.Source := To_Unbounded_String (Msg ("source").Get_String);
      S.Round := Natural (ROSIDL.UInt32'(Msg ("round").As_UInt32) mod 2 ** 30);
      S.Plan_Round := Natural (ROSIDL.UInt32'(Msg ("plan_round").As_UInt32) mod 2 ** 30);
      S.Proposer := To_Unbounded_String (Msg ("proposer").Get_String);
      S.Makespan := Float_Of (Msg ("makespan"));
      S.Total := Float_Of (Msg ("total_cost"));
      S.Robots := Strings_Of (Msg ("robots"));
      if Tasks.Length > Scenes.Max_Tasks then
         Scene_Store.Reject ("a TeamPlan of more than" & Scenes.Max_Tasks'Image & " tasks");
         return;
      end if;
      for I in 1 .. Tasks.Length loop
         declare
            E  : constant Field_Ref := Tasks.Element (I);
            Xs : constant Float64_Array := E ("x").Get_Float64_Array;
            Ys : constant Float64_Array := E ("y").Get_Float64_Array;
            T  : Scenes.Task_Sample;
         begin
            if Xs'Length /= Ys'Length then
               Scene_Store.Reject ("a task whose x and y differ in length ("
                                   & E ("id").Get_String & ")");
            else
               T.Id := To_Unbounded_String (E ("id").Get_String);
               T.Kind := To_Unbounded_String (E ("kind").Get_String);
               for K in 0 .. Natural'Min (Xs'Length, Scenes.Max_Points + 1) - 1 loop
                  T.Points.Append (Point'(Element_Of (Xs, Xs'First + K),
                                          Element_Of (Ys, Ys'First + K)));
               end loop;
               T.Choice := Natural (ROSIDL.UInt32'(E ("choice").As_UInt32) mod 2 ** 30);
               T.State := To_Unbounded_String (E ("state").Get_String);
               T.Robot := To_Unbounded_String (E ("robot").Get_String);
               S.Tasks.Append (T);
            end if;
         end;
      end loop;
      Scene_Store.Update_Plan (S);
   end On_Plan;

   procedure On_Event
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      Scene_Store.Sim_Event (Msg ("data").Get_String);
   end On_Event;

   procedure On_Map
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
      Width  : constant ROSIDL.UInt32 := Msg ("info")("width").As_UInt32;
      Height : constant ROSIDL.UInt32 := Msg ("info")("height").As_UInt32;
      Cell   : constant Real := Float_Of (Msg ("info")("resolution"));
      Origin : constant Point :=
        (Float_Of (Msg ("info")("origin")("position")("x")),
         Float_Of (Msg ("info")("origin")("position")("y")));
      Data   : constant Int8_Array := Msg ("data").Get_Int8_Array;
      use type ROSIDL.Int8;
   begin
      if Width = 0 or else Height = 0 or else Width > 8_000 or else Height > 8_000
        or else Data'Length /= Natural (Width) * Natural (Height)
        or else not (Cell > 0.0 and then Cell < 100.0)
        or else not (abs Origin.X < 1.0E6 and then abs Origin.Y < 1.0E6)
      then
         Scene_Store.Reject ("an OccupancyGrid whose size, resolution or origin is out of range");
         return;
      end if;
      declare
         type Grid_Writer is access Sancta.Robot.Grids.Grid;
         G : constant Grid_Writer :=
           new Sancta.Robot.Grids.Grid (Integer (Width) - 1, Integer (Height) - 1);
      begin
         G.Origin := Origin;
         G.Resolution := Cell;
         for J in 0 .. Integer (Height) - 1 loop
            for I in 0 .. Integer (Width) - 1 loop
               G.Occupied (I, J) := Data (Data'First + J * Integer (Width) + I) >= 50;
            end loop;
         end loop;
         Scene_Store.Set_Map (G.all'Unchecked_Access);
      end;
   end On_Map;

   --  Laser scans: one subscription per robot, in slots -------------------

   Max_Scan_Slots : constant := 16;
   package Name_Holders is new Ada.Containers.Indefinite_Holders (String);
   Slot_Robot : array (1 .. Max_Scan_Slots) of Name_Holders.Holder;

   procedure On_Scan (Slot : Positive; Msg : Message) is
      Ranges    : constant Float32_Array := Msg ("ranges").Get_Float32_Array;
      Angle     : constant Real := Float_Of (Msg ("angle_min"));
      Increment : constant Real := Float_Of (Msg ("angle_increment"));
      Max_Range : constant Real := Float_Of (Msg ("range_max"));
      Step      : constant Positive := Positive'Max (1, Ranges'Length / 180);
      Hits      : Scenes.Point_Vectors.Vector;
      K         : Natural := 0;
   begin
      if Ranges'Length > 100_000 or else not (abs Angle < 10.0 and then abs Increment < 1.0) then
         Scene_Store.Reject ("a LaserScan out of range");
         return;
      end if;
      while K < Ranges'Length loop
         declare
            R : constant Real := Element_Of (Ranges, Ranges'First + K);
            A : constant Real := Angle + Real (K) * Increment;
         begin
            if R > 0.0 and then R < Max_Range and then R < 1000.0 then
               Hits.Append (Point'(R * Math.Cos (A), R * Math.Sin (A)));
            end if;
         end;
         K := K + Step;
      end loop;
      Scene_Store.Update_Scan (Slot_Robot (Slot).Element, Hits);
   end On_Scan;

   generic
      Slot : Positive;
   procedure Scan_Callback
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info);

   procedure Scan_Callback
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      On_Scan (Slot, Msg);
   end Scan_Callback;

   procedure S1 is new Scan_Callback (1);
   procedure S2 is new Scan_Callback (2);
   procedure S3 is new Scan_Callback (3);
   procedure S4 is new Scan_Callback (4);
   procedure S5 is new Scan_Callback (5);
   procedure S6 is new Scan_Callback (6);
   procedure S7 is new Scan_Callback (7);
   procedure S8 is new Scan_Callback (8);
   procedure S9 is new Scan_Callback (9);
   procedure S10 is new Scan_Callback (10);
   procedure S11 is new Scan_Callback (11);
   procedure S12 is new Scan_Callback (12);
   procedure S13 is new Scan_Callback (13);
   procedure S14 is new Scan_Callback (14);
   procedure S15 is new Scan_Callback (15);
   procedure S16 is new Scan_Callback (16);

   type Callback_Access is access procedure
     (Node : in out RCL.Nodes.Node'Class; Msg : in out Message; Info : ROSIDL.Message_Info);
   Scan_Callbacks : constant array (1 .. Max_Scan_Slots) of Callback_Access :=
     [S1'Access, S2'Access, S3'Access, S4'Access, S5'Access, S6'Access, S7'Access, S8'Access,
      S9'Access, S10'Access, S11'Access, S12'Access, S13'Access, S14'Access, S15'Access,
      S16'Access];

   --  The DDS task ----------------------------------------------------------

   task type Worker is
      entry Go (Config : Feed_Config);
   end Worker;
   type Worker_Access is access Worker;
   Runner : Worker_Access;

   Was_Interrupted : Boolean := False
     with Atomic;

   function Interrupted return Boolean is (Was_Interrupted);

   function Support (Package_Name, Name : String) return ROSIDL.Typesupport.Message_Support
     renames ROSIDL.Typesupport.Get_Message_Support;

   task body Worker is
      Settings : Feed_Config;
      Operator : Sancta.Team.Agents.Agent_Access;
      Scans_On : Boolean := False;
      Slots    : Natural := 0;
   begin
      accept Go (Config : Feed_Config) do
         Settings := Config;
      end Go;
      declare
         Node   : RCL.Nodes.Node := RCL.Nodes.Init ("sancta_view");
         Prefix : constant String := "/sancta/" & To_String (Settings.Team) & "/";

         procedure Call_Control (Command, Robot : String) is
            Service : constant ROSIDL.Typesupport.Service_Support :=
              ROSIDL.Typesupport.Get_Service_Support ("sancta_msgs", "SimControl");
            Request : constant Message :=
              Init (ROSIDL.Typesupport.Request_Support (Service));
         begin
            Request ("command").Set_String (Command);
            Request ("name").Set_String (Robot);
            declare
               Response : constant Message :=
                 Node.Client_Call (Service, "/sancta_sim/control", Request, Timeout => 3.0);
            begin
               Scene_Store.Note ("operator: " & Command & " " & Robot & ": "
                                 & (if Response ("success").As_Bool then "done"
                                    else "refused: " & Response ("message").Get_String));
            end;
         end Call_Control;

         procedure Publish_Mission (File : String) is
            M : constant Sancta.Team.Missions.Mission := Sancta.Team.Missions.Read (File);
         begin
            if Operator = null then
               Operator := Sancta.Team.Agents.Create
                 ((Id       => To_Unbounded_String ("view_operator"),
                   Team     => Settings.Team,
                   Is_Robot => False,
                   Verbose  => False,
                   others   => <>));
            end if;
            Operator.Publish_Mission (M);
            Scene_Store.Note ("operator: mission " & To_String (M.Name) & " ("
                              & Natural'Image (Natural (M.Tasks.Length)) & " tasks) published");
         end Publish_Mission;

         procedure Serve_Requests is
            Found : Boolean;
            Queue : Request_Vectors.Vector;
         begin
            Requests.Take (Found, Queue);
            for R of Queue loop
               begin
                  case R.Kind is
                     when Control => Call_Control (R.Text, To_String (R.Robot));
                     when Mission => Publish_Mission (R.Text);
                     when Scans   => Scans_On := True;
                  end case;
               exception
                  when E : others =>
                     Scene_Store.Note ("operator: " & R.Text & " " & To_String (R.Robot)
                                       & " failed: " & Ada.Exceptions.Exception_Message (E));
               end;
            end loop;
         end Serve_Requests;

         procedure Follow_Scans is
            S : constant Scenes.Scene := Scene_Store.Get;
         begin
            for C in S.Robots.Iterate loop
               declare
                  Id : constant String := Scenes.Robot_Maps.Key (C);
               begin
                  if Slots < Max_Scan_Slots
                    and then (for all K in 1 .. Slots => Slot_Robot (K).Element /= Id)
                  then
                     Slots := Slots + 1;
                     Slot_Robot (Slots) := Name_Holders.To_Holder (Id);
                     Node.Subscribe (Support ("sensor_msgs", "LaserScan"), "/" & Id & "/scan",
                                     Scan_Callbacks (Slots), RCL.QoS.Sensor_Data);
                  end if;
               end;
            end loop;
         end Follow_Scans;

      begin
         Node.Subscribe (Support ("sancta_msgs", "RobotState"), Prefix & "gui/robots",
                         On_Robot'Access);
         Node.Subscribe (Support ("sancta_msgs", "TeamPlan"), Prefix & "gui/plan",
                         On_Plan'Access,
                         (RCL.QoS.Default with delta
                            Depth => 1, Durability => RCL.QoS.Transient_Local));
         Node.Subscribe (Support ("std_msgs", "String"), "/sancta_sim/events", On_Event'Access);
         if Settings.Map_Topic /= Null_Unbounded_String then
            Node.Subscribe (Support ("nav_msgs", "OccupancyGrid"), To_String (Settings.Map_Topic),
                            On_Map'Access,
                            (RCL.QoS.Default with delta
                               Depth => 1, Durability => RCL.QoS.Transient_Local));
         end if;
         loop
            Node.Spin (During => 0.05);
            Scene_Store.Refresh;
            Serve_Requests;
            if Scans_On then
               Follow_Scans;
            end if;
            if RCL.Contexts.Is_Shutdown then
               Was_Interrupted := True;
            end if;
            exit when Requests.Stopping or else Was_Interrupted;
         end loop;
         if Operator /= null then
            Operator.Stop;
         end if;
      end;
   exception
      when E : others =>
         Scene_Store.Note ("DDS task failed: " & Ada.Exceptions.Exception_Information (E));
         Was_Interrupted := True;
   end Worker;

   procedure Start (Config : Feed_Config) is
      World_Name : constant String := To_String (Config.World);
   begin
      Scene_Store.Set_Lost_After (Config.Lost_After);
      if World_Name /= "" then
         declare
            File : constant String := Sancta.Simulation.Map_Files.World_File (World_Name);
         begin
            if File = "" then
               raise Constraint_Error with "--world " & World_Name
                 & ": no such file and no bundled world of that name ("
                 & Sancta.Simulation.Map_Files.Bundled_Worlds & ")";
            end if;
            Scene_Store.Set_Map
              (new Sancta.Robot.Grids.Grid'
                 (Sancta.Simulation.Worlds.Occupancy
                    (Sancta.Simulation.Map_Files.Load_World (File))));
         end;
      end if;
      Runner := new Worker;
      Runner.Go (Config);
   end Start;

   procedure Stop is
   begin
      Requests.Ask_Stop;
      if Runner /= null then
         while not Runner'Terminated loop
            delay 0.05;
         end loop;
      end if;
   end Stop;

end Sancta.Views.Feeds;
