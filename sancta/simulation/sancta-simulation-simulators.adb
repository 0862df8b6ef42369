with Ada.Numerics.Generic_Elementary_Functions;
with Ada.Unchecked_Deallocation;

package body Sancta.Simulation.Simulators is

   use Ada.Strings.Unbounded;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   procedure Free is new Ada.Unchecked_Deallocation (Range_Array, Range_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Robot_Array, Robot_Array_Access);

   Epsilon : constant := 1.0E-9;

   function Clamp (V, Limit : Real) return Real is
     (Real'Max (-Limit, Real'Min (Limit, V)));

   function Is_Full_Circle (L : Laser_Config) return Boolean is
     (L.Field_Of_View >= 2.0 * Pi - 1.0E-6);

   function Angle_Min (L : Laser_Config) return Real is
     (if Is_Full_Circle (L) then -Pi else -L.Field_Of_View / 2.0);

   function Increment (L : Laser_Config) return Real is
     (if Is_Full_Circle (L) then 2.0 * Pi / Real (L.Beams)
      elsif L.Beams = 1 then 0.0
      else L.Field_Of_View / Real (L.Beams - 1));

   ----------------
   -- Initialize --
   ----------------

   procedure Initialize
     (This           : in out Simulator;
      World          : Worlds.World;
      Seed           : Interfaces.Unsigned_64 := 0;
      Physics_Period : Real := 0.01) is
   begin
      Finalize (This);
      This.The_World := World;
      This.Seed := Seed;
      This.Period := Physics_Period;
      This.Ticks := 0;
      This.Events.Clear;
   end Initialize;

   function Clock (This : Simulator) return Real is
     (Real (This.Ticks) * This.Period);

   function World (This : Simulator) return Worlds.World is (This.The_World);

   procedure Add_Robot
     (This   : in out Simulator;
      Config : Robot_Config;
      Start  : Pose;
      Id     : out Robot_Id;
      Name   : String := "")
   is
      State : Robot_State;
   begin
      Id := Robot_Id (This.Count + 1);
      State.Name := To_Unbounded_String
        (if Name = "" then "robot_" & Robot_Id'Image (Id)(2 .. Robot_Id'Image (Id)'Last)
         else Name);
      State.Config := Config;
      State.Truth := Start;
      State.Odom := Start;
      State.Random := Generators.Create
        (This.Seed, Interfaces.Unsigned_64 (Id));
      State.Next_Odom := This.Clock;
      State.Next_Scan := This.Clock;
      State.Next_GPS := This.Clock;
      State.Ranges := new Range_Array (1 .. Config.Laser.Beams);
      State.Ranges.all := [others => Config.Laser.Max_Range];
      if This.Robots = null or else This.Robots'Last < Id then
         declare
            Grown : constant Robot_Array_Access :=
              new Robot_Array (1 .. Robot_Id (Natural'Max (8, 2 * This.Count)));
         begin
            if This.Robots /= null then
               Grown (1 .. Robot_Id'Base (This.Count)) :=
                 This.Robots (1 .. Robot_Id'Base (This.Count));
               Free (This.Robots);
            end if;
            This.Robots := Grown;
         end;
      end if;
      This.Robots (Id) := State;
      This.Count := This.Count + 1;
      This.Events.Append
        (Event'(Robot_Added, This.Clock, Id, Id, Position (Start)));
   end Add_Robot;

   function Robot_Count (This : Simulator) return Natural is (This.Count);

   function Name (This : Simulator; Id : Robot_Id) return String is
     (To_String (This.Robots (Id).Name));

   function Is_Alive (This : Simulator; Id : Robot_Id) return Boolean is
     (This.Robots (Id).Alive);

   procedure Kill (This : in out Simulator; Id : Robot_Id) is
      R : Robot_State renames This.Robots (Id);
   begin
      if R.Alive then
         R.Alive := False;
         R.Velocity := (others => 0.0);
         R.Command := (others => 0.0);
         This.Events.Append
           (Event'(Robot_Killed, This.Clock, Id, Id, Position (R.Truth)));
      end if;
   end Kill;

   procedure Revive (This : in out Simulator; Id : Robot_Id) is
      R : Robot_State renames This.Robots (Id);
   begin
      if not R.Alive then
         R.Alive := True;
         R.Velocity := (others => 0.0);
         R.Command := (others => 0.0);
         R.Colliding := False;
         R.Next_Odom := This.Clock;
         R.Next_Scan := This.Clock;
         R.Next_GPS := This.Clock;
         This.Events.Append
           (Event'(Robot_Revived, This.Clock, Id, Id, Position (R.Truth)));
      end if;
   end Revive;

   procedure Teleport (This : in out Simulator; Id : Robot_Id; Where : Pose) is
      R : Robot_State renames This.Robots (Id);
   begin
      R.Truth := Where;
      R.Velocity := (others => 0.0);
      R.Colliding := False;
   end Teleport;

   procedure Set_Command (This : in out Simulator; Id : Robot_Id; Command : Twist) is
      R : Robot_State renames This.Robots (Id);
   begin
      if R.Alive then
         R.Command := Command;
      end if;
   end Set_Command;

   ----------
   -- Cast --
   ----------

   function Ray_Disk
     (From : Point; DX, DY : Real; Center : Point; Radius : Real) return Real
   is
      --  Distance along the unit ray to the disk, or Real'Last.
      CX    : constant Real := Center.X - From.X;
      CY    : constant Real := Center.Y - From.Y;
      Along : constant Real := CX * DX + CY * DY;
      Perp2 : constant Real := CX * CX + CY * CY - Along * Along;
      T     : Real;
   begin
      if Along <= 0.0 or else Perp2 >= Radius * Radius then
         return Real'Last;
      end if;
      T := Along - Math.Sqrt (Radius * Radius - Perp2);
      return (if T > 0.0 then T else Real'Last);
   end Ray_Disk;

   function Cast
     (This      : Simulator;
      From      : Point;
      Angle     : Real;
      Max_Range : Real;
      Ignore    : Robot_Id'Base := 0) return Real
   is
      Result : Real := Worlds.Cast (This.The_World, From, Angle, Max_Range);
      DX     : constant Real := Math.Cos (Angle);
      DY     : constant Real := Math.Sin (Angle);
   begin
      for Id in 1 .. Robot_Id'Base (This.Count) loop
         if Id /= Ignore and then This.Robots (Id).Alive then
            Result := Real'Min
              (Result,
               Ray_Disk (From, DX, DY, Position (This.Robots (Id).Truth),
                         This.Robots (Id).Config.Radius));
         end if;
      end loop;
      return Result;
   end Cast;

   -----------
   -- Sense --
   -----------

   procedure Scan (This : in out Simulator; Id : Robot_Id) is
      R     : Robot_State renames This.Robots (Id);
      L     : Laser_Config renames R.Config.Laser;
      From  : constant Point := Position (R.Truth);
      First : constant Real := R.Truth.Yaw + Angle_Min (L);
      Inc   : constant Real := Increment (L);
      Full  : constant Boolean := Is_Full_Circle (L);
      Ranges : Range_Array renames R.Ranges.all;
      CI     : constant Real := Math.Cos (Inc);
      SI     : constant Real := Math.Sin (Inc);
      DX     : Real := Math.Cos (First);
      DY     : Real := Math.Sin (First);
      Next_X : Real;
   begin
      --  The beam direction turns by Inc from beam to beam: a rotation
      --  instead of two trigonometric calls, re-anchored every 32 beams.
      for B in Ranges'Range loop
         if (B - 1) mod 32 = 0 then
            DX := Math.Cos (First + Real (B - 1) * Inc);
            DY := Math.Sin (First + Real (B - 1) * Inc);
         end if;
         Ranges (B) := Worlds.Cast_Along (This.The_World, From, DX, DY, L.Max_Range);
         Next_X := DX * CI - DY * SI;
         DY := DX * SI + DY * CI;
         DX := Next_X;
      end loop;
      --  Other robots: only the beams inside each one's angular extent.
      for Other in 1 .. Robot_Id'Base (This.Count) loop
         if Other /= Id and then This.Robots (Other).Alive then
            declare
               O      : Robot_State renames This.Robots (Other);
               C      : constant Point := Position (O.Truth);
               D      : constant Real := Distance (From, C);
               Radius : constant Real := O.Config.Radius;
            begin
               if D > Radius and then D - Radius < L.Max_Range and then Inc > 0.0 then
                  declare
                     Bearing : constant Real :=
                       Math.Arctan (C.Y - From.Y, C.X - From.X) - First;
                     Rel     : constant Real :=
                       Bearing - 2.0 * Pi * Real'Floor (Bearing / (2.0 * Pi));
                     Half    : constant Real := Math.Arcsin (Radius / D);
                     Lo      : constant Integer :=
                       Integer (Real'Ceiling ((Rel - Half) / Inc));
                     Hi      : constant Integer :=
                       Integer (Real'Floor ((Rel + Half) / Inc));
                     N       : constant Integer := L.Beams;
                  begin
                     for K in Lo .. Hi loop
                        declare
                           Off   : constant Real := Real (K) * Inc
                             - 2.0 * Pi * Real'Floor (Real (K) * Inc / (2.0 * Pi));
                           --  The candidate's offset from beam 1 in [0, 2 pi).
                           Index : constant Integer :=
                             (if Full then K mod N
                              else Integer (Real'Rounding (Off / Inc)));
                           --  A wrong neighbour is harmless: the ray test
                           --  below uses the beam's own angle.
                           A : Real;
                        begin
                           if Index in 0 .. N - 1 then
                              A := First + Real (Index) * Inc;
                              Ranges (Index + 1) := Real'Min
                                (Ranges (Index + 1),
                                 Ray_Disk (From, Math.Cos (A), Math.Sin (A), C, Radius));
                           end if;
                        end;
                     end loop;
                  end;
               end if;
            end;
         end if;
      end loop;
      for B in Ranges'Range loop
         if Ranges (B) < L.Max_Range then
            Ranges (B) := Real'Max
              (L.Min_Range,
               Real'Min (L.Max_Range,
                         Ranges (B) + Generators.Gaussian (R.Random, L.Noise_Std_Dev)));
         end if;
      end loop;
      R.Scan_Count := R.Scan_Count + 1;
      R.Scan_Stamp := This.Clock;
   end Scan;

   procedure Sense (This : in out Simulator; Id : Robot_Id) is
      Now : constant Real := This.Clock;

      procedure Advance (Next : in out Real; Rate : Real) is
      begin
         Next := Next + 1.0 / Rate;
         if Next <= Now + Epsilon then
            Next := Now + 1.0 / Rate;
         end if;
      end Advance;

      R : Robot_State renames This.Robots (Id);
   begin
      if R.Config.Odometry.Rate > 0.0 and then Now + Epsilon >= R.Next_Odom then
         Advance (R.Next_Odom, R.Config.Odometry.Rate);
         R.Odom_Count := R.Odom_Count + 1;
         R.Last_Odom :=
           (Stamp => Now, Pose => R.Odom, Velocity => R.Odom_Velocity,
            Pose_Variance => R.Odom_Var, Yaw_Variance => R.Yaw_Var);
      end if;
      if R.Config.Laser.Rate > 0.0 and then Now + Epsilon >= R.Next_Scan then
         Advance (R.Next_Scan, R.Config.Laser.Rate);
         Scan (This, Id);
      end if;
      if R.Config.GPS.Enabled and then R.Config.GPS.Rate > 0.0
        and then Now + Epsilon >= R.Next_GPS
      then
         Advance (R.Next_GPS, R.Config.GPS.Rate);
         R.GPS_Count := R.GPS_Count + 1;
         declare
            --  One draw per declaration: the components of an aggregate are
            --  evaluated in an order the compiler chooses, and a seed must
            --  give the same fixes in every build.
            Error_X : constant Real := Generators.Gaussian (R.Random, R.Config.GPS.Std_Dev);
            Error_Y : constant Real := Generators.Gaussian (R.Random, R.Config.GPS.Std_Dev);
         begin
            R.Last_GPS :=
              (Stamp    => Now,
               Position => (R.Truth.X + Error_X, R.Truth.Y + Error_Y),
               Std_Dev  => R.Config.GPS.Std_Dev);
         end;
      end if;
   end Sense;

   ----------
   -- Move --
   ----------

   function Integrate (P : Pose; V, W, H : Real) return Pose is
   begin
      if abs W < 1.0E-9 then
         return (P.X + V * H * Math.Cos (P.Yaw), P.Y + V * H * Math.Sin (P.Yaw), P.Yaw);
      else
         declare
            Yaw : constant Real := P.Yaw + W * H;
         begin
            return (P.X + V / W * (Math.Sin (Yaw) - Math.Sin (P.Yaw)),
                    P.Y - V / W * (Math.Cos (Yaw) - Math.Cos (P.Yaw)),
                    Normalize_Angle (Yaw));
         end;
      end if;
   end Integrate;

   procedure Move (This : in out Simulator; Id : Robot_Id; H : Real) is
      R       : Robot_State renames This.Robots (Id);
      C       : Robot_Config renames R.Config;
      Target  : constant Twist :=
        (Clamp (R.Command.Linear_X, C.Max_Linear),
         Clamp (R.Command.Angular_Z, C.Max_Angular));
      V       : constant Real := R.Velocity.Linear_X
        + Clamp (Target.Linear_X - R.Velocity.Linear_X, C.Max_Linear_Accel * H);
      W       : constant Real := R.Velocity.Angular_Z
        + Clamp (Target.Angular_Z - R.Velocity.Angular_Z, C.Max_Angular_Accel * H);
      Next    : constant Pose := Integrate (R.Truth, V, W, H);
      Blocked : Boolean := False;
      Other   : Robot_Id := Id;
   begin
      if V = 0.0 and then W = 0.0 then
         R.Velocity := (others => 0.0);
         R.Odom_Velocity := (others => 0.0);
         return;
      end if;
      if Worlds.Disk_Collides (This.The_World, Position (Next), C.Radius) then
         Blocked := True;
      else
         for K in 1 .. Robot_Id'Base (This.Count) loop
            if K /= Id and then This.Robots (K).Alive then
               declare
                  Q     : constant Point := Position (This.Robots (K).Truth);
                  Reach : constant Real := C.Radius + This.Robots (K).Config.Radius;
                  D     : constant Real := Distance (Position (Next), Q);
               begin
                  if D < Reach and then D <= Distance (Position (R.Truth), Q) then
                     Blocked := True;
                     Other := K;
                     exit;
                  end if;
               end;
            end if;
         end loop;
      end if;
      if Blocked then
         R.Velocity := (others => 0.0);
         R.Odom_Velocity := (others => 0.0);
         if not R.Colliding then
            R.Colliding := True;
            R.Collisions := R.Collisions + 1;
            This.Events.Append
              (Event'((if Other = Id then Wall_Collision else Robot_Collision),
               This.Clock, Id, Other, Position (R.Truth)));
         end if;
         return;
      end if;
      R.Colliding := False;
      R.Truth := Next;
      R.Velocity := (V, W);
      --  Wheel odometry: the true increments with scale errors, bias and
      --  noise, integrated at the midpoint heading.
      declare
         O  : Odometry_Config renames C.Odometry;
         DS : constant Real := V * H;
         DA : constant Real := W * H;
         MS : constant Real := DS * (1.0 + O.Linear_Scale_Error)
           + Generators.Gaussian (R.Random, O.Linear_Noise * Math.Sqrt (abs DS));
         MA : constant Real := DA * (1.0 + O.Angular_Scale_Error) + O.Angular_Bias * H
           + Generators.Gaussian (R.Random, O.Angular_Noise * Math.Sqrt (abs DA));
         Mid : constant Real := R.Odom.Yaw + MA / 2.0;
      begin
         R.Odom := (R.Odom.X + MS * Math.Cos (Mid), R.Odom.Y + MS * Math.Sin (Mid),
                    Normalize_Angle (R.Odom.Yaw + MA));
         R.Odom_Velocity := (MS / H, MA / H);
         R.Odom_Var := R.Odom_Var + O.Linear_Noise ** 2 * abs DS;
         R.Yaw_Var := R.Yaw_Var + O.Angular_Noise ** 2 * abs DA;
      end;
   end Move;

   ----------
   -- Step --
   ----------

   procedure Step (This : in out Simulator; Dt : Real) is
      N : constant Long_Long_Integer :=
        (if Dt = 0.0 then 0
         else Long_Long_Integer'Max (1, Long_Long_Integer (Dt / This.Period)));
   begin
      for Tick in 1 .. N loop
         This.Ticks := This.Ticks + 1;
         for Id in 1 .. Robot_Id'Base (This.Count) loop
            if This.Robots (Id).Alive then
               Move (This, Id, This.Period);
            end if;
         end loop;
         for Id in 1 .. Robot_Id'Base (This.Count) loop
            if This.Robots (Id).Alive then
               Sense (This, Id);
            end if;
         end loop;
      end loop;
   end Step;

   -------------
   -- Readers --
   -------------

   function Ground_Truth (This : Simulator; Id : Robot_Id) return Pose_Stamped is
     ((This.Clock, This.Robots (Id).Truth));

   function Is_Colliding (This : Simulator; Id : Robot_Id) return Boolean is
     (This.Robots (Id).Colliding);

   function Collision_Count (This : Simulator; Id : Robot_Id) return Natural is
     (This.Robots (Id).Collisions);

   function Odometry_Count (This : Simulator; Id : Robot_Id) return Natural is
     (This.Robots (Id).Odom_Count);

   function Latest_Odometry (This : Simulator; Id : Robot_Id) return Odometry is
     (This.Robots (Id).Last_Odom);

   function Scan_Count (This : Simulator; Id : Robot_Id) return Natural is
     (This.Robots (Id).Scan_Count);

   function Latest_Scan (This : Simulator; Id : Robot_Id) return Laser_Scan is
      R : Robot_State renames This.Robots (Id);
      L : Laser_Config renames R.Config.Laser;
   begin
      return
        (Beams           => L.Beams,
         Stamp           => R.Scan_Stamp,
         Angle_Min       => Angle_Min (L),
         Angle_Max       => Angle_Min (L) + Real (L.Beams - 1) * Increment (L),
         Angle_Increment => Increment (L),
         Time_Increment  => 0.0,
         Scan_Time       => (if L.Rate > 0.0 then 1.0 / L.Rate else 0.0),
         Range_Min       => L.Min_Range,
         Range_Max       => L.Max_Range,
         Ranges          => R.Ranges.all);
   end Latest_Scan;

   function GPS_Count (This : Simulator; Id : Robot_Id) return Natural is
     (This.Robots (Id).GPS_Count);

   function Latest_GPS (This : Simulator; Id : Robot_Id) return GPS_Fix is
     (This.Robots (Id).Last_GPS);

   procedure Take_Events (This : in out Simulator; Events : out Event_Vectors.Vector) is
   begin
      Events := This.Events;
      This.Events.Clear;
   end Take_Events;

   overriding procedure Finalize (This : in out Simulator) is
   begin
      if This.Robots /= null then
         for Id in 1 .. Robot_Id'Base (This.Count) loop
            Free (This.Robots (Id).Ranges);
         end loop;
         Free (This.Robots);
      end if;
      This.Count := 0;
   end Finalize;

end Sancta.Simulation.Simulators;
