with Ada.Containers;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with RCL.Names;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with ROSIDL;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Sancta.Geometry;
with Sancta.Logging;
with Sancta.Runtime.Clocks;
with Sancta.Team.Agents;
with Sancta.Team.Missions;
with Sancta.Team.Plans;
with Sancta.Team.Interface_Paths;

package body Sancta.Standard_Components.GUI_Relay is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use Sancta.Team;
   use ROSIDL.Dynamic;
   use type Ada.Real_Time.Time;
   use type Agents.Agent_Access;
   use type Plans.Plan;
   use type Ada.Containers.Count_Type;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;

   type Node_Access is access RCL.Nodes.Node;
   type Publisher_Access is access RCL.Publishers.Publisher;
   procedure Free is new Ada.Unchecked_Deallocation (RCL.Nodes.Node, Node_Access);
   procedure Free is new Ada.Unchecked_Deallocation (RCL.Publishers.Publisher, Publisher_Access);

   package Owner_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, String);
   package Round_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Natural);
   package Text_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   type Relay is new Base_Component with record
      Node        : Node_Access;
      Robots_Pub  : Publisher_Access;
      Plan_Pub    : Publisher_Access;
      Markers_Pub : Publisher_Access;
      Path_Pub    : Publisher_Access;
      Agent       : Agents.Agent_Access;
      Period      : Ada.Real_Time.Time_Span;
      Here        : Pose;
      Has_Pose    : Boolean := False;
      Distance    : Real := 0.0;
      Round       : Plans.Snapshot;
      Plan        : Plans.Plan;
      --  The latest adopted plan and its round (kept while a new round
      --  is being planned).
      First_Owner : Owner_Maps.Map;
      --  The robot each task was first planned for: its owner in the last
      --  plan adopted in the first round that planned it (a round's plan
      --  improves as better proposals come: that is not a re-allocation).
      First_Round : Round_Maps.Map;
      --  For each task of First_Owner, the round (generation) that set it.
      Bad_Tasks   : Owner_Maps.Map;
      --  Tasks whose text did not decode (logged once).
      Last_Plan   : Unbounded_String;
      Unchanged   : Natural := 0;
      --  The last TeamPlan's content, and for how many periods it was not
      --  republished (an unchanged plan goes out every Resend periods).
   end record;

   Resend : constant := 8;

   overriding procedure Start (This : in out Relay);
   overriding procedure Stop (This : in out Relay);
   overriding procedure Run (This : in out Relay; Next : in out Clocks.Time);
   overriding procedure On_Input
     (This : in out Relay; Data : String; Item : Values.Value'Class);

   function Node_Name (This : Relay'Class) return String is
     (RCL.Names.Name_Token ("sancta_" & This.Agent_Id & "_gui_relay"));

   function Support (Name : String) return ROSIDL.Typesupport.Message_Support is
   begin
      Sancta.Team.Interface_Paths.Ensure;  --  sancta_msgs on the ROS 2 library's path
      return ROSIDL.Typesupport.Get_Message_Support ("sancta_msgs", Name);
   end Support;

   function Standard_Support (Package_Name, Name : String)
                              return ROSIDL.Typesupport.Message_Support is
     (ROSIDL.Typesupport.Get_Message_Support (Package_Name, Name));

   function Topic_Part (Id : String) return String renames RCL.Names.Name_Token;
   --  An agent id as a topic name token.

   --  Standard visualization messages (RViz, Foxglove) -------------------------

   procedure Set_Point (Target : Field_Ref; P : Point; Z : Real := 0.0) is
   begin
      Target ("x").As_Float64 := ROSIDL.Float64 (P.X);
      Target ("y").As_Float64 := ROSIDL.Float64 (P.Y);
      Target ("z").As_Float64 := ROSIDL.Float64 (Z);
   end Set_Point;

   type Colour is record
      R, G, B : ROSIDL.Float32;
   end record;

   procedure Set_Colour (Target : Field_Ref; C : Colour; Alpha : ROSIDL.Float32 := 1.0) is
   begin
      Target ("r").As_Float32 := C.R;
      Target ("g").As_Float32 := C.G;
      Target ("b").As_Float32 := C.B;
      Target ("a").As_Float32 := Alpha;
   end Set_Colour;

   function State_Colour (State : String) return Colour is
     (if State = "done" then (0.2, 0.7, 0.2)
      elsif State = "active" then (1.0, 0.55, 0.0)
      elsif State = "assigned" then (0.2, 0.4, 0.9)
      elsif State = "reallocated" then (0.85, 0.1, 0.1)
      else (0.6, 0.6, 0.6));
   --  Tasks by state for RViz/Foxglove: pending grey, assigned blue,
   --  active orange, done green, reallocated red. Not sancta-view's
   --  colours (greys and robots' colours, Rendering.Color_Of): these
   --  markers keep their own, checked by test_team_demo.

   Robot_Colours : constant array (0 .. 5) of Colour :=
     [Colour'(0.12, 0.47, 0.71), Colour'(1.0, 0.5, 0.05), Colour'(0.17, 0.63, 0.17),
      Colour'(0.58, 0.4, 0.74), Colour'(0.55, 0.34, 0.29), Colour'(0.89, 0.47, 0.76)];

   Marker_Sphere : constant := 2;
   Marker_Line_Strip : constant := 4;
   Marker_Text : constant := 9;
   Marker_Delete_All : constant := 3;
   --  visualization_msgs/Marker's type and action constants.

   function Step_Points
     (Round : Plans.Snapshot; Step : Plans.Step) return Missions.Point_Vectors.Vector is
      --  Where a tour step takes the robot: the chosen entry, then the exit
      --  when the task is a segment.
      T      : constant Missions.Mission_Task := Plans.Task_Of (Round, To_String (Step.Task_Id));
      Result : Missions.Point_Vectors.Vector;
   begin
      Result.Append (Missions.Entry_Point (T, Step.Choice));
      if Missions.Exit_Point (T, Step.Choice) /= Missions.Entry_Point (T, Step.Choice) then
         Result.Append (Missions.Exit_Point (T, Step.Choice));
      end if;
      return Result;
   exception
      when others =>
         return Missions.Point_Vectors.Empty_Vector;  --  A task the round does not know (yet).
   end Step_Points;

   overriding procedure Start (This : in out Relay) is
      Prefix : constant String := "/sancta/" & This.Option_Text ("team") & "/";
   begin
      This.Period := This.Option_Duration ("period");
      This.Node := new RCL.Nodes.Node'(RCL.Nodes.Init (Node_Name (This)));
      This.Robots_Pub := new RCL.Publishers.Publisher'
        (This.Node.Publish (Support ("RobotState"), Prefix & Robots_Topic));
      This.Plan_Pub := new RCL.Publishers.Publisher'
        (This.Node.Publish (Support ("TeamPlan"), Prefix & Plan_Topic,
                            (RCL.QoS.Default with delta
                               Depth => 1, Durability => RCL.QoS.Transient_Local)));
      This.Markers_Pub := new RCL.Publishers.Publisher'
        (This.Node.Publish (Standard_Support ("visualization_msgs", "MarkerArray"),
                            Prefix & Markers_Topic,
                            (RCL.QoS.Default with delta
                               Depth => 1, Durability => RCL.QoS.Transient_Local)));
      This.Path_Pub := new RCL.Publishers.Publisher'
        (This.Node.Publish (Standard_Support ("nav_msgs", "Path"),
                            Prefix & Paths_Topic & "/" & Topic_Part (This.Agent_Id)));
      This.Subscribe ("pose");
      This.Log (Logging.Info, "relaying to GUIs on " & Prefix & "gui/{robots,plan}, "
                & Prefix & Markers_Topic & ", " & Prefix & Paths_Topic & "/"
                & Topic_Part (This.Agent_Id));
   end Start;

   overriding procedure Stop (This : in out Relay) is
   begin
      Base_Component (This).Stop;
      Free (This.Robots_Pub);
      Free (This.Plan_Pub);
      Free (This.Markers_Pub);
      Free (This.Path_Pub);
      Free (This.Node);
   end Stop;

   overriding procedure On_Input
     (This : in out Relay; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
      P : constant Pose := Values.Pose_Value (Item).Data;
   begin
      if This.Has_Pose then
         This.Distance := This.Distance + Distance (Position (This.Here), Position (P));
      end if;
      This.Here := P;
      This.Has_Pose := True;
   end On_Input;

   --  The team's state as this agent's replica holds it --------------------

   function Mission_Ids (This : Relay) return Text_Vectors.Vector is
      Text   : constant String := This.Agent.Database.Get_String ("mission");
      Result : Text_Vectors.Vector;
      First  : Positive := Text'First;
   begin
      for K in Text'Range loop
         if Text (K) = ',' then
            if K > First then
               Result.Append (Text (First .. K - 1));
            end if;
            First := K + 1;
         end if;
      end loop;
      if First <= Text'Last then
         Result.Append (Text (First .. Text'Last));
      end if;
      return Result;
   end Mission_Ids;

   function Done_By (This : Relay; Task_Id : String) return String is
     (This.Agent.Database.Get_String ("done/" & Task_Id));

   function Tour_Of (This : Relay; Robot : String) return Natural is
   begin
      if This.Plan.Generation = 0 then
         return 0;
      end if;
      for K in 1 .. Natural'Min (Natural (This.Round.Robots.Length),
                                 Natural (This.Plan.Tours.Length))
      loop
         if To_String (This.Round.Robots (K).Id) = Robot then
            return K;
         end if;
      end loop;
      return 0;
   end Tour_Of;

   function Remaining (This : Relay; K : Natural) return Plans.Step_Vectors.Vector is
      Result : Plans.Step_Vectors.Vector;
   begin
      if K > 0 then
         for S of This.Plan.Tours (K) loop
            if Done_By (This, To_String (S.Task_Id)) = "" then
               Result.Append (S);
            end if;
         end loop;
      end if;
      return Result;
   end Remaining;

   procedure Follow_Plan (This : in out Relay) is
      S : constant Plans.Snapshot := This.Agent.Round;
      P : constant Plans.Plan := This.Agent.Adopted;
   begin
      This.Round.Generation := S.Generation;
      if P.Generation > 0 and then P.Generation = S.Generation
        and then P.Tours.Length = S.Robots.Length
        and then (P.Generation /= This.Plan.Generation or else P /= This.Plan)
        --  A round's adopted plan changes when a better proposal comes.
      then
         This.Round := S;
         This.Plan := P;
         for K in 1 .. Natural (P.Tours.Length) loop
            for Step of P.Tours (K) loop
               declare
                  Id : constant String := To_String (Step.Task_Id);
               begin
                  if not This.First_Owner.Contains (Id) then
                     This.First_Owner.Insert (Id, To_String (S.Robots (K).Id));
                     This.First_Round.Insert (Id, P.Generation);
                  elsif This.First_Round (Id) = P.Generation then
                     This.First_Owner.Replace (Id, To_String (S.Robots (K).Id));
                  end if;
               end;
            end loop;
         end loop;
      end if;
   end Follow_Plan;

   procedure Set_Strings (Field : Field_Ref; Items : Text_Vectors.Vector) is
      List : constant Array_Ref := Field.As_Array;
   begin
      List.Resize (Natural (Items.Length));
      for I in 1 .. Natural (Items.Length) loop
         List.Element (I).Set_String (Items (I));
      end loop;
   end Set_Strings;

   function Kind_Name (K : Missions.Task_Kind) return String is
     (case K is
         when Missions.Goto_Pose       => "goto",
         when Missions.Explore_Segment => "explore",
         when Missions.Choose_Entry    => "choose");

   procedure Publish_Robot (This : in out Relay) is
      Msg   : constant Message := Init (Support ("RobotState"));
      Me    : constant String := This.Agent_Id;
      K     : constant Natural := (if This.Agent = null then 0 else Tour_Of (This, Me));
      Left  : constant Plans.Step_Vectors.Vector :=
        (if K = 0 then Plans.Step_Vectors.Empty_Vector else Remaining (This, K));
      Tour, Done : Text_Vectors.Vector;
      Choices    : UInt32_Array (1 .. Natural (Left.Length));
      Status     : constant String :=
        (if This.Has_Input ("status") and then This.Has_Value ("status")
         then This.Input ("status").Image else "");
   begin
      Msg ("robot").Set_String (Me);
      Msg ("stamp").As_Float64 := ROSIDL.Float64
        (Ada.Real_Time.To_Duration (This.Now - Ada.Real_Time.Time_First));
      Msg ("x").As_Float64 := ROSIDL.Float64 (This.Here.X);
      Msg ("y").As_Float64 := ROSIDL.Float64 (This.Here.Y);
      Msg ("yaw").As_Float64 := ROSIDL.Float64 (This.Here.Yaw);
      Msg ("status").Set_String (Status);
      Msg ("current_task").Set_String
        ((if Ada.Strings.Fixed.Head (Status, 5) = "task "
          then Status (Status'First + 5 .. Status'Last)
          elsif not Left.Is_Empty then To_String (Left.First_Element.Task_Id) else ""));
      for I in 1 .. Natural (Left.Length) loop
         Tour.Append (To_String (Left (I).Task_Id));
         Choices (I) := ROSIDL.UInt32 (Left (I).Choice);
      end loop;
      if This.Agent /= null then
         Msg ("round").As_UInt32 := ROSIDL.UInt32 (This.Round.Generation);
         Msg ("plan_round").As_UInt32 := ROSIDL.UInt32 (This.Plan.Generation);
         for Id of Mission_Ids (This) loop
            if Done_By (This, Id) = Me then
               Done.Append (Id);
            end if;
         end loop;
         if K > 0 then
            Msg ("planned_cost").As_Float64 := ROSIDL.Float64
              (Plans.Tour_Cost (This.Round, Position (This.Here), Left));
         end if;
      end if;
      Set_Strings (Msg ("done"), Done);
      Set_Strings (Msg ("tour"), Tour);
      Msg ("choices").Set_UInt32_Array (Choices);
      Msg ("distance").As_Float64 := ROSIDL.Float64 (This.Distance);
      This.Robots_Pub.Publish (Msg);
      --  nav_msgs/Path: from the robot along its remaining tour.
      declare
         Path  : constant Message := Init (Standard_Support ("nav_msgs", "Path"));
         Poses : constant Array_Ref := Path ("poses").As_Array;
         Along : Missions.Point_Vectors.Vector;
      begin
         Along.Append (Position (This.Here));
         for Step of Left loop
            Along.Append (Step_Points (This.Round, Step));
         end loop;
         Path ("header")("frame_id").Set_String ("map");
         Poses.Resize (Natural (Along.Length));
         for I in 1 .. Natural (Along.Length) loop
            Poses.Element (I)("header")("frame_id").Set_String ("map");
            Set_Point (Poses.Element (I)("pose")("position"), Along (I));
            Poses.Element (I)("pose")("orientation")("w").As_Float64 := 1.0;
         end loop;
         This.Path_Pub.Publish (Path);
      end;
   end Publish_Robot;

   type Shown_Task is record
      Id    : Unbounded_String;
      Where : Point;
      State : Unbounded_String;
   end record;
   package Shown_Vectors is new Ada.Containers.Vectors (Positive, Shown_Task);

   procedure Publish_Markers (This : in out Relay; Shown : Shown_Vectors.Vector) is
      --  visualization_msgs/MarkerArray: a DELETEALL (the array replaces the
      --  last one), a sphere and a label per task (coloured by state), a
      --  line strip per robot of the round along its tour.
      Msg     : constant Message := Init (Standard_Support ("visualization_msgs", "MarkerArray"));
      Markers : constant Array_Ref := Msg ("markers").As_Array;
      Count   : constant Natural :=
        1 + 2 * Natural (Shown.Length)
        + (if This.Plan.Generation > 0 then Natural (This.Plan.Tours.Length) else 0);
      N       : Natural := 0;

      function Next (Name_Space : String; Id : Natural; Kind : ROSIDL.Int32) return Field_Ref is
      begin
         N := N + 1;
         declare
            M : constant Field_Ref := Markers.Element (N);
         begin
            M ("header")("frame_id").Set_String ("map");
            M ("ns").Set_String (Name_Space);
            M ("id").As_Int32 := ROSIDL.Int32 (Id);
            M ("type").As_Int32 := Kind;
            M ("pose")("orientation")("w").As_Float64 := 1.0;
            return M;
         end;
      end Next;
   begin
      Markers.Resize (Count);
      declare
         Clear : constant Field_Ref := Next ("", 0, Marker_Sphere);
      begin
         Clear ("action").As_Int32 := Marker_Delete_All;
      end;
      for K in 1 .. Natural (Shown.Length) loop
         declare
            S     : Shown_Task renames Shown (K);
            Ball  : constant Field_Ref := Next ("tasks", K, Marker_Sphere);
            Label : constant Field_Ref := Next ("labels", K, Marker_Text);
         begin
            Set_Point (Ball ("pose")("position"), S.Where);
            Ball ("scale")("x").As_Float64 := 0.35;
            Ball ("scale")("y").As_Float64 := 0.35;
            Ball ("scale")("z").As_Float64 := 0.35;
            Set_Colour (Ball ("color"), State_Colour (To_String (S.State)));
            Set_Point (Label ("pose")("position"), S.Where, Z => 0.6);
            Label ("scale")("z").As_Float64 := 0.35;
            Set_Colour (Label ("color"), (1.0, 1.0, 1.0));
            Label ("text").Set_String (To_String (S.Id) & " (" & To_String (S.State) & ")");
         end;
      end loop;
      if This.Plan.Generation > 0 then
         for K in 1 .. Natural (This.Plan.Tours.Length) loop
            declare
               Line   : constant Field_Ref := Next ("tours", K, Marker_Line_Strip);
               Points : constant Array_Ref := Line ("points").As_Array;
               Along  : Missions.Point_Vectors.Vector;
            begin
               if K <= Natural (This.Round.Robots.Length) then
                  Along.Append (This.Round.Robots (K).Where);
                  Line ("text").Set_String (To_String (This.Round.Robots (K).Id));
               end if;
               for Step of This.Plan.Tours (K) loop
                  Along.Append (Step_Points (This.Round, Step));
               end loop;
               Points.Resize (Natural (Along.Length));
               for I in 1 .. Natural (Along.Length) loop
                  Set_Point (Points.Element (I), Along (I));
               end loop;
               Line ("scale")("x").As_Float64 := 0.08;
               Set_Colour (Line ("color"), Robot_Colours ((K - 1) mod Robot_Colours'Length));
            end;
         end loop;
      end if;
      This.Markers_Pub.Publish (Msg);
   end Publish_Markers;

   procedure Publish_Plan (This : in out Relay) is
      Shown : Shown_Vectors.Vector;
      Msg   : constant Message := Init (Support ("TeamPlan"));
      Ids   : constant Text_Vectors.Vector := Mission_Ids (This);
      Tasks : constant Array_Ref := Msg ("tasks").As_Array;
      Robots : Text_Vectors.Vector;
      N     : Natural := 0;
      Content : Unbounded_String;
   begin
      Msg ("team").Set_String (This.Option_Text ("team"));
      Msg ("source").Set_String (This.Agent_Id);
      Msg ("round").As_UInt32 := ROSIDL.UInt32 (This.Round.Generation);
      Msg ("plan_round").As_UInt32 := ROSIDL.UInt32 (This.Plan.Generation);
      if This.Plan.Generation > 0 then
         Msg ("proposer").Set_String (To_String (This.Plan.Proposer));
         Msg ("makespan").As_Float64 :=
           ROSIDL.Float64 (Plans.Makespan (This.Round, This.Plan));
         Msg ("total_cost").As_Float64 := ROSIDL.Float64 (Plans.Total (This.Round, This.Plan));
      end if;
      for R of This.Agent.Round.Robots loop
         Robots.Append (To_String (R.Id));
      end loop;
      Set_Strings (Msg ("robots"), Robots);
      Tasks.Resize (Natural (Ids.Length));
      for Id of Ids loop
         declare
            Text : constant String := This.Agent.Database.Get_String ("task/" & Id);
            T    : Missions.Mission_Task;
         begin
            T := Missions.Decode (Id, Text);
            N := N + 1;
            declare
               E     : constant Field_Ref := Tasks.Element (N);
               Xs, Ys : Float64_Array (1 .. Natural (T.Points.Length));
               Robot : Unbounded_String := To_Unbounded_String (Done_By (This, Id));
               State : Unbounded_String := To_Unbounded_String ("pending");
            begin
               for P in Xs'Range loop
                  Xs (P) := ROSIDL.Float64 (T.Points (P).X);
                  Ys (P) := ROSIDL.Float64 (T.Points (P).Y);
               end loop;
               E ("id").Set_String (Id);
               E ("kind").Set_String (Kind_Name (T.Kind));
               E ("x").Set_Float64_Array (Xs);
               E ("y").Set_Float64_Array (Ys);
               for K in 1 .. Natural (This.Plan.Tours.Length) loop
                  declare
                     Tour : constant Plans.Step_Vectors.Vector := This.Plan.Tours (K);
                     Mine : constant String := To_String (This.Round.Robots (K).Id);
                     Seen_Undone : Boolean := False;
                  begin
                     for Step of Tour loop
                        if To_String (Step.Task_Id) = Id then
                           E ("choice").As_UInt32 := ROSIDL.UInt32 (Step.Choice);
                           if Robot = Null_Unbounded_String then
                              Robot := To_Unbounded_String (Mine);
                              State := To_Unbounded_String
                                ((if not Seen_Undone then "active"
                                  elsif This.First_Owner.Contains (Id)
                                    and then This.First_Owner (Id) /= Mine
                                  then "reallocated" else "assigned"));
                           end if;
                        end if;
                        Seen_Undone := Seen_Undone
                          or else Done_By (This, To_String (Step.Task_Id)) = "";
                     end loop;
                  end;
               end loop;
               if Done_By (This, Id) /= "" then
                  State := To_Unbounded_String ("done");
               end if;
               E ("state").Set_String (To_String (State));
               E ("robot").Set_String (To_String (Robot));
               Shown.Append (Shown_Task'(Id    => To_Unbounded_String (Id),
                                         Where => T.Points.First_Element,
                                         State => State));
               Append (Content, Id & "=" & State & "," & Robot & ";");
            end;
         exception
            when Missions.Format_Error =>
               if Text /= "" and then not This.Bad_Tasks.Contains (Id) then
                  This.Bad_Tasks.Insert (Id, Text);
                  This.Log (Logging.Warning, "task " & Id & ": unreadable text '" & Text & "'");
               end if;
         end;
      end loop;
      Tasks.Resize (N);
      Append (Content, This.Round.Generation'Image & This.Plan.Generation'Image);
      for R of Robots loop
         Append (Content, " " & R);
      end loop;
      if Content /= This.Last_Plan or else This.Unchanged >= Resend then
         This.Plan_Pub.Publish (Msg);
         Publish_Markers (This, Shown);
         This.Last_Plan := Content;
         This.Unchanged := 0;
      else
         This.Unchanged := This.Unchanged + 1;
      end if;
   end Publish_Plan;

   overriding procedure Run (This : in out Relay; Next : in out Clocks.Time) is
   begin
      Next := Next + This.Period;
      if This.Agent = null then
         This.Agent := Agents.Find (This.Agent_Id);
      end if;
      if This.Agent /= null then
         Follow_Plan (This);
      end if;
      if This.Has_Pose then
         Publish_Robot (This);
      end if;
      if This.Agent /= null and then This.Agent.Mission_Tasks > 0 then
         Publish_Plan (This);
      end if;
   end Run;

   function Create is new Factory.Create_Component (Relay);

begin
   Factory.Register
     ((Name    => To_Unbounded_String ("gui_relay"),
       Doc     => To_Unbounded_String ("relays an agent's pose, plan and state to remote GUIs"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose", Optional => True,
                               Doc => "the robot in the world")
                    & In_Port ("status", "types.string", Optional => True,
                               Doc => "what the robot is doing (team_member's status)"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("team", Text_Option, "team")
                    & Make_Option ("period", Duration_Option, "0.25"),
       others  => <>),
      Create'Access);
end Sancta.Standard_Components.GUI_Relay;
