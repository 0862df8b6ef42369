with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Interfaces;
with Sancta.Standard_Components.Robot_Messages;
with Sancta.Standard_Components.ROS2;
with Sancta.Geometry;
with Sancta.Robot.Aligners;
with Sancta.Robot.GPS_Fusion;
with Sancta.Robot.Mappers;
with Sancta.Robot.Scan_Matchers;
with Sancta.Robot.Sensors;
with Sancta.Runtime.Clocks;

package body Sancta.Standard_Components.Localization is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;
   use type Interfaces.Integer_8;

   package RM renames Sancta.Standard_Components.Robot_Messages;

   function Pose_Of (Item : Values.Value'Class) return Pose is (Values.Pose_Value (Item).Data);

   function Real_Option (This : Component'Class; Name : String) return Real is
     (Real (This.Option_Real (Name)));

   ------------------
   -- scan_matcher --
   ------------------

   type Scan_Matcher is new Base_Component with record
      Config      : Robot.Scan_Matchers.Matcher_Config;
      Corrector   : Robot.Scan_Matchers.Corrector;
      Paper_Ports : Boolean := False;
      --  True for "scan_matching": odometry on input "pose", an output on
      --  every odometry pose, a fixed correction from options; False for
      --  "scan_matcher": input "odometry", an output per scan.
      Fixed       : Pose := (0.0, 0.0, 0.0);
      --  The odometric frame's pose in the corrected frame (options).
      Drift       : Pose := (0.0, 0.0, 0.0);
      --  The correction measured by the last match: corrected pose =
      --  Drift (+) odometric pose.
   end record;

   overriding procedure Start (This : in out Scan_Matcher);
   overriding procedure On_Input
     (This : in out Scan_Matcher; Data : String; Item : Values.Value'Class);

   function Odometry_Input (This : Scan_Matcher'Class) return String is
     (if This.Paper_Ports then "pose" else "odometry");

   overriding procedure Start (This : in out Scan_Matcher) is
   begin
      This.Config.Keyframe_Distance := Real_Option (This, "keyframe_distance");
      This.Config.Keyframe_Angle := Real_Option (This, "keyframe_angle");
      This.Config.Max_Iterations := Positive (This.Option_Integer ("max_iterations"));
      This.Subscribe ("scan");
      if This.Paper_Ports then
         This.Fixed := (Real_Option (This, "dx"), Real_Option (This, "dy"),
                        Real_Option (This, "dyaw"));
         This.Subscribe ("pose");
      end if;
   end Start;

   overriding procedure On_Input
     (This : in out Scan_Matcher; Data : String; Item : Values.Value'Class) is
   begin
      if Data = "scan" then
         if This.Has_Value (This.Odometry_Input) then
            declare
               Odometry : constant Pose := Pose_Of (This.Input (This.Odometry_Input));
            begin
               This.Corrector.Update
                 (This.Config, Odometry, RM.To_Scan (ROS2.Message_Value (Item).Message));
               This.Drift := Compose (This.Corrector.Corrected,
                                      Relative (Odometry, (0.0, 0.0, 0.0)));
               This.Output ("pose", Values.Pose_Value'
                              (Data => Compose (This.Fixed, This.Corrector.Corrected)));
               This.Output ("error", Values.Real_Value'
                              (Data => Long_Float (This.Corrector.Last_Result.Error)));
            end;
         end if;
      else
         This.Output ("pose", Values.Pose_Value'
                        (Data => Compose (This.Fixed, Compose (This.Drift, Pose_Of (Item)))));
      end if;
   end On_Input;

   function Create_Scan_Matcher is new Factory.Create_Component (Scan_Matcher);

   type Scan_Matcher_Access is access all Scan_Matcher;

   function Create_Scan_Matching (Ctx : Context) return Component_Access is
      Result : constant Scan_Matcher_Access := new Scan_Matcher;
   begin
      Result.Paper_Ports := True;
      Result.Initialize (Ctx);
      return Component_Access (Result);
   end Create_Scan_Matching;

   -------------
   -- aligner --
   -------------

   type Aligner is new Base_Component with record
      Config : Robot.Aligners.Aligner_Config;
      Error  : Real := 0.0;
   end record;

   overriding procedure Start (This : in out Aligner);
   overriding procedure On_Input
     (This : in out Aligner; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Aligner) is
   begin
      This.Config.Tolerance := Real_Option (This, "tolerance");
      This.Subscribe ("pose");
      This.Subscribe ("scan");
   end Start;

   overriding procedure On_Input
     (This : in out Aligner; Data : String; Item : Values.Value'Class) is
   begin
      if Data = "scan" then
         if This.Has_Value ("pose") then
            declare
               Error : Real;
               Found : Boolean;
            begin
               Robot.Aligners.Estimate_Error
                 (This.Config, Pose_Of (This.Input ("pose")).Yaw,
                  RM.To_Scan (ROS2.Message_Value (Item).Message), Error, Found);
               if Found then
                  This.Error := Error;
               end if;
            end;
         end if;
      else
         declare
            P : constant Pose := Pose_Of (Item);
         begin
            This.Output ("pose", Values.Pose_Value'
                           (Data => (P.X, P.Y, Normalize_Angle (P.Yaw - This.Error))));
         end;
      end if;
   end On_Input;

   function Create_Aligner is new Factory.Create_Component (Aligner);

   ----------------
   -- gps_fusion --
   ----------------

   type GPS_Fuser is new Base_Component with record
      Filter : Robot.GPS_Fusion.Filter;
      Start_Pose : Pose;
   end record;

   overriding procedure Start (This : in out GPS_Fuser);
   overriding procedure On_Input
     (This : in out GPS_Fuser; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out GPS_Fuser) is
   begin
      This.Start_Pose := (Real_Option (This, "x"), Real_Option (This, "y"),
                          Real_Option (This, "yaw"));
      This.Filter.Initialize
        (This.Start_Pose, Real_Option (This, "variance"),
         Config => (Odometry_Noise => Real_Option (This, "odometry_noise"), others => <>));
      This.Subscribe ("odometry");
      This.Subscribe ("gps");
   end Start;

   overriding procedure On_Input
     (This : in out GPS_Fuser; Data : String; Item : Values.Value'Class) is
   begin
      if Data = "gps" then
         This.Filter.Correct (RM.To_Fix (ROS2.Message_Value (Item).Message));
      else
         This.Filter.Predict (Pose_Of (Item));
      end if;
      This.Output ("pose", Values.Pose_Value'(Data => This.Filter.Estimate));
      This.Output ("variance", Values.Real_Value'(Data => Long_Float (This.Filter.Variance)));
   end On_Input;

   function Create_GPS_Fuser is new Factory.Create_Component (GPS_Fuser);

   ------------
   -- mapper --
   ------------

   type Mapper is new Base_Component with record
      Map    : Robot.Mappers.Mapper;
      Period : Ada.Real_Time.Time_Span;
      Stamp  : Real := 0.0;
      Scans  : Natural := 0;
   end record;

   overriding procedure Start (This : in out Mapper);
   overriding procedure Run (This : in out Mapper; Next : in out Clocks.Time);
   overriding procedure On_Input
     (This : in out Mapper; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Mapper) is
   begin
      This.Map.Initialize
        ((Origin     => (Real_Option (This, "origin_x"), Real_Option (This, "origin_y")),
          Resolution => Real_Option (This, "resolution"),
          Width      => Natural (This.Option_Integer ("width")),
          Height     => Natural (This.Option_Integer ("height"))));
      This.Period := This.Option_Duration ("period");
      This.Subscribe ("scan");
   end Start;

   overriding procedure On_Input
     (This : in out Mapper; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
   begin
      if This.Has_Value ("pose") then
         declare
            Scan : constant Robot.Sensors.Laser_Scan :=
              RM.To_Scan (ROS2.Message_Value (Item).Message);
         begin
            This.Map.Update (Pose_Of (This.Input ("pose")), Scan);
            This.Stamp := Scan.Stamp;
            This.Scans := This.Scans + 1;
         end;
      end if;
   end On_Input;

   overriding procedure Run (This : in out Mapper; Next : in out Clocks.Time) is
   begin
      if This.Scans > 0 then
         declare
            Data  : constant Robot.Mappers.Cell_Value_Array := This.Map.Data;
            Known : Natural := 0;
         begin
            for C of Data loop
               if C >= 0 then
                  Known := Known + 1;
               end if;
            end loop;
            This.Output ("map", ROS2.Message_Value'
                           (Message => RM.Grid_Message
                              (This.Map.Frame_Of, Data, This.Stamp,
                               This.Option_Text ("frame_id"))));
            This.Output ("known", Values.Real_Value'
                           (Data => Long_Float (Known)
                                    / Long_Float (Natural'Max (1, Data'Length))));
         end;
      end if;
      Next := Next + This.Period;
   end Run;

   function Create_Mapper is new Factory.Create_Component (Mapper);

   function Positive_Check (Text : String) return String is
     (if Long_Float'Value (Text) > 0.0 then "" else "expected a positive value, found " & Text);

   function Size_Check (Text : String) return String is
     (if Long_Long_Integer'Value (Text) in 1 .. 10_000 then ""
      else "expected 1 .. 10000 cells, found " & Text);

   function Opt (Name : String; Default : String; Check : Option_Check := Positive_Check'Access)
     return Option_Spec is (Make_Option (Name, Real_Option, Default, Check => Check));

   function ICP_Options return Option_Vectors.Vector is
     (Option_Vectors.Empty_Vector
        & Opt ("keyframe_distance", "0.4")
        & Opt ("keyframe_angle", "0.3")
        & Make_Option ("max_iterations", Integer_Option, "50", Check => Size_Check'Access));
   --  The options of the ICP matcher, in both components that run it.

begin
   Factory.Register
     ((Name    => To_Unbounded_String ("scan_matcher"),
       Doc     => To_Unbounded_String ("point-to-line ICP odometry correction"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("odometry", "types.pose")
                    & In_Port ("scan", RM.Scan_Type)
                    & Out_Port ("pose", "types.pose")
                    & Out_Port ("error", "types.real"),
       Options => ICP_Options,
       others  => <>),
      Create_Scan_Matcher'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("scan_matching"),
       Doc     => To_Unbounded_String
                    ("odometric pose corrected by ICP on laser scans (or a fixed correction)"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose")
                    & In_Port ("scan", RM.Scan_Type, Optional => True)
                    & Out_Port ("pose", "types.pose")
                    & Out_Port ("error", "types.real"),
       Options => ICP_Options
                    & Make_Option ("dx", Real_Option, "0.0")
                    & Make_Option ("dy", Real_Option, "0.0")
                    & Make_Option ("dyaw", Real_Option, "0.0"),
       others  => <>),
      Create_Scan_Matching'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("aligner"),
       Doc     => To_Unbounded_String ("heading correction from walls at right angles"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose")
                    & In_Port ("scan", RM.Scan_Type)
                    & Out_Port ("pose", "types.pose"),
       Options => Option_Vectors.Empty_Vector
                    & Opt ("tolerance", "0.17"),
       others  => <>),
      Create_Aligner'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("gps_fusion"),
       Doc     => To_Unbounded_String ("Kalman fusion of odometry and GPS fixes"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("odometry", "types.pose")
                    & In_Port ("gps", RM.GPS_Type)
                    & Out_Port ("pose", "types.pose")
                    & Out_Port ("variance", "types.real"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("x", Real_Option, "0.0")
                    & Make_Option ("y", Real_Option, "0.0")
                    & Make_Option ("yaw", Real_Option, "0.0")
                    & Make_Option ("variance", Real_Option, "0.0")
                    & Make_Option ("odometry_noise", Real_Option, "0.01"),
       others  => <>),
      Create_GPS_Fuser'Access);
   Factory.Register
     ((Name    => To_Unbounded_String ("mapper"),
       Doc     => To_Unbounded_String ("log-odds occupancy grid, published as OccupancyGrid"),
       Ports   => Port_Vectors.Empty_Vector
                    & In_Port ("pose", "types.pose")
                    & In_Port ("scan", RM.Scan_Type)
                    & Out_Port ("map", RM.Map_Type)
                    & Out_Port ("known", "types.real"),
       Options => Option_Vectors.Empty_Vector
                    & Make_Option ("origin_x", Real_Option, "0.0")
                    & Make_Option ("origin_y", Real_Option, "0.0")
                    & Opt ("resolution", "0.1")
                    & Make_Option ("width", Integer_Option, "200", Check => Size_Check'Access)
                    & Make_Option ("height", Integer_Option, "200", Check => Size_Check'Access)
                    & Make_Option ("period", Duration_Option, "1.0")
                    & Make_Option ("frame_id", Text_Option, "map"),
       others  => <>),
      Create_Mapper'Access);
end Sancta.Standard_Components.Localization;
