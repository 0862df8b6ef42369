package body Sancta.Robot.Grids is

   function Floor (V : Real) return Integer is
      I : Integer;
   begin
      if V < Real (-Far) then
         return -Far;
      elsif V > Real (Far) then
         return Far;
      end if;
      --  Floor without the run-time library's attribute routine: the
      --  conversion rounds, then step down when it rounded up.
      I := Integer (V);
      return (if Real (I) > V then I - 1 else I);
   end Floor;

   function Column (F : Frame; X : Real) return Integer is
     (Floor ((X - F.Origin.X) / F.Resolution));

   function Row (F : Frame; Y : Real) return Integer is
     (Floor ((Y - F.Origin.Y) / F.Resolution));

   function Distance_To_Segment (P : Point; Wall : Segment) return Real is
      D   : constant Point := Wall.B - Wall.A;
      L2  : constant Real := D.X * D.X + D.Y * D.Y;
      T   : Real;
   begin
      if L2 = 0.0 then
         return Distance (P, Wall.A);
      end if;
      T := ((P.X - Wall.A.X) * D.X + (P.Y - Wall.A.Y) * D.Y) / L2;
      T := Real'Max (0.0, Real'Min (1.0, T));
      return Distance (P, Wall.A + T * D);
   end Distance_To_Segment;

   procedure Draw (G : in out Grid; Wall : Segment) is
      F      : constant Frame := Frame_Of (G);
      Reach  : constant Real := Wall.Thickness / 2.0 + G.Resolution / 2.0;
      --  Cells exactly at the reach stay free (less a rounding margin).
      I0     : constant Integer :=
        Integer'Max (0, Column (F, Real'Min (Wall.A.X, Wall.B.X) - Reach));
      I1     : constant Integer :=
        Integer'Min (Width (G) - 1, Column (F, Real'Max (Wall.A.X, Wall.B.X) + Reach));
      J0     : constant Integer :=
        Integer'Max (0, Row (F, Real'Min (Wall.A.Y, Wall.B.Y) - Reach));
      J1     : constant Integer :=
        Integer'Min (Height (G) - 1, Row (F, Real'Max (Wall.A.Y, Wall.B.Y) + Reach));
   begin
      for I in I0 .. I1 loop
         for J in J0 .. J1 loop
            if Distance_To_Segment (Center (F, I, J), Wall)
              < Reach - G.Resolution * 1.0E-6
            then
               G.Occupied (I, J) := True;
            end if;
         end loop;
      end loop;
   end Draw;

   procedure For_Each_Occupied_Run (G : Grid) is
      I     : Integer;
      First : Integer;
   begin
      for J in 0 .. G.Last_Row loop
         I := 0;
         while I <= G.Last_Column loop
            if G.Occupied (I, J) then
               First := I;
               while I <= G.Last_Column and then G.Occupied (I, J) loop
                  I := I + 1;
               end loop;
               Occupied_Run (J, First, I - 1);
            else
               I := I + 1;
            end if;
         end loop;
      end loop;
   end For_Each_Occupied_Run;

end Sancta.Robot.Grids;
