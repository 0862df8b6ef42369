package body Sancta.Allocation.Annealers.Tours is

   --  The max segment tree in its iterative form: leaf of robot R at
   --  Robots + R - 1, node I the max of nodes 2 I and 2 I + 1.

   procedure Set_Tree_Cost (S : in out State; R : Positive; V : Cost) is
      I : Positive := S.Robots + R - 1;
   begin
      S.Max_Tree (I) := V;
      while I > 1 loop
         I := I / 2;
         S.Max_Tree (I) := Cost'Max (S.Max_Tree (2 * I), S.Max_Tree (2 * I + 1));
      end loop;
      if S.Robots in 3 .. Top_Robots then
         --  The three largest costs (robots in order of index among equals).
         declare
            Top : Count_Array renames S.Top;
            C : Cost_Array renames S.Robot_Cost;
         begin
            Top := [0, 0, 0];
            for Q in 1 .. S.Robots loop
               if Top (1) = 0 or else C (Q) > C (Top (1)) then
                  Top := [Q, Top (1), Top (2)];
               elsif Top (2) = 0 or else C (Q) > C (Top (2)) then
                  Top (3) := Top (2);
                  Top (2) := Q;
               elsif Top (3) = 0 or else C (Q) > C (Top (3)) then
                  Top (3) := Q;
               end if;
            end loop;
         end;
      end if;
   end Set_Tree_Cost;

   function Max_Between (S : State; Lo, Hi : Natural) return Cost is
      --  Max over robots Lo .. Hi (0 when empty).
      L : Natural := S.Robots + Lo - 1;
      H : Natural := S.Robots + Hi;  --  half-open
      M : Cost := 0;
   begin
      if Lo > Hi or else Lo < 1 then
         return 0;
      end if;
      while L < H loop
         if L mod 2 = 1 then
            M := Cost'Max (M, S.Max_Tree (L));
            L := L + 1;
         end if;
         if H mod 2 = 1 then
            H := H - 1;
            M := Cost'Max (M, S.Max_Tree (H));
         end if;
         L := L / 2;
         H := H / 2;
      end loop;
      return M;
   end Max_Between;

   function Max_Except (S : State; A, B : Natural) return Cost is
      Lo : constant Natural := (if B = 0 then A else Natural'Min (A, B));
      Hi : constant Natural := (if B = 0 then A else Natural'Max (A, B));
   begin
      if S.Robots = 1 then
         return (if A = 0 then S.Max_Tree (1) else 0);
      elsif S.Robots <= Top_Robots and then S.Robots >= 3 then
         for Q of S.Top loop
            if Q /= A and then Q /= B then
               return S.Robot_Cost (Q);
            end if;
         end loop;
      end if;
      return Cost'Max (Max_Between (S, 1, Lo - 1),
                       Cost'Max (Max_Between (S, Lo + 1, Hi - 1),
                                 Max_Between (S, Hi + 1, S.Robots)));
   end Max_Except;

   --  The index of (X, Y) along a Hilbert curve over a 2 ** 16 grid.
   function Hilbert_Index (X, Y : Natural) return Long_Long_Integer is
      Side : constant := 2 ** 16;
      XX : Natural := X;
      YY : Natural := Y;
      D  : Long_Long_Integer := 0;
      H  : Natural := Side / 2;
   begin
      while H > 0 loop
         declare
            RX : constant Natural := (if XX / H mod 2 = 1 then 1 else 0);
            RY : constant Natural := (if YY / H mod 2 = 1 then 1 else 0);
            T  : Natural;
         begin
            D := D + Long_Long_Integer (H) * Long_Long_Integer (H)
              * Long_Long_Integer (if RX = 0 then RY elsif RY = 0 then 3 else 2);
            if RY = 0 then
               if RX = 1 then
                  XX := Side - 1 - XX;
                  YY := Side - 1 - YY;
               end if;
               T := XX;
               XX := YY;
               YY := T;
            end if;
         end;
         H := H / 2;
      end loop;
      return D;
   end Hilbert_Index;

   --  The ranks of P's locations (0 first) along a Hilbert curve through
   --  their coordinates (ties and no coordinates: by number).
   function Hilbert_Ranks (P : Problem) return Index_Table is
      Rank : Index_Table (0 .. P.Locations) := [for L in 0 .. P.Locations => L];
   begin
      if not P.Has_Coordinates then
         return Rank;
      end if;
      declare
         Min_X, Min_Y : Long_Float := Long_Float'Last;
         Max_X, Max_Y : Long_Float := Long_Float'First;
         Key   : array (1 .. P.Locations) of Long_Long_Integer;
         Order : Index_Table (1 .. P.Locations) := [for L in 1 .. P.Locations => L];
         Span  : Long_Float;
      begin
         for C of P.Coordinates loop
            Min_X := Long_Float'Min (Min_X, Long_Float (C.X));
            Max_X := Long_Float'Max (Max_X, Long_Float (C.X));
            Min_Y := Long_Float'Min (Min_Y, Long_Float (C.Y));
            Max_Y := Long_Float'Max (Max_Y, Long_Float (C.Y));
         end loop;
         Span := Long_Float'Max (1.0E-9, Long_Float'Max (Max_X - Min_X, Max_Y - Min_Y));
         for L in 1 .. P.Locations loop
            Key (L) := Hilbert_Index
              (Natural (Long_Float'Floor
                 ((Long_Float (P.Coordinates (L).X) - Min_X) / Span * 65535.0)),
               Natural (Long_Float'Floor
                 ((Long_Float (P.Coordinates (L).Y) - Min_Y) / Span * 65535.0)));
         end loop;
         --  Insertion sort by (key, number): at most Compact_Limit items.
         for I in 2 .. P.Locations loop
            declare
               L : constant Positive := Order (I);
               J : Natural := I - 1;
            begin
               while J >= 1 and then Key (Order (J)) > Key (L) loop
                  Order (J + 1) := Order (J);
                  J := J - 1;
               end loop;
               Order (J + 1) := L;
            end;
         end loop;
         for I in 1 .. P.Locations loop
            Rank (Order (I)) := I;
         end loop;
      end;
      return Rank;
   end Hilbert_Ranks;

   function Compact_Matrix (P : Problem) return Compact_Distances is
      Tile  : constant := 16;
      Side  : constant Positive := (P.Locations + Tile) / Tile * Tile;
      --  Locations 0 .. P.Locations, padded to whole tiles.
      Tiles : constant Positive := Side / Tile;
      Largest : Cost := 0;
      C : Compact_Distances;
   begin
      if not Has_Matrix (P) or else P.Locations > Compact_Limit
        or else (for some R in 1 .. P.Robots => Has_Own_Costs (P, R))
      then
         return C;
      end if;
      for From in 0 .. P.Locations loop
         for To in 0 .. P.Locations loop
            declare
               D : constant Cost := Distance (P, From, To);
            begin
               if D < 0 or else D > Cost (Wide_Cost'Last) then
                  return C;
               end if;
               Largest := Cost'Max (Largest, D);
            end;
         end loop;
      end loop;
      declare
         Rank : constant Index_Table := Hilbert_Ranks (P);
      begin
         --  Rank R is row R mod Tile of tile row R / Tile, column R mod
         --  Tile of tile column R / Tile; a tile is Tile rows of Tile.
         C.Row := new Index_Table'
           ([for L in 0 .. P.Locations =>
               Rank (L) / Tile * Tiles * Tile * Tile + Rank (L) mod Tile * Tile]);
         C.Column := new Index_Table'
           ([for L in 0 .. P.Locations => Rank (L) / Tile * Tile * Tile + Rank (L) mod Tile]);
      end;
      if Largest <= Cost (Narrow_Cost'Last) then
         C.Narrow := new Narrow_Matrix'(0 .. Side * Side - 1 => 0);
      else
         C.Wide := new Wide_Matrix'(0 .. Side * Side - 1 => 0);
      end if;
      for From in 0 .. P.Locations loop
         for To in 0 .. P.Locations loop
            declare
               I : constant Natural := C.Row (From) + C.Column (To);
               D : constant Cost := Distance (P, From, To);
            begin
               if C.Narrow /= null then
                  C.Narrow (I) := Narrow_Cost (D);
               else
                  C.Wide (I) := Wide_Cost (D);
               end if;
            end;
         end loop;
      end loop;
      return C;
   end Compact_Matrix;

   procedure Free (C : in out Compact_Distances) is
      procedure Free is new Ada.Unchecked_Deallocation (Narrow_Matrix, Narrow_Access);
      procedure Free is new Ada.Unchecked_Deallocation (Wide_Matrix, Wide_Access);
      procedure Free is new Ada.Unchecked_Deallocation (Index_Table, Index_Access);
   begin
      Free (C.Narrow);
      Free (C.Wide);
      Free (C.Row);
      Free (C.Column);
   end Free;

   procedure Rebuild
     (P : Problem; S : in out State; R : Positive; From : Positive;
      Same_From : Positive := Positive'Last; Shift : Integer := 0)
   is
      N : constant Natural := S.Length (R);
      M : constant Cost := Cost (P.Multiplier (R));
      F : constant Positive := Positive'Min (From, N + 1);
      Tail : constant Positive := Positive'Min (Same_From, N + 2);
      --  The arcs into positions Tail .. N + 1 are the old tour's (N + 2:
      --  none); position Tail - 1 is their anchor, recomputed below.
      Old_Cost       : constant Cost := S.Robot_Cost (R);
      Old_Completion : constant Cost := S.Robot_Completion (R);
      Old_Forward, Old_Backward : Cost := 0;
      --  The anchor's old prefix costs.
      Bad : Natural := 0;
   begin
      if Tail <= N + 1 then
         --  The old tail's locations and prefix costs to their new places
         --  (in the direction that reads each old entry before it is
         --  overwritten), then the anchor's old costs aside.
         if Shift > 0 then
            for I in Tail - 1 .. N + 1 loop
               S.Location_At (R, I) := S.Location_At (R, I + Shift);
               S.Forward_Cost (R, I) := S.Forward_Cost (R, I + Shift);
               S.Backward_Cost (R, I) := S.Backward_Cost (R, I + Shift);
            end loop;
         elsif Shift < 0 then
            for I in reverse Tail - 1 .. N + 1 loop
               S.Location_At (R, I) := S.Location_At (R, I + Shift);
               S.Forward_Cost (R, I) := S.Forward_Cost (R, I + Shift);
               S.Backward_Cost (R, I) := S.Backward_Cost (R, I + Shift);
            end loop;
         end if;
         Old_Forward := S.Forward_Cost (R, Tail - 1);
         Old_Backward := S.Backward_Cost (R, Tail - 1);
      end if;
      S.Location_At (R, 0) := P.Start (R);
      for I in F .. Positive'Min (N, Tail - 1) loop
         declare
            T : constant Positive := S.Task_At (R, I);
            L : constant Natural := Location_Of (P, T, S.Choice (T));
         begin
            S.Location_At (R, I) := L;
            S.Owner (T) := R;
            S.Position (T) := I;
            S.Forward_Cost (R, I) :=
              S.Forward_Cost (R, I - 1) + Arc (P, S, R, S.Location_At (R, I - 1), L);
            S.Backward_Cost (R, I) :=
              S.Backward_Cost (R, I - 1) + Arc (P, S, R, L, S.Location_At (R, I - 1));
            S.Forward_Sum (R, I) := S.Forward_Sum (R, I - 1) + S.Forward_Cost (R, I);
            S.Backward_Sum (R, I) := S.Backward_Sum (R, I - 1) + S.Backward_Cost (R, I);
         end;
      end loop;
      if Tail <= N + 1 then
         declare
            Forward_Change : constant Cost := S.Forward_Cost (R, Tail - 1) - Old_Forward;
            Backward_Change : constant Cost := S.Backward_Cost (R, Tail - 1) - Old_Backward;
         begin
            for I in Tail .. N loop
               S.Forward_Cost (R, I) := S.Forward_Cost (R, I) + Forward_Change;
               S.Backward_Cost (R, I) := S.Backward_Cost (R, I) + Backward_Change;
               S.Forward_Sum (R, I) := S.Forward_Sum (R, I - 1) + S.Forward_Cost (R, I);
               S.Backward_Sum (R, I) := S.Backward_Sum (R, I - 1) + S.Backward_Cost (R, I);
            end loop;
            if Shift /= 0 then
               for I in Tail .. N loop
                  S.Position (S.Task_At (R, I)) := I;
               end loop;
            end if;
            S.Forward_Cost (R, N + 1) := S.Forward_Cost (R, N + 1) + Forward_Change;
            S.Backward_Cost (R, N + 1) := S.Backward_Cost (R, N + 1) + Backward_Change;
         end;
      else
         S.Location_At (R, N + 1) := P.Finish (R);
         S.Forward_Cost (R, N + 1) :=
           S.Forward_Cost (R, N) + Arc (P, S, R, S.Location_At (R, N), P.Finish (R));
         S.Backward_Cost (R, N + 1) :=
           S.Backward_Cost (R, N) + Arc (P, S, R, P.Finish (R), S.Location_At (R, N));
      end if;
      if not P.All_Feasible then
         for I in 1 .. N loop
            if not P.Can_Do (R, S.Task_At (R, I)) then
               Bad := Bad + 1;
            end if;
         end loop;
      end if;
      S.Infeasible (R) := Bad;
      S.Robot_Cost (R) := M * S.Forward_Cost (R, N + 1) + Cost (Bad) * Infinity;
      S.Robot_Completion (R) := M * S.Forward_Sum (R, N) + Cost (Bad) * Infinity;
      S.Total_Cost := S.Total_Cost - Old_Cost + S.Robot_Cost (R);
      S.Total_Completion := S.Total_Completion - Old_Completion + S.Robot_Completion (R);
      S.Total_Square := S.Total_Square - Square_Of (S, Old_Cost) + Square_Of (S, S.Robot_Cost (R));
      Set_Tree_Cost (S, R, S.Robot_Cost (R));
   end Rebuild;

   procedure Set_Square_Floor (S : in out State; Floor : Cost) is
   begin
      S.Square_Floor := Floor;
      S.Total_Square := 0.0;
      for R in 1 .. S.Robots loop
         S.Total_Square := S.Total_Square + Square_Of (S, S.Robot_Cost (R));
      end loop;
   end Set_Square_Floor;

   procedure Cost_From_Scratch
     (P : Problem; R : Positive; Task_At : Position_Grid; Length : Natural;
      Choice : Location_Array; Tour_Cost, Completion : out Cost)
   is
      Here : Natural := P.Start (R);
      Time, Sum : Cost := 0;
      Bad  : Natural := 0;
      M    : constant Cost := Cost (P.Multiplier (R));
   begin
      for I in 1 .. Length loop
         declare
            T : constant Positive := Task_At (R, I);
            L : constant Natural := Location_Of (P, T, Choice (T));
         begin
            Time := Time + Robot_Distance (P, R, Here, L);
            Sum := Sum + Time;
            if not P.Can_Do (R, T) then
               Bad := Bad + 1;
            end if;
            Here := L;
         end;
      end loop;
      Time := Time + Robot_Distance (P, R, Here, P.Finish (R));
      Tour_Cost := M * Time + Cost (Bad) * Infinity;
      Completion := M * Sum + Cost (Bad) * Infinity;
   end Cost_From_Scratch;

   procedure Compute_Neighbours (P : Problem; S : in out State) is
      K : constant Positive := S.Neighbours;
      Dist : Cost_Array (1 .. K) := [others => 0];
   begin
      for T in 1 .. S.Tasks loop
         declare
            LT : constant Natural := Location_Of (P, T);
            N  : Natural := 0;
         begin
            for U in 1 .. S.Tasks loop
               if U /= T then
                  declare
                     LU : constant Natural := Location_Of (P, U);
                     D  : constant Cost :=
                       Cost'Min (Distance (P, LT, LU), Distance (P, LU, LT));
                     I  : Natural;
                  begin
                     if N < K or else D < Dist (N) then
                        if N < K then
                           N := N + 1;
                        end if;
                        I := N;
                        while I > 1 and then Dist (I - 1) > D loop
                           Dist (I) := Dist (I - 1);
                           S.Near (T, I) := S.Near (T, I - 1);
                           I := I - 1;
                        end loop;
                        Dist (I) := D;
                        S.Near (T, I) := U;
                     end if;
                  end;
               end if;
            end loop;
            S.Near_Count (T) := N;
         end;
      end loop;
   end Compute_Neighbours;

   procedure Load (P : Problem; S : in out State; A : Assignment) is
   begin
      S.Choice := A.Choice;
      S.Selection := A.Branch;
      S.Active_Tasks := 0;
      for T in 1 .. S.Tasks loop
         S.Active (T) := Is_Active (P, S.Selection, T);
         if S.Active (T) then
            S.Active_Tasks := S.Active_Tasks + 1;
         end if;
         S.Owner (T) := 0;
         S.Position (T) := 0;
      end loop;
      S.Total_Cost := 0;
      S.Total_Square := 0.0;
      S.Total_Completion := 0;
      S.Robot_Cost := [others => 0];
      S.Robot_Completion := [others => 0];
      for R in 1 .. S.Robots loop
         S.Length (R) := A.Length (R);
         for I in 1 .. A.Length (R) loop
            S.Task_At (R, I) := A.Tour (R, I);
         end loop;
         Rebuild (P, S, R, 1);
      end loop;
   end Load;

   procedure Store (S : State; A : in out Assignment) is
   begin
      A.Choice := S.Choice;
      A.Branch := S.Selection;
      for R in 1 .. S.Robots loop
         A.Length (R) := S.Length (R);
         for I in 1 .. S.Length (R) loop
            A.Tour (R, I) := S.Task_At (R, I);
         end loop;
      end loop;
   end Store;

   procedure Shuffle (G : in out Generator; Items : in out Count_Array; Last : Natural) is
   begin
      for I in reverse 2 .. Last loop
         declare
            J : constant Positive := 1 + Random.Below (G, I);
            X : constant Natural := Items (I);
         begin
            Items (I) := Items (J);
            Items (J) := X;
         end;
      end loop;
   end Shuffle;

end Sancta.Allocation.Annealers.Tours;
