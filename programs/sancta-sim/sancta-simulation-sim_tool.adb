with Ada.Command_Line;
with Ada.Containers.Vectors;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Interfaces;
with RCL.Contexts;
with RCL.DDS;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with ROSIDL;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Sancta.Geometry;               use Sancta.Geometry;
with Sancta.Robot.Grids;
with Sancta.Robot.Sensors;
with Sancta.Standard_Components.Robot_Messages;
with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Tool_Arguments;
with Sancta.Simulation.Robot_Lists;
with Sancta.Simulation.Simulators;
with Sancta.Simulation.Worlds;

package body Sancta.Simulation.Sim_Tool is

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   use ROSIDL.Dynamic;

   package Math renames Ada.Numerics.Long_Elementary_Functions;
   package Robot_Messages renames Sancta.Standard_Components.Robot_Messages;

   use Tool_Arguments;

   procedure Usage is
   begin
      Put_Line ("usage: sancta-sim WORLD [options]");
      Put_Line ("  WORLD                   a bundled world (" & Map_Files.Bundled_Worlds
                & "),");
      Put_Line ("                          a map-server YAML file or a wall world (.walls)");
      Put_Line ("  --robot ""NAME X Y YAW [KEY=VALUE ...]""   a robot (repeatable; keys: see");
      Put_Line ("                          Sancta.Simulation.Robot_Lists)");
      Put_Line ("  --robots FILE           robots, one per line in that format");
      Put_Line ("  --rate R | Rx           simulated seconds per wall second (default 1); when");
      Put_Line ("                          starved of CPU it runs slower, and does not make up");
      Put_Line ("                          more than 0.25 simulated s of the lag by racing");
      Put_Line ("  --as-fast-as-possible   no pacing");
      Put_Line ("  --seed N                noise seed (default 0)");
      Put_Line ("  --duration S            stop after S simulated seconds (default: never)");
      Put_Line ("  --step S                simulated seconds per step (default 0.02)");
      Put_Line ("  --truth-period S        ground-truth period (default 0.1)");
      Put_Line ("  --cmd-timeout S         stop a robot S simulated seconds after its last");
      Put_Line ("                          cmd_vel (default 0: never)");
      Put_Line ("  --quiet                 do not print events");
   end Usage;

   --  ROS 2 side of one robot --

   type Node_Access is access RCL.Nodes.Node;
   type Publisher_Access is access RCL.Publishers.Publisher;

   type Robot_IO is record
      Id        : Simulators.Robot_Id := 1;
      Name      : Unbounded_String;
      Start     : Pose;
      Node      : Node_Access;
      Odom      : Publisher_Access;
      Scan      : Publisher_Access;
      Truth     : Publisher_Access;
      GPS       : Publisher_Access;
      Last_Odom : Natural := 0;
      Last_Scan : Natural := 0;
      Last_GPS  : Natural := 0;
      Last_Cmd  : Real := 0.0;
      --  Simulated time of the last cmd_vel.
      Bad_Cmd_Said : Boolean := False;
      --  A non-finite cmd_vel was reported (said once per robot).
   end record;

   package IO_Vectors is new Ada.Containers.Vectors (Positive, Robot_IO);

   procedure Ignore_Sample
     (Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info) is null;
   --  The cmd_vel subscription's callback: never called (no executor spins
   --  the robot nodes; the stepping loop takes the samples itself).

   function Image (X : Real) return String is
      Hundredths : constant Long_Long_Integer := Long_Long_Integer (X * 100.0);
      Whole      : constant String := Long_Long_Integer'Image (abs Hundredths / 100);
      Cents      : constant String :=
        Long_Long_Integer'Image (100 + abs Hundredths mod 100);
   begin
      return (if Hundredths < 0 then "-" else "") & Whole (Whole'First + 1 .. Whole'Last)
        & "." & Cents (Cents'Last - 1 .. Cents'Last);
   end Image;
   --  X with two decimals ("-1.05").

   --  The publication path keeps one message per type and writes it
   --  through field references looked up once (a Field_Ref designates the
   --  message's storage, which stays put): looking fields up by name on
   --  every publication dominated the cost of the ROS 2 path.

   type Time_Fields is record
      Sec, Nanosec : Field_Ref;
   end record;
   --  The fields of a builtin_interfaces/Time.

   function Time_Fields_Of (Stamp : Field_Ref) return Time_Fields is
     ((Sec => Stamp ("sec"), Nanosec => Stamp ("nanosec")));

   type Header_Fields is record
      Stamp    : Time_Fields;
      Frame_Id : Field_Ref;
   end record;
   --  The fields of a std_msgs/Header.

   function Header_Fields_Of (Header : Field_Ref) return Header_Fields is
     ((Stamp => Time_Fields_Of (Header ("stamp")), Frame_Id => Header ("frame_id")));

   type Pose_Fields is record
      X, Y, Z, Qx, Qy, Qz, Qw : Field_Ref;
   end record;
   --  The fields of a geometry_msgs/Pose.

   function Pose_Fields_Of (Target : Field_Ref) return Pose_Fields is
     ((X  => Target ("position")("x"), Y => Target ("position")("y"),
       Z  => Target ("position")("z"), Qx => Target ("orientation")("x"),
       Qy => Target ("orientation")("y"), Qz => Target ("orientation")("z"),
       Qw => Target ("orientation")("w")));

   procedure Set_Time (Stamp : Time_Fields; T : Real) is
      Seconds : constant Real := Real'Floor (T);
      Nanos   : constant Real := Real'Floor ((T - Seconds) * 1.0E9);
   begin
      Stamp.Sec.As_Int32 := ROSIDL.Int32 (Seconds);
      Stamp.Nanosec.As_UInt32 := ROSIDL.UInt32 (Real'Min (Nanos, 999_999_999.0));
   end Set_Time;

   procedure Set_Stamp (Header : Header_Fields; T : Real; Frame : String) is
   begin
      Set_Time (Header.Stamp, T);
      Header.Frame_Id.Set_String (Frame);
   end Set_Stamp;

   function Is_Sane (P : Pose) return Boolean is
     (P.X'Valid and then P.Y'Valid and then P.Yaw'Valid
      and then abs P.X < 1.0E6 and then abs P.Y < 1.0E6 and then abs P.Yaw < 1.0E6);
   --  Finite coordinates of a sensible size.

   procedure Set_Pose (Target : Pose_Fields; P : Pose) is
   begin
      Target.X.As_Float64 := ROSIDL.Float64 (P.X);
      Target.Y.As_Float64 := ROSIDL.Float64 (P.Y);
      Target.Z.As_Float64 := 0.0;
      Target.Qx.As_Float64 := 0.0;
      Target.Qy.As_Float64 := 0.0;
      Target.Qz.As_Float64 := ROSIDL.Float64 (Math.Sin (Long_Float (P.Yaw) / 2.0));
      Target.Qw.As_Float64 := ROSIDL.Float64 (Math.Cos (Long_Float (P.Yaw) / 2.0));
   end Set_Pose;



   procedure Simulate
     (World       : Worlds.World;
      Robots      : Robot_Lists.Robot_List;
      Rate        : Real;
      As_Fast     : Boolean;
      Seed        : Interfaces.Unsigned_64;
      Duration_S  : Real;
      Step        : Real;
      Truth_Every : Real;
      Cmd_Timeout : Real;
      Quiet       : Boolean)
   is
      use ROSIDL.Typesupport;
      use type Ada.Real_Time.Time;

      Sim   : Simulators.Simulator;
      IO    : IO_Vectors.Vector;
      Main  : RCL.Nodes.Node := RCL.Nodes.Init ("sancta_sim", Namespace => "/");

      Twist_Support : constant Message_Support := Get_Message_Support ("geometry_msgs", "Twist");
      Odom_Support  : constant Message_Support := Get_Message_Support ("nav_msgs", "Odometry");
      Scan_Support  : constant Message_Support :=
        Get_Message_Support ("sensor_msgs", "LaserScan");
      Truth_Support : constant Message_Support :=
        Get_Message_Support ("geometry_msgs", "PoseStamped");
      GPS_Support   : constant Message_Support :=
        Get_Message_Support ("geometry_msgs", "PoseWithCovarianceStamped");
      Clock_Support : constant Message_Support := Get_Message_Support ("rosgraph_msgs", "Clock");
      Text_Support  : constant Message_Support := Get_Message_Support ("std_msgs", "String");
      Control       : constant Service_Support :=
        Get_Service_Support ("sancta_msgs", "SimControl");

      Twist_Msg : Message := Init (Twist_Support);
      Odom_Msg  : constant Message := Init (Odom_Support);
      Truth_Msg : constant Message := Init (Truth_Support);
      Scan_Msg  : constant Message := Init (Scan_Support);
      Clock_Msg : constant Message := Init (Clock_Support);
      Text_Msg  : constant Message := Init (Text_Support);

      Odom_Header  : constant Header_Fields := Header_Fields_Of (Odom_Msg ("header"));
      Odom_Child   : constant Field_Ref := Odom_Msg ("child_frame_id");
      Odom_Pose    : constant Pose_Fields := Pose_Fields_Of (Odom_Msg ("pose")("pose"));
      Odom_Cov     : constant Field_Ref := Odom_Msg ("pose")("covariance");
      Odom_Linear  : constant Field_Ref := Odom_Msg ("twist")("twist")("linear")("x");
      Odom_Angular : constant Field_Ref := Odom_Msg ("twist")("twist")("angular")("z");
      Truth_Header : constant Header_Fields := Header_Fields_Of (Truth_Msg ("header"));
      Truth_Pose   : constant Pose_Fields := Pose_Fields_Of (Truth_Msg ("pose"));
      Clock_Time   : constant Time_Fields := Time_Fields_Of (Clock_Msg ("clock"));
      Scan_Header  : constant Header_Fields := Header_Fields_Of (Scan_Msg ("header"));
      Scan_Angle_Min       : constant Field_Ref := Scan_Msg ("angle_min");
      Scan_Angle_Max       : constant Field_Ref := Scan_Msg ("angle_max");
      Scan_Angle_Increment : constant Field_Ref := Scan_Msg ("angle_increment");
      Scan_Time_Increment  : constant Field_Ref := Scan_Msg ("time_increment");
      Scan_Scan_Time       : constant Field_Ref := Scan_Msg ("scan_time");
      Scan_Range_Min       : constant Field_Ref := Scan_Msg ("range_min");
      Scan_Range_Max       : constant Field_Ref := Scan_Msg ("range_max");
      Scan_Ranges          : constant Field_Ref := Scan_Msg ("ranges");
      --  The fields written on every publication, looked up once.

      Clock_Pub  : RCL.Publishers.Publisher :=
        Main.Publish (Clock_Support, "/clock", RCL.QoS.Clock);
      Events_Pub : RCL.Publishers.Publisher :=
        Main.Publish (Text_Support, "/sancta_sim/events");

      Template     : Simulators.Robot_Config := Simulators.Default_Robot;

      --  Standard visualization topics: /tf (map -> <robot>/odom ->
      --  <robot>/base_link at the odometry rate; map -> odom is what a
      --  perfect localizer would publish, so that the chain gives the ground
      --  truth), /tf_static (<robot>/base_link -> <robot>/laser, the scan's
      --  frame; every robot in one latched message) and /map (the world's
      --  occupancy grid, latched).
      TF_Support  : constant Message_Support := Get_Message_Support ("tf2_msgs", "TFMessage");
      Map_Support : constant Message_Support :=
        Get_Message_Support ("nav_msgs", "OccupancyGrid");
      Latched     : constant RCL.QoS.Profile :=
        (RCL.QoS.Default with delta Depth => 1, Durability => RCL.QoS.Transient_Local);
      TF_Pub      : RCL.Publishers.Publisher :=
        Main.Publish (TF_Support, "/tf", (RCL.QoS.Default with delta Depth => 100));
      Static_Pub  : RCL.Publishers.Publisher := Main.Publish (TF_Support, "/tf_static", Latched);
      Map_Pub     : RCL.Publishers.Publisher := Main.Publish (Map_Support, "/map", Latched);
      TF_Msg      : constant Message := Init (TF_Support);

      procedure Set_Transform
        (Item : Field_Ref; T : Real; Parent, Child : String; P : Pose) is
         Target : constant Pose_Fields :=
           (X  => Item ("transform")("translation")("x"),
            Y  => Item ("transform")("translation")("y"),
            Z  => Item ("transform")("translation")("z"),
            Qx => Item ("transform")("rotation")("x"),
            Qy => Item ("transform")("rotation")("y"),
            Qz => Item ("transform")("rotation")("z"),
            Qw => Item ("transform")("rotation")("w"));
      begin
         Set_Stamp (Header_Fields_Of (Item ("header")), T, Parent);
         Item ("child_frame_id").Set_String (Child);
         Set_Pose (Target, P);
      end Set_Transform;

      procedure Publish_Static_Transforms is
         Static : constant Message := Init (TF_Support);
         List   : constant Array_Ref := Static ("transforms").As_Array;
      begin
         List.Resize (Natural (IO.Length));
         for I in 1 .. Natural (IO.Length) loop
            Set_Transform (List.Element (I), Sim.Clock, To_String (IO (I).Name) & "/base_link",
                           To_String (IO (I).Name) & "/laser", (0.0, 0.0, 0.0));
         end loop;
         Static_Pub.Publish (Static);
      end Publish_Static_Transforms;

      procedure Publish_Map is
         Grid : constant Sancta.Robot.Grids.Grid := World.Occupancy;
         Msg  : constant Message := Init (Map_Support);
         Cells : ROSIDL.Dynamic.Int8_Array (1 .. (Grid.Last_Column + 1) * (Grid.Last_Row + 1));
         Info : constant Field_Ref := Msg ("info");
      begin
         --  Row-major from the grid's origin (OccupancyGrid's layout):
         --  100 occupied, 0 free.
         for J in 0 .. Grid.Last_Row loop
            for I in 0 .. Grid.Last_Column loop
               Cells (J * (Grid.Last_Column + 1) + I + 1) :=
                 (if Grid.Occupied (I, J) then 100 else 0);
            end loop;
         end loop;
         Set_Stamp (Header_Fields_Of (Msg ("header")), 0.0, "map");
         Info ("resolution").As_Float32 := ROSIDL.Float32 (Grid.Resolution);
         Info ("width").As_UInt32 := ROSIDL.UInt32 (Grid.Last_Column + 1);
         Info ("height").As_UInt32 := ROSIDL.UInt32 (Grid.Last_Row + 1);
         Set_Pose (Pose_Fields_Of (Info ("origin")), (Grid.Origin.X, Grid.Origin.Y, 0.0));
         Msg ("data").Set_Int8_Array (Cells);
         Map_Pub.Publish (Msg);
      end Publish_Map;

      procedure Say (Text : String) is
      begin
         if not Quiet then
            Put_Line ("[sancta-sim t=" & Image (Sim.Clock) & "] " & Text);
         end if;
         Text_Msg ("data").Set_String (Text);
         Events_Pub.Publish (Text_Msg);
      end Say;

      function Find (Name : String) return Natural is
      begin
         for I in 1 .. Natural (IO.Length) loop
            if To_String (IO (I).Name) = Name then
               return I;
            end if;
         end loop;
         return 0;
      end Find;

      procedure Add (Name : String; Config : Simulators.Robot_Config; Start : Pose) is
         R : Robot_IO;
         NS : constant String := "/" & Name;
      begin
         Sim.Add_Robot (Config, Start, R.Id, Name);
         R.Name := To_Unbounded_String (Name);
         R.Start := Start;
         R.Last_Cmd := Sim.Clock;
         R.Node := new RCL.Nodes.Node'(RCL.Nodes.Init ("sancta_sim", Namespace => NS));
         R.Odom := new RCL.Publishers.Publisher'(R.Node.Publish (Odom_Support, "odom"));
         R.Scan := new RCL.Publishers.Publisher'
           (R.Node.Publish (Scan_Support, "scan", RCL.QoS.Sensor_Data));
         R.Truth := new RCL.Publishers.Publisher'
           (R.Node.Publish (Truth_Support, "ground_truth"));
         if Config.GPS.Enabled then
            R.GPS := new RCL.Publishers.Publisher'(R.Node.Publish (GPS_Support, "gps"));
         end if;
         R.Node.Subscribe_Raw (DDS_Type_Name (Twist_Support), "cmd_vel", Ignore_Sample'Access);
         IO.Append (R);
         Publish_Static_Transforms;
      end Add;

      procedure Publish_Readings (R : in out Robot_IO; With_Truth : Boolean) is
         Count : Natural;
      begin
         if not Sim.Is_Alive (R.Id) then
            return;
         end if;
         Count := Sim.Odometry_Count (R.Id);
         if Count /= R.Last_Odom then
            R.Last_Odom := Count;
            declare
               O   : constant Sancta.Robot.Sensors.Odometry := Sim.Latest_Odometry (R.Id);
               Rel : constant Pose := Relative (R.Start, O.Pose);
               Cov : ROSIDL.Dynamic.Float64_Array (1 .. 36) := [others => 0.0];
            begin
               Set_Stamp (Odom_Header, O.Stamp, To_String (R.Name) & "/odom");
               Odom_Child.Set_String (To_String (R.Name) & "/base_link");
               Set_Pose (Odom_Pose, Rel);
               Cov (1) := ROSIDL.Float64 (O.Pose_Variance);
               Cov (8) := ROSIDL.Float64 (O.Pose_Variance);
               Cov (36) := ROSIDL.Float64 (O.Yaw_Variance);
               Odom_Cov.Set_Float64_Array (Cov);
               Odom_Linear.As_Float64 := ROSIDL.Float64 (O.Velocity.Linear_X);
               Odom_Angular.As_Float64 := ROSIDL.Float64 (O.Velocity.Angular_Z);
               R.Odom.Publish (Odom_Msg);
               declare
                  Truth : constant Pose := Sim.Ground_Truth (R.Id).Pose;
                  List  : constant Array_Ref := TF_Msg ("transforms").As_Array;
                  Name  : constant String := To_String (R.Name);
               begin
                  List.Resize (2);
                  Set_Transform (List.Element (1), O.Stamp, "map", Name & "/odom",
                                 Compose (Truth, Relative (Rel, (0.0, 0.0, 0.0))));
                  Set_Transform (List.Element (2), O.Stamp, Name & "/odom", Name & "/base_link",
                                 Rel);
                  TF_Pub.Publish (TF_Msg);
               end;
            end;
         end if;
         Count := Sim.Scan_Count (R.Id);
         if Count /= R.Last_Scan then
            R.Last_Scan := Count;
            declare
               Scan   : constant Sancta.Robot.Sensors.Laser_Scan := Sim.Latest_Scan (R.Id);
               Ranges : ROSIDL.Dynamic.Float32_Array (1 .. Scan.Beams);
            begin
               --  As Robot_Messages.Scan_Message, into the reused message.
               for I in Ranges'Range loop
                  Ranges (I) := ROSIDL.Float32 (Scan.Ranges (I));
               end loop;
               Set_Stamp (Scan_Header, Scan.Stamp, To_String (R.Name) & "/laser");
               Scan_Angle_Min.As_Float32 := ROSIDL.Float32 (Scan.Angle_Min);
               Scan_Angle_Max.As_Float32 := ROSIDL.Float32 (Scan.Angle_Max);
               Scan_Angle_Increment.As_Float32 := ROSIDL.Float32 (Scan.Angle_Increment);
               Scan_Time_Increment.As_Float32 := ROSIDL.Float32 (Scan.Time_Increment);
               Scan_Scan_Time.As_Float32 := ROSIDL.Float32 (Scan.Scan_Time);
               Scan_Range_Min.As_Float32 := ROSIDL.Float32 (Scan.Range_Min);
               Scan_Range_Max.As_Float32 := ROSIDL.Float32 (Scan.Range_Max);
               Scan_Ranges.Set_Float32_Array (Ranges);
               R.Scan.Publish (Scan_Msg);
            end;
         end if;
         if R.GPS /= null then
            Count := Sim.GPS_Count (R.Id);
            if Count /= R.Last_GPS then
               R.Last_GPS := Count;
               R.GPS.Publish (Robot_Messages.Fix_Message (Sim.Latest_GPS (R.Id)));
            end if;
         end if;
         if With_Truth then
            declare
               T : constant Sancta.Robot.Sensors.Pose_Stamped := Sim.Ground_Truth (R.Id);
            begin
               Set_Stamp (Truth_Header, T.Stamp, "map");
               Set_Pose (Truth_Pose, T.Pose);
               R.Truth.Publish (Truth_Msg);
            end;
         end if;
      end Publish_Readings;

      procedure Take_Commands (R : in out Robot_IO) is
         Info : ROSIDL.Message_Info;
      begin
         loop
            declare
               Data : constant RCL.DDS.Byte_Array := R.Node.Take_Raw ("cmd_vel", Info);
            begin
               exit when Data'Length = 0;
               ROSIDL.CDR.Decode (Data, Twist_Msg);
               declare
                  --  Tested through the references: a copy of a NaN raises
                  --  Constraint_Error under validity checks (debug build).
                  Linear  : constant ROSIDL.Dynamic.Float64_Ref :=
                    Twist_Msg ("linear")("x").As_Float64;
                  Angular : constant ROSIDL.Dynamic.Float64_Ref :=
                    Twist_Msg ("angular")("z").As_Float64;
               begin
                  if Linear.Element.all'Valid and then Angular.Element.all'Valid then
                     R.Last_Cmd := Sim.Clock;
                     --  Finite values; the simulator clamps them to the
                     --  robot's limits.
                     Sim.Set_Command
                       (R.Id, (Linear_X  => Real (Linear.Element.all),
                               Angular_Z => Real (Angular.Element.all)));
                  elsif not R.Bad_Cmd_Said then
                     --  NaN or infinite: the sample is ignored (the robot
                     --  keeps its last command, or stops on --cmd-timeout).
                     R.Bad_Cmd_Said := True;
                     Say ("cmd_vel for " & To_String (R.Name)
                          & ": non-finite velocity ignored (said once per robot)");
                  end if;
               end;
            exception
               when E : ROSIDL.Decode_Error =>
                  Say ("bad cmd_vel sample for " & To_String (R.Name) & ": "
                       & Ada.Exceptions.Exception_Message (E));
            end;
         end loop;
         if Cmd_Timeout > 0.0 and then Sim.Clock - R.Last_Cmd > Cmd_Timeout then
            Sim.Set_Command (R.Id, (0.0, 0.0));
         end if;
      end Take_Commands;

      procedure Answer
        (Unused_Node : in out RCL.Nodes.Node'Class;
         Request     : Message;
         Response    : in out Message)
      is
         --  The /sancta_sim/control service, answered in the stepping loop.
         Command : constant String := Request ("command").Get_String;
         Name    : constant String := Request ("name").Get_String;
         function Coordinate (Field : String) return Real is
            Value : constant ROSIDL.Dynamic.Float64_Ref := Request (Field).As_Float64;
         begin
            return (if Value.Element.all'Valid then Real (Value.Element.all) else Real'Last);
         end Coordinate;
         --  The request's value, Real'Last (refused by Is_Sane) for NaN/Inf.

         Where   : constant Pose :=
           (Coordinate ("x"), Coordinate ("y"), Coordinate ("yaw"));
         Index   : constant Natural := Find (Name);
         Ok      : Boolean := True;
         Text    : Unbounded_String;
      begin
         if Command = "list" then
            for R of IO loop
               Append (Text, R.Name & (if Sim.Is_Alive (R.Id) then "" else "(dead)") & " ");
            end loop;
         elsif Command = "add" then
            if not Robot_Lists.Is_Valid_Name (Name) then
               Ok := False;
               Text := To_Unbounded_String ("add: invalid robot name """ & Name & """");
            elsif Index /= 0 then
               Ok := False;
               Text := To_Unbounded_String ("add: robot " & Name & " exists already");
            elsif not Is_Sane (Where) then
               Ok := False;
               Text := To_Unbounded_String ("add: invalid start pose");
            else
               Add (Name, Template, Where);
               Text := To_Unbounded_String ("added " & Name);
            end if;
         elsif Command in "kill" | "revive" | "teleport" then
            if Index = 0 then
               Ok := False;
               Text := To_Unbounded_String (Command & ": no robot named """ & Name & """");
            elsif Command = "kill" then
               Sim.Kill (IO (Index).Id);
               Text := To_Unbounded_String ("killed " & Name);
            elsif Command = "revive" then
               Sim.Revive (IO (Index).Id);
               Text := To_Unbounded_String ("revived " & Name);
            elsif not Is_Sane (Where) then
               Ok := False;
               Text := To_Unbounded_String ("teleport: invalid pose");
            else
               Sim.Teleport (IO (Index).Id, Where);
               Text := To_Unbounded_String ("teleported " & Name);
            end if;
         else
            Ok := False;
            Text := To_Unbounded_String
              ("unknown command """ & Command & """ (add, kill, revive, teleport, list)");
         end if;
         Response ("success").As_Bool := Ok;
         Response ("message").Set_String (To_String (Text));
         if not Quiet then
            Put_Line ("[sancta-sim t=" & Image (Sim.Clock) & "] control " & Command & " "
                      & Name & ": " & To_String (Text));
         end if;
      end Answer;

      procedure Report_Events is
         Events : Simulators.Event_Vectors.Vector;
      begin
         Sim.Take_Events (Events);
         for E of Events loop
            declare
               Who : constant String := Sim.Name (E.Robot);
               At_Text : constant String :=
                 " at (" & Image (E.Where.X) & ", " & Image (E.Where.Y) & ")";
            begin
               case E.Kind is
                  when Simulators.Wall_Collision =>
                     Say ("collision " & Who & " wall" & At_Text);
                  when Simulators.Robot_Collision =>
                     Say ("collision " & Who & " " & Sim.Name (E.Other) & At_Text);
                  when Simulators.Robot_Added =>
                     Say ("added " & Who & At_Text);
                  when Simulators.Robot_Killed =>
                     Say ("killed " & Who & At_Text);
                  when Simulators.Robot_Revived =>
                     Say ("revived " & Who & At_Text);
               end case;
            end;
         end loop;
      end Report_Events;

      Started    : Ada.Real_Time.Time := Ada.Real_Time.Clock;
      Origin     : Ada.Real_Time.Time := Started;
      --  Pacing: simulated time T is due at Origin + T / Rate.
      Next_Truth : Real := 0.0;

      Make_Up_Limit : constant Real := 0.25;
      --  Simulated seconds of lag that pacing makes up by stepping without
      --  waiting (a late wake-up, a slow step). Beyond that the simulator
      --  does not race to catch up: simulated time would jump seconds in a
      --  burst that the robots' controllers, on this /clock, cannot follow
      --  (their cmd_vel times out, they stand still while time passes: seen
      --  after the team demo's first plan on a loaded machine). It moves
      --  Origin instead and goes on at Rate from where it is: slower than
      --  Rate while starved, never faster. Below sancta demo's --cmd-timeout
      --  (0.5 s).
      Not_Made_Up : Real := 0.0;
      --  Simulated seconds given up so (said at the end).

      procedure Pace is
         Due  : constant Ada.Real_Time.Time :=
           Origin + Ada.Real_Time.To_Time_Span (Duration (Sim.Clock / Rate));
         Now  : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
         Late : constant Real := Real (Ada.Real_Time.To_Duration (Now - Due)) * Rate;
      begin
         if Late > Make_Up_Limit then
            Not_Made_Up := Not_Made_Up + Late;
            Origin := Now - Ada.Real_Time.To_Time_Span (Duration (Sim.Clock / Rate));
         else
            delay until Due;
         end if;
      end Pace;
   begin
      Sim.Initialize (World, Seed);
      Publish_Map;
      Main.Serve (Control, "/sancta_sim/control", Answer'Access);
      if not Robots.Is_Empty then
         Template := Robots.First_Element.Config;
      end if;
      for R of Robots loop
         Add (To_String (R.Name), R.Config, R.Start);
      end loop;
      Started := Ada.Real_Time.Clock;
      Origin := Started;
      --  Wall time and pacing count from here (robots made).
      Put_Line ("sancta-sim: " & Natural'Image (Natural (IO.Length)) & " robot(s), domain"
                & RCL.DDS.Domain_Id'Image (RCL.Contexts.Domain) & ", "
                & (if As_Fast then "as fast as possible" else "rate " & Image (Rate) & "x"));
      begin
         while not RCL.Contexts.Is_Shutdown
           and then Sim.Clock < Duration_S - Step / 2.0
         loop
            for R of IO loop
               Take_Commands (R);
            end loop;
            Main.Spin (During => 0.0);  --  control requests (Answer)
            Sim.Step (Step);
            Report_Events;
            declare
               Truth_Due : constant Boolean := Sim.Clock >= Next_Truth - 1.0E-9;
            begin
               if Truth_Due then
                  Next_Truth := Next_Truth + Truth_Every;
               end if;
               for R of IO loop
                  Publish_Readings (R, Truth_Due);
               end loop;
            end;
            Set_Time (Clock_Time, Sim.Clock);
            Clock_Pub.Publish (Clock_Msg);
            if not As_Fast then
               Pace;
            end if;
         end loop;
      exception
         when RCL.ROS_Exception =>
            --  A publication cut short by the shutdown (Ctrl-C, SIGTERM): the
            --  run ends normally and its summary below is still printed.
            if not RCL.Contexts.Is_Shutdown then
               raise;
            end if;
      end;
      declare
         Wall : constant Real := Real (Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Started));
      begin
         Put_Line ("sancta-sim: stopped at t=" & Image (Sim.Clock) & " after " & Image (Wall)
                   & " s of wall time (real-time factor "
                   & Image (Sim.Clock / Real'Max (Wall, 1.0E-3)) & ")"
                   & (if Not_Made_Up > 0.0
                      then "; behind its rate by " & Image (Not_Made_Up)
                           & " simulated s in all, not made up"
                      else ""));
      end;
   exception
      when RCL.ROS_Exception =>
         if not RCL.Contexts.Is_Shutdown then
            raise;
         end if;
   end Simulate;

   procedure Run is
      World_Name  : Unbounded_String;
      Robots      : Robot_Lists.Robot_List;
      Rate        : Real := 1.0;
      As_Fast     : Boolean := False;
      Seed        : Interfaces.Unsigned_64 := 0;
      Duration_S  : Real := Real'Last;
      Step        : Real := 0.02;
      Truth_Every : Real := 0.1;
      Cmd_Timeout : Real := 0.0;
      Quiet       : Boolean := False;

      procedure Take (A : String; K : in out Positive) is
         function Value return String is (Next_Value (K));
      begin
         if A = "--robot" then
            Robot_Lists.Parse_Line (Value, "--robot", 1, Robots);
         elsif A = "--robots" then
            Robot_Lists.Load (Value, Robots);
         elsif A = "--rate" then
            declare
               V : constant String := Value;
               T : constant String :=
                 (if V'Length > 1 and then V (V'Last) = 'x'
                  then V (V'First .. V'Last - 1) else V);
            begin
               Rate := To_Real ("--rate", T);
               if Rate <= 0.0 or else Rate > 1.0E6 then
                  raise Usage_Error with "--rate: expected a positive factor, found " & V;
               end if;
            end;
         elsif A = "--as-fast-as-possible" then
            As_Fast := True;
         elsif A = "--seed" then
            declare
               V : constant String := Value;
            begin
               Seed := Interfaces.Unsigned_64'Value (V);
            exception
               when Constraint_Error =>
                  raise Usage_Error with "--seed: expected a whole number, found """ & V & """";
            end;
         elsif A = "--duration" then
            Duration_S := To_Real ("--duration", Value);
            if Duration_S <= 0.0 then
               raise Usage_Error with "--duration: expected a positive time";
            end if;
         elsif A = "--step" then
            declare
               V : constant String := Value;
            begin
               Step := To_Real ("--step", V);
               if Step not in 0.001 .. 0.05 then
                  raise Usage_Error with "--step: expected 0.001 .. 0.05 s, found " & V;
               end if;
            end;
         elsif A = "--truth-period" then
            Truth_Every := To_Real ("--truth-period", Value);
            if Truth_Every <= 0.0 then
               raise Usage_Error with "--truth-period: expected a positive time";
            end if;
         elsif A = "--cmd-timeout" then
            Cmd_Timeout := To_Real ("--cmd-timeout", Value);
            if Cmd_Timeout < 0.0 then
               raise Usage_Error with "--cmd-timeout: expected a time >= 0";
            end if;
         elsif A = "--quiet" then
            Quiet := True;
         else
            raise Usage_Error with A & ": unknown option (see --help)";
         end if;
      end Take;

      function Second_World (A : String) return String is (A & ": only one world may be given");
      function Parse is new Parse_Arguments
        (Usage, Take, Second_World,
         No_World => "no world given (a bundled name, a .yaml or a .walls file)");
   begin
      if not Parse (World_Name) then
         return;
      end if;
      declare
         File : constant String := Map_Files.World_File (To_String (World_Name));
      begin
         if File = "" then
            raise Usage_Error with To_String (World_Name)
              & ": no such file and no bundled world of that name ("
              & Map_Files.Bundled_Worlds & ")";
         end if;
         declare
            World : constant Worlds.World := Map_Files.Load_World (File);
            F     : constant Sancta.Robot.Grids.Frame := Worlds.Frame_Of (World);
         begin
            for R of Robots loop
               if R.Start.X not in F.Origin.X .. F.Origin.X + Real (F.Width) * F.Resolution
                 or else R.Start.Y not in F.Origin.Y .. F.Origin.Y + Real (F.Height) * F.Resolution
               then
                  raise Usage_Error with "--robot " & To_String (R.Name) & ": start ("
                    & Image (R.Start.X) & ", " & Image (R.Start.Y) & ") is outside the world "
                    & File;
               end if;
            end loop;
            Simulate (World, Robots, Rate, As_Fast, Seed, Duration_S, Step, Truth_Every,
                      Cmd_Timeout, Quiet);
         end;
      end;
   exception
      when E : Ada.IO_Exceptions.Device_Error =>
         --  Our output was closed ("sancta-sim --help | head"): done; other
         --  device errors are reported.
         if Ada.Exceptions.Exception_Message (E) /= "Broken pipe" then
            Put_Line (Standard_Error, "sancta-sim: " & Ada.Exceptions.Exception_Message (E));
            Set_Exit_Status (Failure);
         end if;
      when E : Usage_Error | Robot_Lists.List_Error =>
         Put_Line (Standard_Error, "sancta-sim: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
      when E : Format_Error =>
         Put_Line (Standard_Error, "sancta-sim: " & Ada.Exceptions.Exception_Message (E));
         Set_Exit_Status (Failure);
   end Run;

end Sancta.Simulation.Sim_Tool;
