with Sancta.Simulation.Map_Files;
with Sancta.Simulation.Worlds;

package body Sancta.Team.Grid_Costs is

   use Sancta.Robot;

   function Coarsen (G : Grids.Grid; Factor : Positive) return Grids.Grid is
      W : constant Natural := (Grids.Width (G) + Factor - 1) / Factor;
      H : constant Natural := (Grids.Height (G) + Factor - 1) / Factor;
   begin
      return Result : Grids.Grid (W - 1, H - 1) do
         Result.Origin := G.Origin;
         Result.Resolution := G.Resolution * Real (Factor);
         for I in 0 .. G.Last_Column loop
            for J in 0 .. G.Last_Row loop
               if G.Occupied (I, J) then
                  Result.Occupied (I / Factor, J / Factor) := True;
               end if;
            end loop;
         end loop;
      end return;
   end Coarsen;

   protected body Guarded is
      procedure Initialize (Occupancy : Grids.Grid; Robot_Radius : Real) is
      begin
         Map.Initialize (Occupancy, Robot_Radius);
      end Initialize;

      procedure Cost (From, To : Point; Result : out Long_Float) is
         C : constant Real := Path_Costs.Cost (Map, From, To);
      begin
         Result := (if C = Path_Costs.Unreachable then Long_Float (Distance (From, To))
                    else Long_Float (C));
      end Cost;

      function Cached return Natural is (Path_Costs.Cached_Costs (Map));
   end Guarded;

   function Create
     (Occupancy    : Grids.Grid;
      Robot_Radius : Real := 0.2;
      Cell         : Real := 0.2) return Cost_Access
   is
      Factor : constant Positive :=
        Positive'Max (1, Integer (Real'Rounding (Cell / Occupancy.Resolution)));
      Result : constant Cost_Access := new Grid_Cost_Model;
   begin
      Result.Guard.Initialize (Coarsen (Occupancy, Factor), Robot_Radius);
      return Result;
   end Create;

   function Create
     (World_File   : String;
      Robot_Radius : Real := 0.2;
      Cell         : Real := 0.2) return Cost_Access is
   begin
      return Create
        (Simulation.Worlds.Occupancy (Simulation.Map_Files.Load_World (World_File)),
         Robot_Radius, Cell);
   end Create;

   function Leg (This : Grid_Cost_Model; From, To : Point) return Long_Float is
      Result : Long_Float;
   begin
      This.Guard.Cost (From, To, Result);
      return Result;
   end Leg;

   function Cached_Legs (This : Grid_Cost_Model) return Natural is (This.Guard.Cached);

end Sancta.Team.Grid_Costs;
