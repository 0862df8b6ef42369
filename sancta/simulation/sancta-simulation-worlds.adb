with Ada.Numerics.Generic_Elementary_Functions;
with Ada.Unchecked_Deallocation;

package body Sancta.Simulation.Worlds is

   use Robot.Grids;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);

   procedure Free is new Ada.Unchecked_Deallocation (Grid, Grid_Access);
   procedure Free is new Ada.Unchecked_Deallocation
     (Clearance_Matrix, Clearance_Access);

   Cap : constant := 255;
   --  Clearances are counted up to this many cells.

   ------------
   -- Create --
   ------------

   function Create (Occupancy : Grid) return World is
      W : constant Natural := Width (Occupancy);
      H : constant Natural := Height (Occupancy);
   begin
      return Result : World do
         Result.Cells := new Grid'(Occupancy);
         Result.Clear := new Clearance_Matrix (0 .. W - 1, 0 .. H - 1);
         declare
            C : Clearance_Matrix renames Result.Clear.all;

            function At_Or_Zero (I, J : Integer) return Natural is
              (if I in 0 .. W - 1 and then J in 0 .. H - 1 then Natural (C (I, J)) else 0);
            --  Outside the grid counts as occupied.
         begin
            --  Two-pass chessboard distance transform.
            for J in 0 .. H - 1 loop
               for I in 0 .. W - 1 loop
                  if Occupancy.Occupied (I, J) then
                     C (I, J) := 0;
                  else
                     C (I, J) := Clearance (Natural'Min
                       (Cap,
                        1 + Natural'Min
                          (Natural'Min (At_Or_Zero (I - 1, J - 1),
                                        At_Or_Zero (I, J - 1)),
                           Natural'Min (At_Or_Zero (I + 1, J - 1),
                                        At_Or_Zero (I - 1, J)))));
                  end if;
               end loop;
            end loop;
            for J in reverse 0 .. H - 1 loop
               for I in reverse 0 .. W - 1 loop
                  if C (I, J) > 0 then
                     C (I, J) := Clearance (Natural'Min
                       (Natural (C (I, J)),
                        1 + Natural'Min
                          (Natural'Min (At_Or_Zero (I + 1, J + 1),
                                        At_Or_Zero (I, J + 1)),
                           Natural'Min (At_Or_Zero (I - 1, J + 1),
                                        At_Or_Zero (I + 1, J)))));
                  end if;
               end loop;
            end loop;
         end;
      end return;
   end Create;

   function Frame_Of (This : World) return Frame is
     (if This.Cells = null then (others => <>) else Frame_Of (This.Cells.all));

   function Occupancy (This : World) return Grid is
     (if This.Cells = null then Grid'(Last_Column => -1, Last_Row => -1, others => <>)
      else This.Cells.all);

   function Is_Occupied (This : World; I, J : Integer) return Boolean is
     (This.Cells = null or else Is_Occupied (This.Cells.all, I, J));

   ----------
   -- Cast --
   ----------

   function Cast
     (This      : World;
      From      : Point;
      Angle     : Real;
      Max_Range : Real) return Real is
     (Cast_Along (This, From, Math.Cos (Angle), Math.Sin (Angle), Max_Range));

   function Cast_Along
     (This      : World;
      From      : Point;
      DX, DY    : Real;
      Max_Range : Real) return Real
   is
      Infinity : constant Real := Real'Last;
   begin
      if This.Cells = null or else Max_Range <= 0.0 then
         return 0.0;
      end if;
      declare
         G      : Grid renames This.Cells.all;
         C      : Clearance_Matrix renames This.Clear.all;
         Res    : constant Real := G.Resolution;
         Step_I : constant Integer := (if DX >= 0.0 then 1 else -1);
         Step_J : constant Integer := (if DY >= 0.0 then 1 else -1);
         Delta_X : constant Real := (if DX = 0.0 then Infinity else Res / abs DX);
         Delta_Y : constant Real := (if DY = 0.0 then Infinity else Res / abs DY);
         T      : Real := 0.0;
         I, J   : Integer;
         Next_X, Next_Y : Real;
         --  Ray parameters (distances) of the next column and row crossings.

         Inv_Res : constant Real := 1.0 / Res;
         Inv_DX  : constant Real := (if DX = 0.0 then 0.0 else Res / DX);
         Inv_DY  : constant Real := (if DY = 0.0 then 0.0 else Res / DY);

         procedure Locate with Inline is
            --  Cell and next crossings of the ray point at distance T.
            GX : constant Real := (From.X + T * DX - G.Origin.X) * Inv_Res;
            GY : constant Real := (From.Y + T * DY - G.Origin.Y) * Inv_Res;
         begin
            I := Floor (GX);
            J := Floor (GY);
            Next_X :=
              (if DX > 0.0 then T + (Real (I + 1) - GX) * Inv_DX
               elsif DX < 0.0 then T + (Real (I) - GX) * Inv_DX
               else Infinity);
            Next_Y :=
              (if DY > 0.0 then T + (Real (J + 1) - GY) * Inv_DY
               elsif DY < 0.0 then T + (Real (J) - GY) * Inv_DY
               else Infinity);
         end Locate;

         Clear  : Clearance;
         Last_I : constant Integer := G.Last_Column;
         Last_J : constant Integer := G.Last_Row;
         pragma Suppress (Index_Check);
         --  Every C (I, J) below follows an explicit test of I and J
         --  against the grid's bounds (the hot loop of ray casting).
      begin
         Locate;
         loop
            if I not in 0 .. Last_I or else J not in 0 .. Last_J then
               return Real'Min (T, Max_Range);
            end if;
            Clear := C (I, J);
            if Clear = 0 then
               return Real'Min (T, Max_Range);
            end if;
            if T >= Max_Range then
               return Max_Range;
            end if;
            if Clear >= 10 then
               --  Every occupied cell is at least Clear - 1 cells away from
               --  any point of this cell: jump (when that saves more DDA
               --  steps than locating again costs; 10 was best measured).
               T := T + Real (Clear - 1) * Res;
               Locate;
            elsif Next_X < Next_Y then
               T := Next_X;
               Next_X := Next_X + Delta_X;
               I := I + Step_I;
            else
               T := Next_Y;
               Next_Y := Next_Y + Delta_Y;
               J := J + Step_J;
            end if;
         end loop;
      end;
   end Cast_Along;

   -------------------
   -- Disk_Collides --
   -------------------

   function Disk_Collides
     (This : World; Center : Point; Radius : Real) return Boolean
   is
   begin
      if This.Cells = null then
         return True;
      end if;
      declare
         G   : Grid renames This.Cells.all;
         F   : constant Frame := Frame_Of (G);
         Res : constant Real := G.Resolution;
         CI  : constant Integer := Column (F, Center.X);
         CJ  : constant Integer := Row (F, Center.Y);
      begin
         if Contains (F, CI, CJ)
           and then Real (This.Clear (CI, CJ)) - 1.0 > Radius / Res
         then
            return False;
         end if;
         for I in Column (F, Center.X - Radius) .. Column (F, Center.X + Radius) loop
            for J in Row (F, Center.Y - Radius) .. Row (F, Center.Y + Radius) loop
               if Is_Occupied (G, I, J) then
                  declare
                     X0 : constant Real := F.Origin.X + Real (I) * Res;
                     Y0 : constant Real := F.Origin.Y + Real (J) * Res;
                     DX : constant Real :=
                       Real'Max (0.0, Real'Max (X0 - Center.X, Center.X - (X0 + Res)));
                     DY : constant Real :=
                       Real'Max (0.0, Real'Max (Y0 - Center.Y, Center.Y - (Y0 + Res)));
                  begin
                     if DX * DX + DY * DY < Radius * Radius then
                        return True;
                     end if;
                  end;
               end if;
            end loop;
         end loop;
         return False;
      end;
   end Disk_Collides;

   overriding procedure Adjust (This : in out World) is
   begin
      if This.Cells /= null then
         This.Cells := new Grid'(This.Cells.all);
         This.Clear := new Clearance_Matrix'(This.Clear.all);
      end if;
   end Adjust;

   overriding procedure Finalize (This : in out World) is
   begin
      Free (This.Cells);
      Free (This.Clear);
   end Finalize;

end Sancta.Simulation.Worlds;
