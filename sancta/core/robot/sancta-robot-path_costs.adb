with Ada.Unchecked_Deallocation;

package body Sancta.Robot.Path_Costs is

   use Grids;

   procedure Free is new Ada.Unchecked_Deallocation (Boolean_Matrix, Boolean_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Real_Array, Real_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Index_Array, Index_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Scratch, Scratch_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Cost_Maps.Map, Cost_Map_Access);

   Cache_Limit : constant := 1_000_000;
   --  Remembered pairs at most (then the cache starts over).

   Sqrt_2 : constant := 1.41421_35623_73095;

   overriding procedure Finalize (This : in out Planner) is
   begin
      Free (This.Blocked);
      Free (This.Cache);
      if This.Work /= null then
         Free (This.Work.G);
         Free (This.Work.Parent);
         Free (This.Work.Stamp);
         Free (This.Work.Closed);
         Free (This.Work.Heap);
         Free (This.Work.Heap_F);
         Free (This.Work);
      end if;
   end Finalize;

   package Index_Vectors is new Ada.Containers.Vectors (Positive, Natural);

   procedure Block_Around
     (Blocked : in out Boolean_Matrix;
      F       : Frame;
      Radius  : Real;
      I, J    : Integer;
      Changed : access Index_Vectors.Vector := null)
   is
      --  A cell is blocked when its centre is closer than the radius to an
      --  occupied cell (its nearest point): the cells around occupied (I, J).
      --  Cells newly blocked are added to Changed (as J * Width + I).
      Reach : constant Integer := Integer (Real'Ceiling (Radius / F.Resolution));
   begin
      for DI in -Reach .. Reach loop
         for DJ in -Reach .. Reach loop
            if Contains (F, I + DI, J + DJ) then
               declare
                  GX : constant Real := Real'Max (0.0, Real (abs DI) - 0.5) * F.Resolution;
                  GY : constant Real := Real'Max (0.0, Real (abs DJ) - 0.5) * F.Resolution;
               begin
                  if (GX * GX + GY * GY < Radius * Radius
                      or else (DI = 0 and then DJ = 0))
                    and then not Blocked (I + DI, J + DJ)
                  then
                     Blocked (I + DI, J + DJ) := True;
                     if Changed /= null then
                        Changed.Append ((J + DJ) * F.Width + I + DI);
                     end if;
                  end if;
               end;
            end if;
         end loop;
      end loop;
   end Block_Around;

   procedure Initialize
     (This         : in out Planner;
      Occupancy    : Grid;
      Robot_Radius : Real;
      Connect      : Connectivity := Eight)
   is
      F     : constant Frame := Frame_Of (Occupancy);
      N     : constant Natural := F.Width * F.Height;
   begin
      Finalize (This);
      This.Frame := F;
      This.Connect := Connect;
      This.Radius := Robot_Radius;
      This.Blocked := new Boolean_Matrix'(0 .. F.Width - 1 => [0 .. F.Height - 1 => False]);
      for I in 0 .. F.Width - 1 loop
         for J in 0 .. F.Height - 1 loop
            if Occupancy.Occupied (I, J) then
               Block_Around (This.Blocked.all, F, Robot_Radius, I, J);
            end if;
         end loop;
      end loop;
      This.Work := new Scratch'
        (G          => new Real_Array (0 .. N - 1),
         Parent     => new Index_Array (0 .. N - 1),
         Stamp      => new Index_Array'(0 .. N - 1 => 0),
         Closed     => new Index_Array'(0 .. N - 1 => 0),
         Heap       => new Index_Array (0 .. Natural'Max (1024, N / 8)),
         Heap_F     => new Real_Array (0 .. Natural'Max (1024, N / 8)),
         Generation => 0);
      This.Cache := new Cost_Maps.Map;
   end Initialize;

   function Cell_Free (This : Planner; I, J : Integer) return Boolean is
     (Contains (This.Frame, I, J) and then not This.Blocked (I, J));

   function Is_Free (This : Planner; P : Point) return Boolean is
     (This.Blocked /= null
      and then Cell_Free (This, Column (This.Frame, P.X), Row (This.Frame, P.Y)));

   ------------
   -- Search --
   ------------

   procedure Search (This : Planner; From, To : Point; Goal_Index : out Integer) is
      --  A* from From's cell; Goal_Index is To's cell index, or -1.
      F      : Frame renames This.Frame;
      W      : Scratch renames This.Work.all;
      SI     : constant Integer := Column (F, From.X);
      SJ     : constant Integer := Row (F, From.Y);
      GI     : constant Integer := Column (F, To.X);
      GJ     : constant Integer := Row (F, To.Y);
      Size   : Natural := 0;

      function Index (I, J : Integer) return Natural is (J * F.Width + I);

      function H (I, J : Integer) return Real is
         DX : constant Real := Real (abs (I - GI));
         DY : constant Real := Real (abs (J - GJ));
      begin
         return F.Resolution *
           (if This.Connect = Four then DX + DY
            else Real'Max (DX, DY) + (Sqrt_2 - 1.0) * Real'Min (DX, DY));
      end H;

      procedure Push (Cell : Natural; Priority : Real) is
         K : Natural := Size;
      begin
         if Size = W.Heap'Length then
            --  Grow (a cell enters at most 8 times: the heap stays under 8N).
            declare
               New_Heap   : constant Index_Access := new Index_Array (0 .. 2 * Size - 1);
               New_Heap_F : constant Real_Access := new Real_Array (0 .. 2 * Size - 1);
            begin
               New_Heap (0 .. Size - 1) := W.Heap.all;
               New_Heap_F (0 .. Size - 1) := W.Heap_F.all;
               Free (W.Heap);
               Free (W.Heap_F);
               W.Heap := New_Heap;
               W.Heap_F := New_Heap_F;
            end;
         end if;
         Size := Size + 1;
         while K > 0 and then W.Heap_F ((K - 1) / 2) > Priority loop
            W.Heap (K) := W.Heap ((K - 1) / 2);
            W.Heap_F (K) := W.Heap_F ((K - 1) / 2);
            K := (K - 1) / 2;
         end loop;
         W.Heap (K) := Cell;
         W.Heap_F (K) := Priority;
      end Push;

      procedure Pop (Cell : out Natural) is
         Last_Cell : constant Integer := W.Heap (Size - 1);
         Last_F    : constant Real := W.Heap_F (Size - 1);
         K         : Natural := 0;
         C         : Natural;
      begin
         Cell := W.Heap (0);
         Size := Size - 1;
         loop
            C := 2 * K + 1;
            exit when C >= Size;
            if C + 1 < Size and then W.Heap_F (C + 1) < W.Heap_F (C) then
               C := C + 1;
            end if;
            exit when W.Heap_F (C) >= Last_F;
            W.Heap (K) := W.Heap (C);
            W.Heap_F (K) := W.Heap_F (C);
            K := C;
         end loop;
         if Size > 0 then
            W.Heap (K) := Last_Cell;
            W.Heap_F (K) := Last_F;
         end if;
      end Pop;

      Cell : Natural;
   begin
      Goal_Index := -1;
      if not Contains (F, SI, SJ) or else not Cell_Free (This, GI, GJ) then
         return;
      end if;
      W.Generation := W.Generation + 1;
      W.Stamp (Index (SI, SJ)) := W.Generation;
      W.G (Index (SI, SJ)) := 0.0;
      W.Parent (Index (SI, SJ)) := -1;
      Push (Index (SI, SJ), H (SI, SJ));
      while Size > 0 loop
         Pop (Cell);
         if W.Closed (Cell) /= W.Generation then
            W.Closed (Cell) := W.Generation;
            if Cell = Index (GI, GJ) then
               Goal_Index := Cell;
               return;
            end if;
            declare
               CI : constant Integer := Cell mod F.Width;
               CJ : constant Integer := Cell / F.Width;
            begin
               for DI in -1 .. 1 loop
                  for DJ in -1 .. 1 loop
                     if (DI /= 0 or else DJ /= 0)
                       and then (This.Connect = Eight or else DI = 0 or else DJ = 0)
                       and then Cell_Free (This, CI + DI, CJ + DJ)
                       and then (DI = 0 or else DJ = 0
                                 or else (Cell_Free (This, CI + DI, CJ)
                                          and then Cell_Free (This, CI, CJ + DJ)))
                     then
                        declare
                           N    : constant Natural := Index (CI + DI, CJ + DJ);
                           Step : constant Real :=
                             (if DI /= 0 and then DJ /= 0 then Sqrt_2 else 1.0)
                             * F.Resolution;
                           G    : constant Real := W.G (Cell) + Step;
                        begin
                           if W.Closed (N) /= W.Generation
                             and then (W.Stamp (N) /= W.Generation or else G < W.G (N))
                           then
                              W.Stamp (N) := W.Generation;
                              W.G (N) := G;
                              W.Parent (N) := Cell;
                              Push (N, G + H (CI + DI, CJ + DJ));
                           end if;
                        end;
                     end if;
                  end loop;
               end loop;
            end;
         end if;
      end loop;
   end Search;

   function Cost (This : Planner; From, To : Point) return Real is
      Goal : Integer;
   begin
      if This.Blocked = null then
         return Unreachable;
      end if;
      declare
         F   : Frame renames This.Frame;
         FI  : constant Integer := Column (F, From.X);
         FJ  : constant Integer := Row (F, From.Y);
         TI  : constant Integer := Column (F, To.X);
         TJ  : constant Integer := Row (F, To.Y);
         Key : Cell_Pair;
         Pos : Cost_Maps.Cursor;
         Result : Real;
      begin
         if Contains (F, FI, FJ) and then Contains (F, TI, TJ) then
            Key := (FJ * F.Width + FI, TJ * F.Width + TI);
            Pos := This.Cache.Find (Key);
            if Cost_Maps.Has_Element (Pos) then
               return Cost_Maps.Element (Pos);
            end if;
         end if;
         Search (This, From, To, Goal);
         Result := (if Goal < 0 then Unreachable else This.Work.G (Goal));
         if Contains (F, FI, FJ) and then Contains (F, TI, TJ) then
            if Natural (This.Cache.Length) >= Cache_Limit then
               This.Cache.Clear;
            end if;
            This.Cache.Insert (Key, Result);
         end if;
         return Result;
      end;
   end Cost;

   function Generic_Cost (From, To : Point) return Real is (Cost (Map, From, To));

   function Cached_Costs (This : Planner) return Natural is
     (if This.Cache = null then 0 else Natural (This.Cache.Length));

   function Line_Of_Sight (This : Planner; A, B : Point) return Boolean is
      L     : constant Real := Distance (A, B);
      Steps : constant Natural :=
        Natural (Real'Ceiling (2.0 * L / This.Frame.Resolution)) + 1;
   begin
      for K in 0 .. Steps loop
         if not Is_Free (This, A + (Real (K) / Real (Steps)) * (B - A)) then
            return False;
         end if;
      end loop;
      return True;
   end Line_Of_Sight;

   function Path (This : Planner; From, To : Point) return Point_Vectors.Vector is
      Goal   : Integer;
      Cells  : Point_Vectors.Vector;
      Result : Point_Vectors.Vector;
   begin
      if This.Blocked = null then
         return Result;
      end if;
      Search (This, From, To, Goal);
      if Goal < 0 then
         return Result;
      end if;
      --  Cell centres from the goal back to the start's successor.
      declare
         C : Integer := This.Work.Parent (Goal);
      begin
         Cells.Append (To);
         while C >= 0 and then This.Work.Parent (C) >= 0 loop
            Cells.Append (Center (This.Frame, C mod This.Frame.Width, C / This.Frame.Width));
            C := This.Work.Parent (C);
         end loop;
         Cells.Reverse_Elements;
      end;
      --  Skip ahead while the next cell is still in sight.
      declare
         Current : Point := From;
         K       : Positive := 1;
         Best    : Positive;
      begin
         while K <= Cells.Last_Index loop
            Best := K;
            for M in K + 1 .. Cells.Last_Index loop
               exit when not Line_Of_Sight (This, Current, Cells (M));
               Best := M;
            end loop;
            Result.Append (Cells (Best));
            Current := Cells (Best);
            K := Best + 1;
         end loop;
      end;
      return Result;
   end Path;

   function Path
     (This      : Planner;
      From, To  : Point;
      Obstacles : Point_Vectors.Vector) return Point_Vectors.Vector
   is
      Changed : aliased Index_Vectors.Vector;
   begin
      if This.Blocked = null then
         return Point_Vectors.Empty_Vector;
      end if;
      for P of Obstacles loop
         declare
            I : constant Integer := Column (This.Frame, P.X);
            J : constant Integer := Row (This.Frame, P.Y);
         begin
            if Contains (This.Frame, I, J) then
               Block_Around (This.Blocked.all, This.Frame, This.Radius, I, J,
                             Changed'Access);
            end if;
         end;
      end loop;
      return Result : constant Point_Vectors.Vector := Path (This, From, To) do
         for C of Changed loop
            This.Blocked (C mod This.Frame.Width, C / This.Frame.Width) := False;
         end loop;
      end return;
   end Path;

end Sancta.Robot.Path_Costs;
