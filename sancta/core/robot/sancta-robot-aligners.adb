with Ada.Numerics.Generic_Elementary_Functions;

package body Sancta.Robot.Aligners is

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   procedure Estimate_Error
     (Config  : Aligner_Config;
      Heading : Real;
      Scan    : Laser_Scan;
      Error   : out Real;
      Found   : out Boolean)
   is
      Half_Pi : constant Real := Pi / 2.0;
      Errors  : array (1 .. Scan.Beams) of Real := [others => 0.0];
      Count   : Natural := 0;
   begin
      Error := 0.0;
      Found := False;
      for B in 1 .. Scan.Beams - Config.Span loop
         declare
            M : constant Positive := B + Config.Span / 2;
            E : constant Positive := B + Config.Span;
         begin
            if Is_Valid (Scan, B) and then Is_Valid (Scan, E) and then Is_Valid (Scan, M) then
               declare
                  P : constant Point := Beam_Point (Scan, B);
                  Q : constant Point := Beam_Point (Scan, E);
                  R : constant Point := Beam_Point (Scan, M);
                  L : constant Real := Distance (P, Q);
               begin
                  if L in 0.05 .. 0.6
                    and then abs ((Q.X - P.X) * (R.Y - P.Y) - (Q.Y - P.Y) * (R.X - P.X)) / L
                             <= Config.Straightness
                  then
                     declare
                        A : constant Real := Heading + Math.Arctan (Q.Y - P.Y, Q.X - P.X);
                        F : Real := A - Half_Pi * Real'Rounding (A / Half_Pi);
                     begin
                        if F <= -Pi / 4.0 then
                           F := F + Half_Pi;
                        end if;
                        if abs F <= Config.Tolerance then
                           Count := Count + 1;
                           Errors (Count) := F;
                        end if;
                     end;
                  end if;
               end;
            end if;
         end;
      end loop;
      if Count >= Config.Min_Support then
         --  The median, by partial selection sort (Count is small).
         for I in 1 .. Count / 2 + 1 loop
            for J in I + 1 .. Count loop
               if Errors (J) < Errors (I) then
                  declare
                     T : constant Real := Errors (I);
                  begin
                     Errors (I) := Errors (J);
                     Errors (J) := T;
                  end;
               end if;
            end loop;
         end loop;
         Error := Errors (Count / 2 + 1);
         Found := True;
      end if;
   end Estimate_Error;

   procedure Align
     (Estimate : in out Pose;
      Scan     : Laser_Scan;
      Aligned  : out Boolean;
      Config   : Aligner_Config := (others => <>))
   is
      Error : Real;
   begin
      Estimate_Error (Config, Estimate.Yaw, Scan, Error, Aligned);
      if Aligned then
         Estimate.Yaw := Normalize_Angle (Estimate.Yaw - Error);
      end if;
   end Align;

end Sancta.Robot.Aligners;
