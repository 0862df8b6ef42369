with Ada.Numerics.Generic_Elementary_Functions;
with Ada.Unchecked_Deallocation;

package body Sancta.Robot.Mappers is

   use Grids;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   procedure Free is new Ada.Unchecked_Deallocation (Real_Matrix, Real_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Flag_Matrix, Flag_Access);

   overriding procedure Finalize (This : in out Mapper) is
   begin
      Free (This.Odds);
      Free (This.Observed);
   end Finalize;

   procedure Initialize
     (This   : in out Mapper;
      Frame  : Grids.Frame;
      Config : Mapper_Config := (others => <>)) is
   begin
      Finalize (This);
      This.Frame := Frame;
      This.Config := Config;
      This.Odds := new Real_Matrix'(0 .. Frame.Width - 1 => [0 .. Frame.Height - 1 => 0.0]);
      This.Observed :=
        new Flag_Matrix'(0 .. Frame.Width - 1 => [0 .. Frame.Height - 1 => False]);
   end Initialize;

   function Frame_Of (This : Mapper) return Frame is (This.Frame);

   procedure Update (This : in out Mapper; Sensor : Pose; Scan : Laser_Scan) is
      F   : Frame renames This.Frame;
      C   : Mapper_Config renames This.Config;

      procedure Add (I, J : Integer; Delta_Odds : Real) is
      begin
         This.Odds (I, J) :=
           Real'Max (-C.Clamp, Real'Min (C.Clamp, This.Odds (I, J) + Delta_Odds));
         This.Observed (I, J) := True;
      end Add;
   begin
      if This.Odds = null then
         return;
      end if;
      for B in 1 .. Scan.Beams loop
         if Scan.Ranges (B) >= Scan.Range_Min then
            declare
               Hit    : constant Boolean := Is_Valid (Scan, B);
               R      : constant Real := Real'Min (Scan.Ranges (B), Scan.Range_Max);
               A      : constant Real := Sensor.Yaw + Beam_Angle (Scan, B);
               DX     : constant Real := Math.Cos (A);
               DY     : constant Real := Math.Sin (A);
               I      : Integer := Column (F, Sensor.X);
               J      : Integer := Row (F, Sensor.Y);
               EI     : constant Integer := Column (F, Sensor.X + R * DX);
               EJ     : constant Integer := Row (F, Sensor.Y + R * DY);
               GX     : constant Real := (Sensor.X - F.Origin.X) / F.Resolution;
               GY     : constant Real := (Sensor.Y - F.Origin.Y) / F.Resolution;
               SI     : constant Integer := (if DX >= 0.0 then 1 else -1);
               SJ     : constant Integer := (if DY >= 0.0 then 1 else -1);
               TDX    : constant Real :=
                 (if DX = 0.0 then Real'Last else F.Resolution / abs DX);
               TDY    : constant Real :=
                 (if DY = 0.0 then Real'Last else F.Resolution / abs DY);
               NX     : Real :=
                 (if DX > 0.0 then (Real (I + 1) - GX) * F.Resolution / DX
                  elsif DX < 0.0 then (GX - Real (I)) * F.Resolution / (-DX)
                  else Real'Last);
               NY     : Real :=
                 (if DY > 0.0 then (Real (J + 1) - GY) * F.Resolution / DY
                  elsif DY < 0.0 then (GY - Real (J)) * F.Resolution / (-DY)
                  else Real'Last);
               Steps  : Natural := 0;
               Limit  : constant Natural := 2 * Natural (R / F.Resolution) + 4;
            begin
               --  Cells crossed before the end cell: free.
               while (I /= EI or else J /= EJ) and then Steps < Limit loop
                  if Contains (F, I, J) then
                     Add (I, J, C.Miss_Log_Odds);
                  end if;
                  if NX < NY then
                     I := I + SI;
                     NX := NX + TDX;
                  else
                     J := J + SJ;
                     NY := NY + TDY;
                  end if;
                  Steps := Steps + 1;
               end loop;
               if Contains (F, EI, EJ) then
                  Add (EI, EJ, (if Hit then C.Hit_Log_Odds else C.Miss_Log_Odds));
               end if;
            end;
         end if;
      end loop;
   end Update;

   function Value (This : Mapper; I, J : Integer) return Cell_Value is
   begin
      if This.Odds = null or else not Contains (This.Frame, I, J)
        or else not This.Observed (I, J)
      then
         return -1;
      end if;
      declare
         P : constant Real := 1.0 - 1.0 / (1.0 + Math.Exp (This.Odds (I, J)));
      begin
         return Cell_Value (Integer (Real'Rounding (100.0 * P)));
      end;
   end Value;

   function Data (This : Mapper) return Cell_Value_Array is
      W : constant Natural := This.Frame.Width;
   begin
      return Result : Cell_Value_Array (0 .. W * This.Frame.Height - 1) do
         for J in 0 .. This.Frame.Height - 1 loop
            for I in 0 .. W - 1 loop
               Result (I + J * W) := Interfaces.Integer_8 (Value (This, I, J));
            end loop;
         end loop;
      end return;
   end Data;

end Sancta.Robot.Mappers;
