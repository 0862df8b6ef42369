with Ada.Numerics.Long_Elementary_Functions;
with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Random;

package body Sancta.Allocation.Annealers is

   use Ada.Numerics.Long_Elementary_Functions;
   use type Ada.Real_Time.Time;

   subtype Gen is Sancta.Allocation.Random.Generator;

   type Grid is array (Positive range <>, Natural range <>) of Natural;
   type Cost_Grid is array (Positive range <>, Natural range <>) of Cost;
   type Near_Grid is array (Positive range <>, Positive range <>) of Natural;

   ---------------------------------------------------------------------------
   --  State: the current solution with its cached costs.

   type State (NR, NT, NK, NP, N2 : Positive) is record
      --  NP = NT + 1 (positions), N2 = 2 NR (tree).
      Tk   : Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      --  Task at each position (1 .. Len).
      Lc   : Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      --  Location at each position; 0 = start, Len + 1 = finish.
      Fw   : Cost_Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      --  Base cost from the start to each position, forward.
      Rv   : Cost_Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      --  Rv (I) = sum over K < I of D (Lc (K + 1), Lc (K)): reversed arcs.
      PF   : Cost_Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      PR   : Cost_Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      --  Prefix sums of Fw and Rv over positions 1 .. I.
      Len  : Count_Array (1 .. NR) := [others => 0];
      Bad  : Count_Array (1 .. NR) := [others => 0];
      Own  : Count_Array (1 .. NT) := [others => 0];
      Pos  : Count_Array (1 .. NT) := [others => 0];
      Choice : Location_Array (1 .. NT) := [others => 1];
      RC   : Cost_Array (1 .. NR) := [others => 0];
      RCm  : Cost_Array (1 .. NR) := [others => 0];
      Sum, Comp : Cost := 0;
      Tree : Cost_Array (1 .. N2) := [others => 0];
      Near : Near_Grid (1 .. NT, 1 .. NK) := [others => [others => 0]];
      Near_Count : Count_Array (1 .. NT) := [others => 0];
      Sel  : Location_Array (1 .. NT) := [others => 1];
      --  Plan trees: the alternative chosen at each OR ordinal ...
      Active : Boolean_Array (1 .. NT) := [others => True];
      --  ... the tasks it makes active (only they are in tours; Own = 0
      --  for the others) ...
      N_Active : Natural := NT;
      --  ... and their number.
   end record;

   type State_Access is access State;
   procedure Free is new Ada.Unchecked_Deallocation (State, State_Access);

   --  Max segment tree: leaves at NR + R - 1 .. 2 NR - 1 (iterative form).
   procedure Tree_Set (S : in out State; R : Positive; V : Cost) is
      I : Positive := S.NR + R - 1;
   begin
      S.Tree (I) := V;
      while I > 1 loop
         I := I / 2;
         S.Tree (I) := Cost'Max (S.Tree (2 * I), S.Tree (2 * I + 1));
      end loop;
   end Tree_Set;

   function Tree_Max (S : State; Lo, Hi : Natural) return Cost is
      --  Max over robots Lo .. Hi (0 when empty).
      L : Natural := S.NR + Lo - 1;
      H : Natural := S.NR + Hi;  --  half-open
      M : Cost := 0;
   begin
      if Lo > Hi or else Lo < 1 then
         return 0;
      end if;
      while L < H loop
         if L mod 2 = 1 then
            M := Cost'Max (M, S.Tree (L));
            L := L + 1;
         end if;
         if H mod 2 = 1 then
            H := H - 1;
            M := Cost'Max (M, S.Tree (H));
         end if;
         L := L / 2;
         H := H / 2;
      end loop;
      return M;
   end Tree_Max;

   function Max_Except (S : State; A, B : Natural) return Cost is
      Lo : constant Natural := (if B = 0 then A else Natural'Min (A, B));
      Hi : constant Natural := (if B = 0 then A else Natural'Max (A, B));
   begin
      if S.NR = 1 then
         return (if A = 0 then S.Tree (1) else 0);
      end if;
      return Cost'Max (Tree_Max (S, 1, Lo - 1),
                       Cost'Max (Tree_Max (S, Lo + 1, Hi - 1), Tree_Max (S, Hi + 1, S.NR)));
   end Max_Except;

   function Key (S : State; R : Positive) return Cost is (S.RC (R));

   function Current_Max (S : State) return Cost is (S.Tree (1));
   --  With one robot the single leaf is Tree (1) itself.

   ---------------------------------------------------------------------------
   --  Rebuild the caches of robot R from position From on (tasks in Tk).

   procedure Rebuild (P : Problem; S : in out State; R : Positive; From : Positive) is
      N : constant Natural := S.Len (R);
      M : constant Cost := Cost (P.Multiplier (R));
      F : constant Positive := Positive'Min (From, N + 1);
      Old_RC  : constant Cost := S.RC (R);
      Old_RCm : constant Cost := S.RCm (R);
      Bad : Natural := 0;
   begin
      S.Lc (R, 0) := P.Start (R);
      for I in F .. N loop
         declare
            T : constant Positive := S.Tk (R, I);
            L : constant Natural := Location_Of (P, T, S.Choice (T));
         begin
            S.Lc (R, I) := L;
            S.Own (T) := R;
            S.Pos (T) := I;
            S.Fw (R, I) := S.Fw (R, I - 1) + Robot_Distance (P, R, S.Lc (R, I - 1), L);
            S.Rv (R, I) := S.Rv (R, I - 1) + Robot_Distance (P, R, L, S.Lc (R, I - 1));
            S.PF (R, I) := S.PF (R, I - 1) + S.Fw (R, I);
            S.PR (R, I) := S.PR (R, I - 1) + S.Rv (R, I);
         end;
      end loop;
      S.Lc (R, N + 1) := P.Finish (R);
      S.Fw (R, N + 1) := S.Fw (R, N) + Robot_Distance (P, R, S.Lc (R, N), P.Finish (R));
      S.Rv (R, N + 1) := S.Rv (R, N) + Robot_Distance (P, R, P.Finish (R), S.Lc (R, N));
      if not P.All_Feasible then
         for I in 1 .. N loop
            if not P.Can_Do (R, S.Tk (R, I)) then
               Bad := Bad + 1;
            end if;
         end loop;
      end if;
      S.Bad (R) := Bad;
      S.RC (R) := M * S.Fw (R, N + 1) + Cost (Bad) * Infinity;
      S.RCm (R) := M * S.PF (R, N) + Cost (Bad) * Infinity;
      S.Sum := S.Sum - Old_RC + S.RC (R);
      S.Comp := S.Comp - Old_RCm + S.RCm (R);
      Tree_Set (S, R, Key (S, R));
   end Rebuild;

   ---------------------------------------------------------------------------
   --  Moves as segment lists.

   type Seg_Kind is (Span, Single);
   type Seg is record
      Kind     : Seg_Kind;
      Robot    : Positive;
      First    : Natural;
      Last     : Natural;
      Reversed : Boolean;
      Task_Id  : Natural;   --  Single: this task ...
      Loc      : Natural;   --  ... at this location
   end record;
   --  No default values: a tour plan only reads its first Count segments,
   --  and moves are built millions of times a second.

   Max_Segs : constant := 6;
   type Seg_List is array (1 .. Max_Segs) of Seg;

   type Tour_Plan is record
      Robot : Natural := 0;      --  0 = unused
      Segs  : Seg_List;
      Count : Natural := 0;
   end record;

   type Move is record
      A, B        : Tour_Plan;
      Switch_Task : Natural := 0;   --  OR switch: task and its new choice
      Switch_To   : Natural := 0;
      Or_Node     : Natural := 0;
      --  Switch subtree: the OR ordinal switched (the move's new tours are
      --  in the solver's Pending record, its costs already evaluated).
      New_Active  : Natural := 0;
      New_A_Cost, New_B_Cost : Cost := 0;
      New_A_Comp, New_B_Comp : Cost := 0;
      New_A_Len, New_B_Len   : Natural := 0;
      New_Max, New_Sum, New_Comp : Cost := 0;
      Value       : Long_Float := 0.0;
   end record;

   procedure Clear (Mv : in out Move) is
   begin
      Mv.A.Robot := 0;
      Mv.A.Count := 0;
      Mv.B.Robot := 0;
      Mv.B.Count := 0;
      Mv.Or_Node := 0;
   end Clear;

   function No_Move return Move is
   begin
      return M : Move do
         Clear (M);
      end return;
   end No_Move;
   --  A move of no tour (for Verify without a prediction).

   procedure Add (T : in out Tour_Plan; Robot : Positive; First, Last : Natural;
                  Reversed : Boolean := False) is
   begin
      if First <= Last then
         T.Count := T.Count + 1;
         T.Segs (T.Count) := (Kind => Span, Robot => Robot, First => First,
                              Last => Last, Reversed => Reversed, Task_Id => 0, Loc => 0);
      end if;
   end Add;

   procedure Add_Single (T : in out Tour_Plan; Task_Id, Loc : Positive) is
   begin
      T.Count := T.Count + 1;
      T.Segs (T.Count) := (Kind => Single, Task_Id => Task_Id, Loc => Loc, Robot => 1,
                           First => 1, Last => 0, Reversed => False);
   end Add_Single;

   procedure Eval_Tour
     (P : Problem; S : State; T : Tour_Plan; Length, Completion : out Cost;
      Count : out Natural)
   is
      R    : constant Positive := T.Robot;
      Here : Natural := P.Start (R);
      Time : Cost := 0;
      Sum  : Cost := 0;
      Bad  : Natural := 0;
      M    : constant Cost := Cost (P.Multiplier (R));
   begin
      Count := 0;
      for K in 1 .. T.Count loop
         declare
            G : Seg renames T.Segs (K);
         begin
            if G.Kind = Single then
               Time := Time + Robot_Distance (P, R, Here, G.Loc);
               Sum := Sum + Time;
               Here := G.Loc;
               Count := Count + 1;
               if not P.Can_Do (R, G.Task_Id) then
                  Bad := Bad + 1;
               end if;
            else
               declare
                  RS : constant Positive := G.Robot;
                  N  : constant Cost := Cost (G.Last - G.First + 1);
               begin
                  if RS /= R and then (Has_Own_Costs (P, R) or else Has_Own_Costs (P, RS)) then
                     --  Another robot's segment in a different metric: arc
                     --  by arc in R's own costs (its prefix sums are RS's).
                     for K2 in G.First .. G.Last loop
                        declare
                           I : constant Positive :=
                             (if G.Reversed then G.Last - (K2 - G.First) else K2);
                        begin
                           Time := Time + Robot_Distance (P, R, Here, S.Lc (RS, I));
                           Sum := Sum + Time;
                           Here := S.Lc (RS, I);
                        end;
                     end loop;
                  elsif not G.Reversed then
                     Time := Time + Robot_Distance (P, R, Here, S.Lc (RS, G.First));
                     Sum := Sum + N * (Time - S.Fw (RS, G.First))
                       + S.PF (RS, G.Last) - S.PF (RS, G.First - 1);
                     Time := Time + S.Fw (RS, G.Last) - S.Fw (RS, G.First);
                     Here := S.Lc (RS, G.Last);
                  else
                     Time := Time + Robot_Distance (P, R, Here, S.Lc (RS, G.Last));
                     Sum := Sum + N * (Time + S.Rv (RS, G.Last))
                       - (S.PR (RS, G.Last) - S.PR (RS, G.First - 1));
                     Time := Time + S.Rv (RS, G.Last) - S.Rv (RS, G.First);
                     Here := S.Lc (RS, G.First);
                  end if;
                  Count := Count + Natural (N);
                  if not P.All_Feasible then
                     for I in G.First .. G.Last loop
                        if not P.Can_Do (R, S.Tk (RS, I)) then
                           Bad := Bad + 1;
                        end if;
                     end loop;
                  end if;
               end;
            end if;
         end;
      end loop;
      Time := Time + Robot_Distance (P, R, Here, P.Finish (R));
      Length := M * Time + Cost (Bad) * Infinity;
      Completion := M * Sum + Cost (Bad) * Infinity;
   end Eval_Tour;

   type Weights is record
      C   : Criterion;
      Tie : Long_Float := 0.0;  --  weight of Sum added to break MinMax ties
   end record;

   function Objective (W : Weights; Max, Sum, Comp : Cost; Tasks : Natural)
     return Long_Float
   is (Value (W.C, Max, Sum, Comp, Tasks) + W.Tie * Long_Float (Sum));

   function Current_Value (P : Problem; S : State; W : Weights) return Long_Float is
     (Objective (W, Current_Max (S), S.Sum, S.Comp, Natural'Min (S.N_Active, P.Tasks)));

   procedure Evaluate_Move
     (P : Problem; S : State; W : Weights; Mv : in out Move; Valid : out Boolean)
   is
      A : constant Natural := Mv.A.Robot;
      --  Positive but for a switch subtree move (no tour plans).
      B : constant Natural := Mv.B.Robot;
      Max, Sum, Comp : Cost;
   begin
      if Mv.Or_Node /= 0 then
         --  Switch subtree: evaluated when proposed (Gen_Switch_Subtree).
         Valid := True;
         return;
      end if;
      Mv.New_Active := S.N_Active;
      Eval_Tour (P, S, Mv.A, Mv.New_A_Cost, Mv.New_A_Comp, Mv.New_A_Len);
      Valid := Mv.New_A_Len >= P.Min_Tasks or else Mv.New_A_Len >= S.Len (A);
      Sum := S.Sum - S.RC (A) + Mv.New_A_Cost;
      Comp := S.Comp - S.RCm (A) + Mv.New_A_Comp;
      Max := (if W.C.Max_Weight = 0.0 then 0
              else Cost'Max (Max_Except (S, A, B), Mv.New_A_Cost));
      --  The makespan only when the criterion uses it (saves O (log R)).
      if B /= 0 then
         Eval_Tour (P, S, Mv.B, Mv.New_B_Cost, Mv.New_B_Comp, Mv.New_B_Len);
         Valid := Valid and then
           (Mv.New_B_Len >= P.Min_Tasks or else Mv.New_B_Len >= S.Len (B));
         Sum := Sum - S.RC (B) + Mv.New_B_Cost;
         Comp := Comp - S.RCm (B) + Mv.New_B_Comp;
         if W.C.Max_Weight /= 0.0 then
            Max := Cost'Max (Max, Mv.New_B_Cost);
         end if;
      end if;
      Mv.New_Max := Max;
      Mv.New_Sum := Sum;
      Mv.New_Comp := Comp;
      Mv.Value := Objective (W, Max, Sum, Comp, S.N_Active);
   end Evaluate_Move;

   --  Writes a planned tour into Buf (tasks), returns the first position
   --  that differs from the current tour of T.Robot (prefix kept).
   procedure Render (S : State; T : Tour_Plan; Buf : in out Count_Array; Len : out Natural;
                     Keep : out Natural) is
      First_Seg : Positive := 1;
   begin
      Len := 0;
      Keep := 0;
      if T.Count >= 1 and then T.Segs (1).Kind = Span and then T.Segs (1).Robot = T.Robot
        and then not T.Segs (1).Reversed and then T.Segs (1).First = 1
      then
         Keep := T.Segs (1).Last;
         Len := Keep;
         First_Seg := 2;
      end if;
      for K in First_Seg .. T.Count loop
         declare
            G : Seg renames T.Segs (K);
         begin
            if G.Kind = Single then
               Len := Len + 1;
               Buf (Len) := G.Task_Id;
            elsif not G.Reversed then
               for I in G.First .. G.Last loop
                  Len := Len + 1;
                  Buf (Len) := S.Tk (G.Robot, I);
               end loop;
            else
               for I in reverse G.First .. G.Last loop
                  Len := Len + 1;
                  Buf (Len) := S.Tk (G.Robot, I);
               end loop;
            end if;
         end;
      end loop;
   end Render;

   procedure Apply (P : Problem; S : in out State; Mv : Move) is
      LA, LB, KA, KB : Natural := 0;
      Buf_A, Buf_B : Count_Array (1 .. S.NP);
      A : constant Positive := Mv.A.Robot;
      B : constant Natural := Mv.B.Robot;
   begin
      Render (S, Mv.A, Buf_A, LA, KA);
      if B /= 0 then
         Render (S, Mv.B, Buf_B, LB, KB);
      end if;
      if Mv.Switch_Task /= 0 then
         S.Choice (Mv.Switch_Task) := Mv.Switch_To;
      end if;
      for I in KA + 1 .. LA loop
         S.Tk (A, I) := Buf_A (I);
      end loop;
      S.Len (A) := LA;
      if B /= 0 then
         for I in KB + 1 .. LB loop
            S.Tk (B, I) := Buf_B (I);
         end loop;
         S.Len (B) := LB;
      end if;
      Rebuild (P, S, A, KA + 1);
      if B /= 0 then
         Rebuild (P, S, B, KB + 1);
      end if;
   end Apply;

   ---------------------------------------------------------------------------
   --  Expensive check.

   procedure Verify (P : Problem; S : State; Mv : Move; Predicted : Boolean) is
      Sum, Comp, Max : Cost := 0;
      Seen : Count_Array (1 .. S.NT) := [others => 0];

      procedure Fail (What : String) with No_Return;
      procedure Fail (What : String) is
      begin
         raise Program_Error with "annealer check failed: " & What;
      end Fail;
   begin
      for R in 1 .. S.NR loop
         declare
            Here : Natural := P.Start (R);
            Time, CSum : Cost := 0;
            Bad : Natural := 0;
            M : constant Cost := Cost (P.Multiplier (R));
            RC, RCm : Cost;
         begin
            if S.Len (R) < P.Frozen_Length (R) then
               Fail ("robot" & R'Image & " lost frozen tasks");
            end if;
            for I in 1 .. S.Len (R) loop
               declare
                  T : constant Positive := S.Tk (R, I);
                  L : constant Natural := Location_Of (P, T, S.Choice (T));
               begin
                  if I <= P.Frozen_Length (R) and then P.Frozen (R, I) /= T then
                     Fail ("frozen prefix of robot" & R'Image & " changed");
                  end if;
                  Seen (T) := Seen (T) + 1;
                  if S.Own (T) /= R or else S.Pos (T) /= I then
                     Fail ("position index of task" & T'Image);
                  end if;
                  Time := Time + Robot_Distance (P, R, Here, L);
                  CSum := CSum + Time;
                  if not P.Can_Do (R, T) then
                     Bad := Bad + 1;
                  end if;
                  Here := L;
               end;
            end loop;
            Time := Time + Robot_Distance (P, R, Here, P.Finish (R));
            RC := M * Time + Cost (Bad) * Infinity;
            RCm := M * CSum + Cost (Bad) * Infinity;
            if RC /= S.RC (R) or else RCm /= S.RCm (R) then
               Fail ("robot" & R'Image & " cost" & S.RC (R)'Image & " /" & S.RCm (R)'Image
                     & " recomputed" & RC'Image & " /" & RCm'Image);
            end if;
            if Predicted then
               if R = Mv.A.Robot and then (RC /= Mv.New_A_Cost or else RCm /= Mv.New_A_Comp) then
                  Fail ("move prediction for robot" & R'Image & ":" & Mv.New_A_Cost'Image
                        & " /" & Mv.New_A_Comp'Image & " actual" & RC'Image & " /" & RCm'Image);
               end if;
               if R = Mv.B.Robot and then (RC /= Mv.New_B_Cost or else RCm /= Mv.New_B_Comp) then
                  Fail ("move prediction for robot" & R'Image & ":" & Mv.New_B_Cost'Image
                        & " actual" & RC'Image);
               end if;
            end if;
            Sum := Sum + RC;
            Comp := Comp + RCm;
            Max := Cost'Max (Max, RC);
         end;
      end loop;
      for T in 1 .. S.NT loop
         if S.Active (T) /= Is_Active (P, S.Sel, T) then
            Fail ("active flag of task" & T'Image);
         elsif Seen (T) /= (if S.Active (T) then 1 else 0) then
            Fail ("task" & T'Image & " (active: " & S.Active (T)'Image & ") appears"
                  & Seen (T)'Image & " times");
         elsif not S.Active (T) and then S.Own (T) /= 0 then
            Fail ("inactive task" & T'Image & " has an owner");
         end if;
      end loop;
      if Active_Count (P, S.Sel) /= S.N_Active then
         Fail ("active count" & S.N_Active'Image);
      end if;
      if Predicted and then Mv.Or_Node /= 0
        and then (Mv.New_Sum /= S.Sum or else Mv.New_Comp /= S.Comp
                  or else Mv.New_Max /= Current_Max (S) or else Mv.New_Active /= S.N_Active)
      then
         Fail ("switch subtree prediction: sum" & Mv.New_Sum'Image & " actual" & S.Sum'Image
               & ", completion" & Mv.New_Comp'Image & " actual" & S.Comp'Image
               & ", max" & Mv.New_Max'Image & " actual" & Current_Max (S)'Image);
      end if;
      if Sum /= S.Sum or else Comp /= S.Comp or else Max /= Current_Max (S) then
         Fail ("totals: sum" & S.Sum'Image & " vs" & Sum'Image & ", max"
               & Current_Max (S)'Image & " vs" & Max'Image);
      end if;
   end Verify;

   ---------------------------------------------------------------------------
   --  Set-up.

   procedure Compute_Neighbours (P : Problem; S : in out State) is
      K : constant Positive := S.NK;
      Dist : Cost_Array (1 .. K) := [others => 0];
   begin
      for T in 1 .. S.NT loop
         declare
            LT : constant Natural := Location_Of (P, T);
            N  : Natural := 0;
         begin
            for U in 1 .. S.NT loop
               if U /= T then
                  declare
                     LU : constant Natural := Location_Of (P, U);
                     D  : constant Cost :=
                       Cost'Min (P.Distance (LT, LU), P.Distance (LU, LT));
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
      S.Sel := A.Branch;
      S.N_Active := 0;
      for T in 1 .. S.NT loop
         S.Active (T) := Is_Active (P, S.Sel, T);
         if S.Active (T) then
            S.N_Active := S.N_Active + 1;
         end if;
         S.Own (T) := 0;
         S.Pos (T) := 0;
      end loop;
      S.Sum := 0;
      S.Comp := 0;
      S.RC := [others => 0];
      S.RCm := [others => 0];
      for R in 1 .. S.NR loop
         S.Len (R) := A.Length (R);
         for I in 1 .. A.Length (R) loop
            S.Tk (R, I) := A.Tour (R, I);
         end loop;
         Rebuild (P, S, R, 1);
      end loop;
   end Load;

   procedure Store (S : State; A : in out Assignment) is
   begin
      A.Choice := S.Choice;
      A.Branch := S.Sel;
      for R in 1 .. S.NR loop
         A.Length (R) := S.Len (R);
         for I in 1 .. S.Len (R) loop
            A.Tour (R, I) := S.Tk (R, I);
         end loop;
      end loop;
   end Store;

   function Make_Weights (P : Problem; C : Criterion; Scale_Sum : Cost) return Weights is
   begin
      if C.Sum_Weight = 0.0 and then C.Ave_Weight = 0.0 and then P.Robots > 1 then
         --  Pure makespan: plateaus everywhere; a tiny total-cost term
         --  breaks ties without ever trading a unit of makespan.
         return (C, 0.5 / Long_Float (Cost'Max (1, Scale_Sum) * Cost (P.Robots)));
      end if;
      return (C, 0.0);
   end Make_Weights;

   --  Insert task T (unassigned) at its best place.
   procedure Best_Insert (P : Problem; S : in out State; W : Weights; T : Positive;
                          Only : Natural := 0) is
      Best : Move;
      Best_Value : Long_Float := Long_Float'Last;
      Found : Boolean := False;
      L : constant Natural := Location_Of (P, T, S.Choice (T));
   begin
      for R in 1 .. S.NR loop
         if (Only = 0 or else R = Only) and then P.Can_Do (R, T) then
            for After in P.Frozen_Length (R) .. S.Len (R) loop
               declare
                  Mv : Move;
                  Ok : Boolean;
               begin
                  Mv.A.Robot := R;
                  Add (Mv.A, R, 1, After);
                  Add_Single (Mv.A, T, L);
                  Add (Mv.A, R, After + 1, S.Len (R));
                  Evaluate_Move (P, S, W, Mv, Ok);
                  if Mv.Value < Best_Value then
                     Best_Value := Mv.Value;
                     Best := Mv;
                     Found := True;
                  end if;
               end;
            end loop;
         end if;
      end loop;
      if not Found then
         raise Program_Error with "no robot can do task" & T'Image;
      end if;
      Apply (P, S, Best);
   end Best_Insert;

   --  Takes the tasks of List out of their tours (they must be movable).
   procedure Shuffle (G : in out Random.Generator; Items : in out Count_Array; Last : Natural)
     with Pre => Items'First = 1 and then Last <= Items'Last;
   --  Fisher-Yates shuffle of Items (1 .. Last).

   procedure Shuffle (G : in out Random.Generator; Items : in out Count_Array; Last : Natural) is
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

   procedure Remove_Tasks (P : Problem; S : in out State; List : Count_Array) is
      Gone : Boolean_Array (1 .. S.NT) := [others => False];
      First : Count_Array (1 .. S.NR) := [others => 0];
   begin
      for T of List loop
         Gone (T) := True;
         declare
            R : constant Positive := S.Own (T);
         begin
            if First (R) = 0 or else S.Pos (T) < First (R) then
               First (R) := S.Pos (T);
            end if;
         end;
      end loop;
      for R in 1 .. S.NR loop
         if First (R) /= 0 then
            declare
               N : Natural := First (R) - 1;
            begin
               for I in First (R) .. S.Len (R) loop
                  if not Gone (S.Tk (R, I)) then
                     N := N + 1;
                     S.Tk (R, N) := S.Tk (R, I);
                  end if;
               end loop;
               S.Len (R) := N;
               Rebuild (P, S, R, First (R));
            end;
         end if;
      end loop;
   end Remove_Tasks;

   procedure Construct (P : Problem; S : in out State; C : Criterion; G : in out Gen) is
      Order : Count_Array (1 .. P.Tasks);
      N     : Natural := 0;
      Done  : Boolean_Array (1 .. P.Tasks) := [others => False];
      W     : Weights := (C, 0.0);
      Empty_A : Assignment := Empty (P);
   begin
      if Has_Plan (P) then
         Empty_A.Branch := Cheapest_Selection (P);
      end if;
      Load (P, S, Empty_A);
      for T in 1 .. P.Tasks loop
         if not P.Is_Frozen (T) and then S.Active (T) then
            N := N + 1;
            Order (N) := T;
         end if;
      end loop;
      Shuffle (G, Order, N);
      --  Minimum counts first: the nearest free feasible task to each start.
      for R in 1 .. P.Robots loop
         while S.Len (R) < P.Min_Tasks loop
            declare
               Best : Natural := 0;
               BD   : Cost := Cost'Last;
            begin
               for K in 1 .. N loop
                  declare
                     T : constant Positive := Order (K);
                  begin
                     if not Done (T) and then P.Can_Do (R, T)
                       and then P.Distance (P.Start (R), Location_Of (P, T)) < BD
                     then
                        BD := P.Distance (P.Start (R), Location_Of (P, T));
                        Best := T;
                     end if;
                  end;
               end loop;
               exit when Best = 0;
               Done (Best) := True;
               Best_Insert (P, S, W, Best, Only => R);
            end;
         end loop;
      end loop;
      W := Make_Weights (P, C, 1 + S.Sum * Cost (P.Tasks));
      for K in 1 .. N loop
         if not Done (Order (K)) then
            Best_Insert (P, S, W, Order (K));
         end if;
      end loop;
   end Construct;

   ---------------------------------------------------------------------------
   --  Move generators. Each fills Mv and returns Ok = False when the draw
   --  does not give a legal move.

   function Movable (P : Problem; S : State; T : Positive) return Boolean is
     (S.Own (T) /= 0 and then S.Pos (T) > P.Frozen_Length (S.Own (T)));
   --  Active (in a tour) and not frozen.

   function Random_Task (P : Problem; S : State; G : in out Gen) return Natural is
   begin
      if S.N_Active < S.NT then
         --  Plan trees: a uniform pick among the tasks in the tours (O (R)).
         for Try in 1 .. 8 loop
            declare
               K : Natural := Random.Below (G, Positive'Max (1, S.N_Active));
            begin
               for R in 1 .. S.NR loop
                  if K < S.Len (R) then
                     if K + 1 > P.Frozen_Length (R) then
                        return S.Tk (R, K + 1);
                     end if;
                     exit;
                  end if;
                  K := K - S.Len (R);
               end loop;
            end;
         end loop;
         return 0;
      end if;
      for Try in 1 .. 8 loop
         declare
            T : constant Positive := 1 + Random.Below (G, S.NT);
         begin
            if Movable (P, S, T) then
               return T;
            end if;
         end;
      end loop;
      return 0;
   end Random_Task;

   --  Move the tasks at positions I .. J of robot R1 to after position Q of
   --  robot R2 (Q in the current numbering of R2), reversed or not.
   procedure Relocate (S : State; Mv : in out Move; R1 : Positive; I, J : Positive;
                       R2 : Positive; Q : Natural; Rev : Boolean; Ok : out Boolean;
                       New_Loc : Natural := 0)
   is
      --  With New_Loc /= 0 (I = J), the task moves to its new OR choice there.
      procedure Moved (T : in out Tour_Plan) is
      begin
         if New_Loc /= 0 then
            Add_Single (T, S.Tk (R1, I), New_Loc);
         else
            Add (T, R1, I, J, Rev);
         end if;
      end Moved;
   begin
      Clear (Mv);
      Ok := True;
      if R1 /= R2 then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, J + 1, S.Len (R1));
         Mv.B.Robot := R2;
         Add (Mv.B, R2, 1, Q);
         Moved (Mv.B);
         Add (Mv.B, R2, Q + 1, S.Len (R2));
      elsif Q + 1 < I then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, Q);
         Moved (Mv.A);
         Add (Mv.A, R1, Q + 1, I - 1);
         Add (Mv.A, R1, J + 1, S.Len (R1));
      elsif Q > J then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, J + 1, Q);
         Moved (Mv.A);
         Add (Mv.A, R1, Q + 1, S.Len (R1));
      elsif New_Loc /= 0 then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Moved (Mv.A);
         Add (Mv.A, R1, J + 1, S.Len (R1));
      elsif Rev and then I < J then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, I, J, True);
         Add (Mv.A, R1, J + 1, S.Len (R1));
      else
         Ok := False;
      end if;
   end Relocate;

   procedure Gen_Or_Opt
     (P : Problem; S : State; G : in out Gen; T : Positive; U_Index : Positive;
      Seg_Len : Positive; Variant : Natural; Mv : in out Move; Ok : out Boolean)
   is
      R1 : constant Positive := S.Own (T);
      I  : constant Positive := S.Pos (T);
      J  : constant Positive := Positive'Min (I + Seg_Len - 1, S.Len (R1));
      U  : constant Natural := S.Near (T, U_Index);
      R2 : Positive;
      Q  : Natural;
      Rev : Boolean;
      pragma Unreferenced (G);
   begin
      Ok := False;
      if U = 0 or else S.Own (U) = 0 then
         return;
      end if;
      R2 := S.Own (U);
      --  0: after U, forward (U -> T); 1: before U, reversed (T -> U);
      --  2: after U, reversed; 3: before U, forward.
      case Variant mod 4 is
         when 0 => Q := S.Pos (U); Rev := False;
         when 1 => Q := S.Pos (U) - 1; Rev := True;
         when 2 => Q := S.Pos (U); Rev := True;
         when others => Q := S.Pos (U) - 1; Rev := False;
      end case;
      if Q < P.Frozen_Length (R2) then
         return;
      end if;
      if R2 = R1 and then Q + 1 >= I and then Q <= J then
         return;
      end if;
      Relocate (S, Mv, R1, I, J, R2, Q, Rev, Ok);
   end Gen_Or_Opt;

   procedure Gen_Two_Opt
     (P : Problem; S : State; T : Positive; U_Index : Positive; Variant : Natural;
      Mv : in out Move; Ok : out Boolean)
   is
      R1 : constant Positive := S.Own (T);
      I  : constant Positive := S.Pos (T);
      U  : constant Natural := S.Near (T, U_Index);
      R2 : Positive;
      J  : Positive;
   begin
      Ok := False;
      if U = 0 or else S.Own (U) = 0 then
         return;
      end if;
      R2 := S.Own (U);
      J := S.Pos (U);
      Clear (Mv);
      if R1 = R2 then
         declare
            Lo, Hi : Natural;
         begin
            if I < J then
               if Variant mod 2 = 0 then
                  Lo := I + 1; Hi := J;       --  T, U adjacent after
               else
                  Lo := I; Hi := J - 1;
               end if;
            else
               if Variant mod 2 = 0 then
                  Lo := J + 1; Hi := I;
               else
                  Lo := J; Hi := I - 1;
               end if;
            end if;
            if Hi <= Lo or else Lo <= P.Frozen_Length (R1) then
               return;
            end if;
            Mv.A.Robot := R1;
            Add (Mv.A, R1, 1, Lo - 1);
            Add (Mv.A, R1, Lo, Hi, True);
            Add (Mv.A, R1, Hi + 1, S.Len (R1));
            Ok := True;
         end;
      else
         Mv.A.Robot := R1;
         Mv.B.Robot := R2;
         if Variant mod 4 = 2 then
            --  Crossed, new arc T -> U: R1: 1..I then R2's J..1 reversed;
            --  R2: R1's I+1..end reversed then R2's J+1.. (tours through a
            --  common depot are cycles: this is 2-opt across two of them).
            if P.Frozen_Length (R2) > 0 or else I < P.Frozen_Length (R1) then
               return;
            end if;
            Add (Mv.A, R1, 1, I);
            Add (Mv.A, R2, 1, J, True);
            Add (Mv.B, R1, I + 1, S.Len (R1), True);
            Add (Mv.B, R2, J + 1, S.Len (R2));
         elsif Variant mod 4 = 3 then
            --  Crossed, new arc U -> T: R1: R2's end..J reversed then R1's
            --  I..; R2: 1..J-1 then R1's 1..I-1 reversed.
            if P.Frozen_Length (R1) > 0 or else J - 1 < P.Frozen_Length (R2) then
               return;
            end if;
            Add (Mv.A, R2, J, S.Len (R2), True);
            Add (Mv.A, R1, I, S.Len (R1));
            Add (Mv.B, R2, 1, J - 1);
            Add (Mv.B, R1, 1, I - 1, True);
         elsif Variant mod 2 = 0 then
            --  R1: 1..I then R2's J..; R2: 1..J-1 then R1's I+1..
            if J - 1 < P.Frozen_Length (R2) then
               return;
            end if;
            Add (Mv.A, R1, 1, I);
            Add (Mv.A, R2, J, S.Len (R2));
            Add (Mv.B, R2, 1, J - 1);
            Add (Mv.B, R1, I + 1, S.Len (R1));
         else
            --  R2: 1..J then R1's I..; R1: 1..I-1 then R2's J+1..
            if J < P.Frozen_Length (R2) then
               return;
            end if;
            Add (Mv.A, R1, 1, I - 1);
            Add (Mv.A, R2, J + 1, S.Len (R2));
            Add (Mv.B, R2, 1, J);
            Add (Mv.B, R1, I, S.Len (R1));
         end if;
         Ok := True;
      end if;
   end Gen_Two_Opt;

   --  Or-3opt (segment exchange within a tour, any segment lengths), both
   --  new arcs next to candidate neighbours: with T at position A and U at
   --  B + 1 (U near T), the tour 1..A, A+1..B, B+1..C, C+1.. becomes
   --  1..A, B+1..C, A+1..B, C+1.. where C is the position of V, a neighbour
   --  of the task at A + 1 (Variant 0: arcs T-U, V-(A+1), B-(C+1)), or of
   --  the task at B with A+1..B reversed (Variant 1: arcs T-U, V-B,
   --  (A+1)-(C+1)).
   procedure Gen_Or3
     (P : Problem; S : State; T : Positive; U_Index, V_Index : Positive; Variant : Natural;
      Mv : in out Move; Ok : out Boolean)
   is
      R  : constant Positive := S.Own (T);
      A  : constant Positive := S.Pos (T);
      U  : constant Natural := S.Near (T, U_Index);
      B, C : Natural;
      Pivot, V : Natural;
   begin
      Ok := False;
      if U = 0 or else S.Own (U) /= R or else S.Pos (U) < A + 2
        or else A < P.Frozen_Length (R)
      then
         return;
      end if;
      B := S.Pos (U) - 1;
      Pivot := S.Tk (R, (if Variant mod 2 = 0 then A + 1 else B));
      V := S.Near (Pivot, V_Index);
      if V = 0 or else S.Own (V) /= R or else S.Pos (V) <= B then
         return;
      end if;
      C := S.Pos (V);
      Clear (Mv);
      Mv.A.Robot := R;
      Add (Mv.A, R, 1, A);
      Add (Mv.A, R, B + 1, C);
      Add (Mv.A, R, A + 1, B, Reversed => Variant mod 2 = 1);
      Add (Mv.A, R, C + 1, S.Len (R));
      Ok := True;
   end Gen_Or3;

   procedure Gen_Cross
     (P : Problem; S : State; T : Positive; U_Index : Positive; L1, L2 : Natural;
      Mv : in out Move; Ok : out Boolean)
   is
      R1 : constant Positive := S.Own (T);
      I  : constant Positive := S.Pos (T);
      U  : constant Natural := S.Near (T, U_Index);
      R2 : Positive;
      J  : Positive;
      E1, E2 : Natural;
   begin
      Ok := False;
      if U = 0 or else S.Own (U) = 0 then
         return;
      end if;
      R2 := S.Own (U);
      J := S.Pos (U);
      if R1 = R2 or else J < P.Frozen_Length (R2) then
         return;
      end if;
      E1 := Natural'Min (I + L1 - 1, S.Len (R1));
      E2 := Natural'Min (J + L2, S.Len (R2));
      Clear (Mv);
      Mv.A.Robot := R1;
      Add (Mv.A, R1, 1, I - 1);
      Add (Mv.A, R2, J + 1, E2);
      Add (Mv.A, R1, E1 + 1, S.Len (R1));
      Mv.B.Robot := R2;
      Add (Mv.B, R2, 1, J);
      Add (Mv.B, R1, I, E1);
      Add (Mv.B, R2, E2 + 1, S.Len (R2));
      Ok := True;
   end Gen_Cross;

   procedure Gen_Swap (P : Problem; S : State; T, U : Positive; Mv : in out Move;
                       Ok : out Boolean) is
      R1 : constant Positive := S.Own (T);
      R2 : constant Positive := S.Own (U);
      I  : Positive := S.Pos (T);
      J  : Positive := S.Pos (U);
      pragma Unreferenced (P);
   begin
      Ok := False;
      if T = U then
         return;
      end if;
      Clear (Mv);
      if R1 = R2 then
         if J < I then
            declare
               X : constant Positive := I;
            begin
               I := J;
               J := X;
            end;
         end if;
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, J, J);
         Add (Mv.A, R1, I + 1, J - 1);
         Add (Mv.A, R1, I, I);
         Add (Mv.A, R1, J + 1, S.Len (R1));
      else
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R2, J, J);
         Add (Mv.A, R1, I + 1, S.Len (R1));
         Mv.B.Robot := R2;
         Add (Mv.B, R2, 1, J - 1);
         Add (Mv.B, R1, I, I);
         Add (Mv.B, R2, J + 1, S.Len (R2));
      end if;
      Ok := True;
   end Gen_Swap;

   function Random_Robot_Position (P : Problem; S : State; G : in out Gen; R : Positive)
     return Natural is
     (P.Frozen_Length (R) + Random.Below (G, S.Len (R) - P.Frozen_Length (R) + 1));

   --  A random re-insertion of task T: robot (other than T's own when
   --  Other), position; Ok False when illegal.
   procedure Gen_Insert (P : Problem; S : State; G : in out Gen; T : Positive;
                         Other : Boolean; Mv : in out Move; Ok : out Boolean) is
      R1 : constant Positive := S.Own (T);
      R2 : Positive;
      Q  : Natural;
   begin
      Ok := False;
      if Other then
         if S.NR = 1 then
            return;
         end if;
         R2 := 1 + Random.Below (G, S.NR - 1);
         if R2 >= R1 then
            R2 := R2 + 1;
         end if;
      else
         R2 := (if Random.Below (G, 2) = 0 then R1 else 1 + Random.Below (G, S.NR));
      end if;
      Q := Random_Robot_Position (P, S, G, R2);
      if R2 = R1 and then (Q = S.Pos (T) or else Q + 1 = S.Pos (T)) then
         return;
      end if;
      Relocate (S, Mv, R1, S.Pos (T), S.Pos (T), R2, Q, False, Ok);
   end Gen_Insert;

   ---------------------------------------------------------------------------
   --  Switch subtree (plan trees): choose another alternative at an OR node;
   --  the tasks that become inactive leave their tours, those that become
   --  active are inserted (cheapest insertion in added length, or at random
   --  places). The new tours of all robots are built in a Pending record and
   --  the touched robots' costs recomputed exactly (integers): the move's
   --  sum, completion and makespan are exact, Apply_Subtree then installs
   --  them and rebuilds only the touched robots.

   type Pending (NR, NP, NT, NI : Positive) is record
      Tk      : Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      Lc      : Grid (1 .. NR, 0 .. NP) := [others => [others => 0]];
      --  The tasks' locations.
      Len     : Count_Array (1 .. NR) := [others => 0];
      Changed : Boolean_Array (1 .. NR) := [others => False];
      RC, RCm : Cost_Array (1 .. NR) := [others => 0];
      Sel     : Location_Array (1 .. NT) := [others => 1];
      Gone    : Boolean_Array (1 .. NT) := [others => False];
      Added   : Count_Array (1 .. NT) := [others => 0];
      Or_Node : Natural := 0;
      New_Active : Natural := 0;
      Under_First : Count_Array (1 .. NP) := [others => 1];
      Under   : Count_Array (1 .. NI) := [others => 0];
      --  The tasks below each OR ordinal O: Under (Under_First (O) ..
      --  Under_First (O + 1) - 1) (fixed for the run; NP = NT + 1).
   end record;

   procedure Set_Under (P : Problem; D : in out Pending) is
      Count : Count_Array (1 .. D.NT + 1) := [others => 0];
   begin
      for T in 1 .. P.Tasks loop
         declare
            X : Natural := P.Task_Or (T);
         begin
            while X /= 0 loop
               Count (X) := Count (X) + 1;
               X := Or_Parent (P, X);
            end loop;
         end;
      end loop;
      D.Under_First (1) := 1;
      for O in 1 .. D.NT loop
         D.Under_First (O + 1) := D.Under_First (O) + Count (O);
      end loop;
      Count := [others => 0];
      for T in 1 .. P.Tasks loop
         declare
            X : Natural := P.Task_Or (T);
         begin
            while X /= 0 loop
               D.Under (D.Under_First (X) + Count (X)) := T;
               Count (X) := Count (X) + 1;
               X := Or_Parent (P, X);
            end loop;
         end;
      end loop;
   end Set_Under;

   function Under_Size (P : Problem) return Positive is
      N : Natural := 0;
   begin
      for T in 1 .. P.Tasks loop
         declare
            X : Natural := P.Task_Or (T);
         begin
            while X /= 0 loop
               N := N + 1;
               X := Or_Parent (P, X);
            end loop;
         end;
      end loop;
      return Positive'Max (1, N);
   end Under_Size;
   type Pending_Access is access Pending;
   procedure Free is new Ada.Unchecked_Deallocation (Pending, Pending_Access);

   function Pending_Loc (P : Problem; D : Pending; R : Positive; Q : Natural) return Natural
   is (if Q = 0 then P.Start (R) elsif Q > D.Len (R) then P.Finish (R) else D.Lc (R, Q));

   procedure Pending_Costs (P : Problem; S : State; D : in out Pending; R : Positive) is
      Here : Natural := P.Start (R);
      Time, Sum : Cost := 0;
      Bad  : Natural := 0;
      M    : constant Cost := Cost (P.Multiplier (R));
   begin
      for I in 1 .. D.Len (R) loop
         declare
            T : constant Positive := D.Tk (R, I);
            L : constant Natural := Location_Of (P, T, S.Choice (T));
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
      D.RC (R) := M * Time + Cost (Bad) * Infinity;
      D.RCm (R) := M * Sum + Cost (Bad) * Infinity;
   end Pending_Costs;

   procedure Gen_Switch_Subtree
     (P : Problem; S : State; G : in out Gen; W : Weights; Locked : Boolean_Array;
      D : in out Pending; Mv : in out Move; Ok : out Boolean)
   is
      O  : Natural := 0;
      NA : Natural := 0;
      Active_After : Natural := S.N_Active;
   begin
      Ok := False;
      Mv := No_Move;
      for Try in 1 .. 4 loop
         declare
            X : constant Positive := 1 + Random.Below (G, Or_Count (P));
         begin
            if not Locked (X) and then Alternatives (P, X) >= 2
              and then Or_Active (P, S.Sel, X)
            then
               O := X;
               exit;
            end if;
         end;
      end loop;
      if O = 0 then
         return;
      end if;
      D.Sel := S.Sel;
      D.Sel (O) := 1 + Random.Below (G, Alternatives (P, O) - 1);
      if D.Sel (O) >= S.Sel (O) then
         D.Sel (O) := D.Sel (O) + 1;
      end if;
      --  Which tasks leave and which come (only tasks below O can).
      for K in D.Under_First (O) .. D.Under_First (O + 1) - 1 loop
         declare
            T : constant Positive := D.Under (K);
            After : constant Boolean := Is_Active (P, D.Sel, T);
         begin
            D.Gone (T) := S.Active (T) and then not After;
            if After and then not S.Active (T) then
               NA := NA + 1;
               D.Added (NA) := T;
               Active_After := Active_After + 1;
            elsif D.Gone (T) then
               Active_After := Active_After - 1;
            end if;
         end;
      end loop;
      --  The current tours without the leaving tasks, and their costs.
      for R in 1 .. S.NR loop
         D.Len (R) := 0;
         D.Changed (R) := False;
         for I in 1 .. S.Len (R) loop
            if D.Gone (S.Tk (R, I)) then
               D.Changed (R) := True;
            else
               D.Len (R) := D.Len (R) + 1;
               D.Tk (R, D.Len (R)) := S.Tk (R, I);
               D.Lc (R, D.Len (R)) := S.Lc (R, I);
            end if;
         end loop;
         if D.Changed (R) then
            Pending_Costs (P, S, D, R);
         else
            D.RC (R) := S.RC (R);
         end if;
      end loop;
      for K in D.Under_First (O) .. D.Under_First (O + 1) - 1 loop
         D.Gone (D.Under (K)) := False;
      end loop;
      --  Insert the coming tasks in random order.
      Shuffle (G, D.Added, NA);
      declare
         Cheapest : constant Boolean := Random.Below (G, 4) /= 0;
      begin
         for K in 1 .. NA loop
            declare
               T : constant Positive := D.Added (K);
               L : constant Natural := Location_Of (P, T, S.Choice (T));
               Best_R : Natural := 0;
               Best_Q : Natural := 0;
               Best_D : Cost := Cost'Last;
               Best_K : Cost := Cost'Last;
               Makespan : constant Boolean :=
                 W.C.Max_Weight > 0.0 and then W.C.Sum_Weight = 0.0 and then W.C.Ave_Weight = 0.0;
               --  Pure makespan: the place giving the least robot cost
               --  (ties: least added cost); else the least added cost.
            begin
               if Cheapest then
                  for R in 1 .. S.NR loop
                     if P.Can_Do (R, T) then
                        for Q in P.Frozen_Length (R) .. D.Len (R) loop
                           declare
                              A  : constant Natural := Pending_Loc (P, D, R, Q);
                              B  : constant Natural := Pending_Loc (P, D, R, Q + 1);
                              DC : constant Cost := Cost (P.Multiplier (R))
                                * (Robot_Distance (P, R, A, L) + Robot_Distance (P, R, L, B)
                                   - Robot_Distance (P, R, A, B));
                              Key : constant Cost := (if Makespan then D.RC (R) + DC else DC);
                           begin
                              if Key < Best_K or else (Key = Best_K and then DC < Best_D) then
                                 Best_K := Key;
                                 Best_D := DC;
                                 Best_R := R;
                                 Best_Q := Q;
                              end if;
                           end;
                        end loop;
                     end if;
                  end loop;
               else
                  for Try in 1 .. 2 * S.NR loop
                     declare
                        R : constant Positive := 1 + Random.Below (G, S.NR);
                     begin
                        if P.Can_Do (R, T) then
                           Best_R := R;
                           Best_Q := P.Frozen_Length (R)
                             + Random.Below (G, D.Len (R) - P.Frozen_Length (R) + 1);
                           exit;
                        end if;
                     end;
                  end loop;
               end if;
               if Best_R = 0 then
                  return;
               end if;
               declare
                  A : constant Natural := Pending_Loc (P, D, Best_R, Best_Q);
                  B : constant Natural := Pending_Loc (P, D, Best_R, Best_Q + 1);
               begin
                  D.RC (Best_R) := D.RC (Best_R) + Cost (P.Multiplier (Best_R))
                    * (Robot_Distance (P, Best_R, A, L) + Robot_Distance (P, Best_R, L, B)
                       - Robot_Distance (P, Best_R, A, B));
               end;
               for I in reverse Best_Q + 1 .. D.Len (Best_R) loop
                  D.Tk (Best_R, I + 1) := D.Tk (Best_R, I);
                  D.Lc (Best_R, I + 1) := D.Lc (Best_R, I);
               end loop;
               D.Tk (Best_R, Best_Q + 1) := T;
               D.Lc (Best_R, Best_Q + 1) := L;
               D.Len (Best_R) := D.Len (Best_R) + 1;
               D.Changed (Best_R) := True;
            end;
         end loop;
      end;
      --  Exact costs of the touched robots.
      declare
         Sum  : Cost := S.Sum;
         Comp : Cost := S.Comp;
         Max  : Cost := 0;
      begin
         for R in 1 .. S.NR loop
            if D.Changed (R) then
               if D.Len (R) < P.Min_Tasks and then D.Len (R) < S.Len (R) then
                  return;
               end if;
               Pending_Costs (P, S, D, R);
               Sum := Sum - S.RC (R) + D.RC (R);
               Comp := Comp - S.RCm (R) + D.RCm (R);
               Max := Cost'Max (Max, D.RC (R));
            else
               Max := Cost'Max (Max, S.RC (R));
            end if;
         end loop;
         Mv.Or_Node := O;
         D.Or_Node := O;
         D.New_Active := Active_After;
         Mv.New_Sum := Sum;
         Mv.New_Comp := Comp;
         Mv.New_Max := Max;
         Mv.New_Active := Active_After;
         Mv.Value := Objective (W, Max, Sum, Comp, Active_After);
         Ok := True;
      end;
   end Gen_Switch_Subtree;

   procedure Apply_Subtree (P : Problem; S : in out State; D : Pending) is
   begin
      S.Sel := D.Sel;
      for K in D.Under_First (D.Or_Node) .. D.Under_First (D.Or_Node + 1) - 1 loop
         declare
            T : constant Positive := D.Under (K);
         begin
            S.Active (T) := Is_Active (P, S.Sel, T);
            if not S.Active (T) then
               S.Own (T) := 0;
               S.Pos (T) := 0;
            end if;
         end;
      end loop;
      S.N_Active := D.New_Active;
      for R in 1 .. S.NR loop
         if D.Changed (R) then
            S.Len (R) := D.Len (R);
            for I in 1 .. D.Len (R) loop
               S.Tk (R, I) := D.Tk (R, I);
            end loop;
            Rebuild (P, S, R, 1);
         end if;
      end loop;
   end Apply_Subtree;

   ---------------------------------------------------------------------------

   protected body Best_Box is
      procedure Post (A : Assignment; V : Long_Float) is
      begin
         Current := A;
         Current_Value := V;
         Posted := True;
      end Post;

      function Has_Value return Boolean is (Posted);
      function Value return Long_Float is (Current_Value);
      function Best return Assignment is (Current);
   end Best_Box;

   function Greedy_Start (P : Problem; C : Criterion; Seed : Interfaces.Unsigned_64)
     return Assignment
   is
      S : State_Access := new State (P.Robots, P.Tasks, 1, P.Tasks + 1, 2 * P.Robots);
      G : Gen := Random.Seeded (Seed);
   begin
      return A : Assignment (P.Robots, P.Tasks) do
         Construct (P, S.all, C, G);
         Store (S.all, A);
         Free (S);
      end return;
   end Greedy_Start;

   procedure Solve
     (P      : Problem;
      Opts   : Options;
      Best   : in out Assignment;
      Stats  : out Progress;
      Report : Reporter := null)
   is
      use Ada.Real_Time;
      K     : constant Positive := Positive'Min (Opts.Neighbours, Positive'Max (1, P.Tasks - 1));
      S     : State_Access := new State (P.Robots, P.Tasks, K, P.Tasks + 1, 2 * P.Robots);
      G     : Gen := Random.Seeded (Opts.Seed);
      Start : constant Time := Clock;
      Next_Report : Time := Start + To_Time_Span (Opts.Report_Every);
      W, WT : Weights;
      --  W guides the search, WT is the criterion (with its tie-break).
      Guide0 : Long_Float := 0.0;
      --  Pure makespan: W adds Guide * total cost, Guide decaying from
      --  Guide0 to WT.Tie over the budget (balances all tours early on).
      Cur, Best_Value : Long_Float;
      Best_Saved : Boolean := True;
      --  Best holds the best solution; False while the current solution is
      --  a better one not yet copied (copied before leaving it).
      Moves, Accepted, Last_Best_Move : Long_Long_Integer := 0;
      Switches : Long_Long_Integer := 0;
      T0, T1, Temp : Long_Float;
      Elapsed : Duration := 0.0;
      Best_Time : Duration := 0.0;
      type Real_Array is array (Move_Kind) of Long_Float;
      Weight : Real_Array := [Or_Opt_Near => 3.0, Two_Opt_Near => 3.0, Or3_Near => 2.0,
                              Cross_Near => 1.5,
                              Random_Move => 0.5, Move_Owner => 0.5, Guided_Move => 0.5,
                              Log_Auction => 0.5, Swap_Any => 0.5, Switch_Or => 0.5,
                              Segment_Move => 0.5, Random_Reverse => 0.5,
                              Switch_Subtree => 0.5, Ruin_Recreate => 0.0];
      --  Ruin_Recreate is not drawn: it runs on its share of evaluations.
      Score, Tries : Real_Array := [others => 0.0];
      Kinds : Kind_Stats_Array;
      Polish_Gain : Long_Float := 0.0;
      Backup : Assignment (P.Robots, P.Tasks);
      Runs : Positive := (if Opts.Runs > 0 then Opts.Runs else 1);
      Run  : Natural := 0;
      --  Geometric schedule: Runs independent anneals share the budget, each
      --  from a fresh start; Run is the current one (from 0).
      Runs_Decided : Boolean :=
        Opts.Runs > 0 or else Opts.Schedule /= Geometric
        or else (Opts.Time_Limit <= 0.0 and then Opts.Iterations <= 0);
      Ruin_Evals : Long_Long_Integer := 0;
      --  Move evaluations spent in ruin and recreate (best insertions).
      Has_Or : Boolean := False;
      D      : Pending_Access :=
        new Pending (P.Robots, P.Tasks + 1, P.Tasks, Under_Size (P));
      Locked : Boolean_Array (1 .. P.Tasks) := [others => False];
      --  Plan trees: the switch subtree move's new tours, and the OR
      --  ordinals it must not switch (above a frozen task).
      Log_Tries : constant Positive :=
        Natural (Long_Float'Floor (Log (Long_Float (P.Tasks)))) + 1;
      Stop : Boolean := False;
      Reheat_T : Long_Float;
      Since_Improve : Long_Long_Integer := 0;
      Cycle_Best : Long_Float;
      Cycle : Natural := 0;

      function Pick_Kind return Move_Kind is
         Total : Long_Float := 0.0;
         X     : Long_Float;
      begin
         for M in Move_Kind loop
            Total := Total + Weight (M);
         end loop;
         X := Random.Uniform (G) * Total;
         for M in Move_Kind loop
            X := X - Weight (M);
            if X < 0.0 then
               return M;
            end if;
         end loop;
         return Or_Opt_Near;
      end Pick_Kind;

      procedure Propose (Kind : Move_Kind; Mv : in out Move; Ok : out Boolean) is
         T : constant Natural := Random_Task (P, S.all, G);
      begin
         Ok := False;
         Mv.Switch_Task := 0;
         Mv.Or_Node := 0;
         if T = 0 then
            return;
         end if;
         if Kind = Switch_Subtree then
            Gen_Switch_Subtree (P, S.all, G, W, Locked, D.all, Mv, Ok);
            return;
         end if;
         case Kind is
            when Switch_Subtree =>
               null;
            when Or_Opt_Near =>
               Gen_Or_Opt (P, S.all, G, T, 1 + Random.Below (G, K), 1 + Random.Below (G, 3),
                           Random.Below (G, 4), Mv, Ok);
            when Two_Opt_Near =>
               Gen_Two_Opt (P, S.all, T, 1 + Random.Below (G, K), Random.Below (G, 4), Mv, Ok);
            when Or3_Near =>
               Gen_Or3 (P, S.all, T, 1 + Random.Below (G, K), 1 + Random.Below (G, K),
                        Random.Below (G, 2), Mv, Ok);
            when Cross_Near =>
               Gen_Cross (P, S.all, T, 1 + Random.Below (G, K), 1 + Random.Below (G, 3),
                          Random.Below (G, 4), Mv, Ok);
            when Random_Move =>
               declare
                  R : constant Positive := S.Own (T);
                  Q : constant Natural := Random_Robot_Position (P, S.all, G, R);
               begin
                  if Q /= S.Pos (T) and then Q + 1 /= S.Pos (T) then
                     Relocate (S.all, Mv, R, S.Pos (T), S.Pos (T), R, Q, False, Ok);
                  end if;
               end;
            when Move_Owner =>
               Gen_Insert (P, S.all, G, T, True, Mv, Ok);
            when Guided_Move | Log_Auction =>
               declare
                  Src : Natural := T;
                  Best_Mv : Move;
                  Found : Boolean := False;
                  Cand : Move;
                  C_Ok : Boolean;
               begin
                  if Kind = Guided_Move then
                     --  A random movable task of the robot with the worst cost.
                     declare
                        Worst : Positive := 1;
                        R_Len : Natural;
                     begin
                        for R in 2 .. S.NR loop
                           if S.RC (R) > S.RC (Worst) then
                              Worst := R;
                           end if;
                        end loop;
                        R_Len := S.Len (Worst) - P.Frozen_Length (Worst);
                        if R_Len = 0 then
                           return;
                        end if;
                        Src := S.Tk (Worst, P.Frozen_Length (Worst) + 1 + Random.Below (G, R_Len));
                     end;
                  end if;
                  for Try in 1 .. Log_Tries loop
                     Gen_Insert (P, S.all, G, Src, Kind = Guided_Move, Cand, C_Ok);
                     if C_Ok then
                        Evaluate_Move (P, S.all, W, Cand, C_Ok);
                        if C_Ok and then (not Found or else Cand.Value < Best_Mv.Value) then
                           Best_Mv := Cand;
                           Found := True;
                        end if;
                     end if;
                  end loop;
                  if Found then
                     Mv := Best_Mv;
                     Ok := True;
                  end if;
               end;
            when Segment_Move =>
               --  A random segment (any length) of T's tour, moved to a
               --  random place of a random robot, maybe reversed.
               declare
                  R1 : constant Positive := S.Own (T);
                  I  : constant Positive := S.Pos (T);
                  J  : constant Positive := I + Random.Below (G, S.Len (R1) - I + 1);
                  R2 : constant Positive := 1 + Random.Below (G, S.NR);
                  Q  : constant Natural := Random_Robot_Position (P, S.all, G, R2);
               begin
                  if R2 /= R1 or else Q + 1 < I or else Q > J then
                     Relocate (S.all, Mv, R1, I, J, R2, Q, Random.Below (G, 2) = 0, Ok);
                  end if;
               end;
            when Random_Reverse =>
               declare
                  R1 : constant Positive := S.Own (T);
                  I  : constant Positive := S.Pos (T);
                  J  : constant Positive := I + Random.Below (G, S.Len (R1) - I + 1);
               begin
                  if J > I then
                     Clear (Mv);
                     Mv.A.Robot := R1;
                     Add (Mv.A, R1, 1, I - 1);
                     Add (Mv.A, R1, I, J, True);
                     Add (Mv.A, R1, J + 1, S.Len (R1));
                     Ok := True;
                  end if;
               end;
            when Swap_Any =>
               declare
                  U : constant Natural := Random_Task (P, S.all, G);
               begin
                  if U /= 0 then
                     Gen_Swap (P, S.all, T, U, Mv, Ok);
                  end if;
               end;
            when Ruin_Recreate =>
               null;  --  Not a single move: see Ruin_And_Recreate.
            when Switch_Or =>
               --  Another alternative of an OR task, at the best of a few
               --  random places (its own place among them).
               if P.Alt_Count (T) > 1 then
                  declare
                     C : Positive := 1 + Random.Below (G, P.Alt_Count (T) - 1);
                     R : constant Positive := S.Own (T);
                     I : constant Positive := S.Pos (T);
                     Cand, Best_Mv : Move;
                     C_Ok : Boolean;
                  begin
                     if C >= S.Choice (T) then
                        C := C + 1;
                     end if;
                     Relocate (S.all, Best_Mv, R, I, I, R, I, False, C_Ok,
                               New_Loc => Location_Of (P, T, C));
                     Evaluate_Move (P, S.all, W, Best_Mv, C_Ok);
                     for Try in 1 .. Log_Tries loop
                        declare
                           R2 : constant Positive := 1 + Random.Below (G, S.NR);
                           Q  : constant Natural := Random_Robot_Position (P, S.all, G, R2);
                        begin
                           if R2 /= R or else (Q /= I and then Q + 1 /= I) then
                              Relocate (S.all, Cand, R, I, I, R2, Q, False, C_Ok,
                                        New_Loc => Location_Of (P, T, C));
                              if C_Ok then
                                 Evaluate_Move (P, S.all, W, Cand, C_Ok);
                                 if C_Ok and then Cand.Value < Best_Mv.Value then
                                    Best_Mv := Cand;
                                 end if;
                              end if;
                           end if;
                        end;
                     end loop;
                     Mv := Best_Mv;
                     Mv.Switch_Task := T;
                     Mv.Switch_To := C;
                     Ok := True;
                  end;
               end if;
         end case;
      end Propose;

      procedure Save_Best is
      begin
         Store (S.all, Best);
         Best_Saved := True;
      end Save_Best;

      function True_Value return Long_Float is
        (Value (Opts.Criterion, Current_Max (S.all), S.Sum, S.Comp, S.N_Active));

      Only_Ruin : Boolean := False;
      --  No drawn move kind is enabled: every move is a ruin and recreate.

      function Ruin_Due return Boolean is
        (Only_Ruin
         or else (Opts.Ruin_Share > 0.0 and then Opts.Enabled (Ruin_Recreate)
                  and then Long_Float (Ruin_Evals) < Opts.Ruin_Share * Long_Float (Moves)));

      --  Ruin and recreate (a large neighbourhood move): a random task and
      --  up to K of its candidate neighbours leave their tours and are put
      --  back one by one, in random order, at their best places for the
      --  search objective (any robot); the result is accepted or undone
      --  like any move.
      function Ruin_Seed return Natural is
         --  Makespan criteria: half the time a task of the longest tour.
      begin
         if W.C.Max_Weight > 0.0 and then P.Robots > 1 and then Random.Below (G, 2) = 0 then
            declare
               Worst : Positive := 1;
               N : Natural;
            begin
               for R in 2 .. S.NR loop
                  if S.RC (R) > S.RC (Worst) then
                     Worst := R;
                  end if;
               end loop;
               N := S.Len (Worst) - P.Frozen_Length (Worst);
               if N > 0 then
                  return S.Tk (Worst, P.Frozen_Length (Worst) + 1 + Random.Below (G, N));
               end if;
            end;
         end if;
         return Random_Task (P, S.all, G);
      end Ruin_Seed;

      procedure Ruin_And_Recreate is
         Seed_T : constant Natural := Ruin_Seed;
         List   : Count_Array (1 .. K + 1);
         N      : Natural := 0;
         Want   : Positive;
         Old_Len : constant Count_Array (1 .. P.Robots) := S.Len;
         Ok     : Boolean := True;
         V, D, TV : Long_Float;
         X : Kind_Stats renames Kinds (Ruin_Recreate);
      begin
         X.Tries := X.Tries + 1;
         if Seed_T = 0 then
            Ruin_Evals := Ruin_Evals + 1;
            return;
         end if;
         Want := 2 + Random.Below (G, K);
         N := 1;
         List (1) := Seed_T;
         for I in 1 .. S.Near_Count (Seed_T) loop
            exit when N >= Want;
            if Movable (P, S.all, S.Near (Seed_T, I)) then
               N := N + 1;
               List (N) := S.Near (Seed_T, I);
            end if;
         end loop;
         Shuffle (G, List, N);
         if not Best_Saved then
            Save_Best;
         end if;
         Store (S.all, Backup);
         Remove_Tasks (P, S.all, List (1 .. N));
         for I in 1 .. N loop
            Best_Insert (P, S.all, W, List (I));
         end loop;
         Ruin_Evals := Ruin_Evals + Long_Long_Integer (N * (S.N_Active + P.Robots));
         for R in 1 .. P.Robots loop
            if S.Len (R) < P.Min_Tasks and then S.Len (R) < Old_Len (R) then
               Ok := False;
            end if;
         end loop;
         V := Current_Value (P, S.all, W);
         D := V - Cur;
         if Ok and then (D <= 0.0 or else (D < 30.0 * Temp
                                           and then Random.Uniform (G) < Exp (-D / Temp)))
         then
            X.Legal := X.Legal + 1;
            X.Accepted := X.Accepted + 1;
            Accepted := Accepted + 1;
            Cur := V;
            if D < 0.0 then
               X.Improving := X.Improving + 1;
            end if;
            TV := Current_Value (P, S.all, WT);
            if TV < Best_Value - 1.0E-9 then
               Best_Value := TV;
               Best_Saved := False;
               Last_Best_Move := Moves;
               Best_Time := To_Duration (Clock - Start);
               X.New_Best := X.New_Best + 1;
               if Opts.Target > 0.0 and then True_Value <= Opts.Target then
                  Stop := True;
               end if;
            end if;
         else
            if Ok then
               X.Legal := X.Legal + 1;
            end if;
            Load (P, S.all, Backup);
         end if;
         if Opts.Check then
            Verify (P, S.all, No_Move, False);
         end if;
      end Ruin_And_Recreate;

      procedure Do_Apply (Mv : Move) is
      begin
         if Mv.Or_Node /= 0 then
            Apply_Subtree (P, S.all, D.all);
         else
            Apply (P, S.all, Mv);
         end if;
         if Opts.Check then
            Verify (P, S.all, Mv, True);
         end if;
      end Do_Apply;

      procedure Send_Report is
      begin
         if Opts.Box /= null then
            if not Best_Saved then
               Save_Best;
            end if;
            Opts.Box.Post (Best, Best_Value);
         end if;
         if Report /= null then
            Report ((Best => Best_Value, Current => Cur, Temperature => Temp, Moves => Moves,
                     Accepted => Accepted, Elapsed => Elapsed,
                     Moves_Per_Second => (if Elapsed > 0.0
                                          then Long_Float (Moves) / Long_Float (Elapsed)
                                          else 0.0),
                     Time_To_Best => Best_Time, Kinds => Kinds,
                     Polish_Gain => Polish_Gain, Switches => Switches));
         end if;
      end Send_Report;

      --  Local descent with the neighbour moves until no improvement (or time).
      procedure Polish is
         Improved : Boolean := True;
         Mv : Move;
         Ok : Boolean;
         Rounds : Natural := 0;
      begin
         while Improved and then Rounds < 50 loop
            Improved := False;
            Rounds := Rounds + 1;
            for T in 1 .. P.Tasks loop
               if Opts.Time_Limit > 0.0 and then T mod 16 = 0
                 and then To_Duration (Clock - Start) > Opts.Time_Limit * 1.02
               then
                  return;
               end if;
               if Movable (P, S.all, T) then
                  for U in 1 .. K loop
                     for V in 0 .. 13 + 2 * K loop
                        if not Movable (P, S.all, T) then
                           exit;
                        end if;
                        if V < 8 then
                           Gen_Or_Opt (P, S.all, G, T, U, 1 + V / 4 * 2, V mod 4, Mv, Ok);
                        elsif V < 12 then
                           Gen_Two_Opt (P, S.all, T, U, V mod 4, Mv, Ok);
                        elsif V < 14 then
                           Gen_Cross (P, S.all, T, U, 1, (V mod 2), Mv, Ok);
                        else
                           Gen_Or3 (P, S.all, T, U, 1 + (V - 14) / 2, V mod 2, Mv, Ok);
                        end if;
                        Mv.Switch_Task := 0;
                        if Ok then
                           Evaluate_Move (P, S.all, W, Mv, Ok);
                           if Ok and then Mv.Value < Cur - 1.0E-9 then
                              Do_Apply (Mv);
                              Cur := Current_Value (P, S.all, W);
                              Improved := True;
                           end if;
                        end if;
                     end loop;
                  end loop;
               end if;
            end loop;
         end loop;
      end Polish;

   begin
      if Opts.Time_Limit <= 0.0 and then Opts.Iterations <= 0 and then Opts.Convergence <= 0 then
         raise Constraint_Error with "annealer: no budget (time, iterations or convergence)";
      end if;
      Compute_Neighbours (P, S.all);
      for T in 1 .. P.Tasks loop
         Has_Or := Has_Or or else P.Alt_Count (T) > 1;
      end loop;
      if not Has_Or then
         Weight (Switch_Or) := 0.0;
      end if;
      for O in 1 .. Or_Count (P) loop
         Locked (O) := Is_Locked (P, O);
      end loop;
      Set_Under (P, D.all);
      if not (for some O in 1 .. Or_Count (P) => not Locked (O) and then Alternatives (P, O) > 1)
      then
         Weight (Switch_Subtree) := 0.0;
      end if;
      if P.Robots = 1 then
         Weight (Move_Owner) := 0.0;
         Weight (Guided_Move) := 0.0;
         Weight (Cross_Near) := 0.0;
      end if;
      for M in Move_Kind loop
         if not Opts.Enabled (M) then
            Weight (M) := 0.0;
         end if;
      end loop;
      if (for all M in Move_Kind => Weight (M) = 0.0) then
         if not Opts.Enabled (Ruin_Recreate) then
            raise Constraint_Error with "annealer: no move kind enabled";
         end if;
         Only_Ruin := True;
      end if;
      if Opts.Initial then
         declare
            V : constant String := Validate (P, Best);
         begin
            if V /= "" and then (V'Length < 6 or else V (V'First .. V'First + 5) /= "robot ") then
               raise Constraint_Error with "annealer: bad initial assignment: " & V;
            end if;
         end;
         Load (P, S.all, Best);
      else
         Construct (P, S.all, Opts.Criterion, G);
      end if;
      WT := Make_Weights (P, Opts.Criterion, S.Sum);
      W := WT;
      if WT.Tie > 0.0 then
         Guide0 := (if Opts.Balance >= 0.0 then Opts.Balance else 1.0 / Long_Float (P.Robots));
         W.Tie := Long_Float'Max (WT.Tie, Guide0);
      end if;
      if Opts.Check then
         Verify (P, S.all, No_Move, False);
      end if;
      Cur := Current_Value (P, S.all, W);
      Best_Value := Current_Value (P, S.all, WT);
      Save_Best;

      --  Temperatures: from the mean uphill delta of sampled moves.
      declare
         Sum_Up : Long_Float := 0.0;
         N_Up   : Natural := 0;
         Mv     : Move;
         Ok     : Boolean;
      begin
         for I in 1 .. 300 loop
            Propose (Pick_Kind, Mv, Ok);
            if Ok then
               Evaluate_Move (P, S.all, W, Mv, Ok);
               if Ok and then Mv.Value > Cur and then Mv.Value - Cur < 0.5 * Long_Float (Infinity)
               then
                  Sum_Up := Sum_Up + (Mv.Value - Cur);
                  N_Up := N_Up + 1;
               end if;
            end if;
         end loop;
         T0 := (if N_Up > 0 then Opts.Start_Factor * Sum_Up / Long_Float (N_Up) else 1.0);
         if Opts.Start_Temperature > 0.0 then
            T0 := Opts.Start_Temperature;
         end if;
         T1 := (if Opts.End_Temperature > 0.0 then Opts.End_Temperature else T0 / Opts.End_Ratio);
         T1 := Long_Float'Min (T1, T0);
         Temp := T0;
         Reheat_T := T0;
      end;
      Cycle_Best := Cur;

      Main : loop
         --  Budget and temperature every 128 moves.
         if Moves mod 128 = 0 then
            declare
               Now : constant Time := Clock;
               X   : Long_Float := 0.0;
            begin
               Elapsed := To_Duration (Now - Start);
               if Opts.Time_Limit > 0.0 then
                  X := Long_Float (Elapsed) / Long_Float (Opts.Time_Limit);
                  Stop := Stop or else Elapsed >= Opts.Time_Limit * (if Opts.Polish then 0.97
                                                                     else 1.0);
               end if;
               if Opts.Iterations > 0 then
                  X := Long_Float'Max (X, Long_Float (Moves) / Long_Float (Opts.Iterations));
                  Stop := Stop or else Moves >= Opts.Iterations;
               end if;
               if Opts.Convergence > 0 then
                  Stop := Stop or else
                    (Moves - Last_Best_Move >= Opts.Convergence
                     and then (Opts.Time_Limit > 0.0 or else Opts.Iterations > 0
                               or else Moves >= 10 * Opts.Convergence));
                  --  Alone, it applies once the schedule is half way down.
                  if Opts.Time_Limit <= 0.0 and then Opts.Iterations <= 0 then
                     --  Convergence only: cool over 20 stagnation windows.
                     X := Long_Float (Moves) / (20.0 * Long_Float (Opts.Convergence));
                  end if;
               end if;
               exit Main when Stop;
               X := Long_Float'Min (1.0, X);
               if Guide0 > WT.Tie and then Opts.Balance_Decay then
                  W.Tie := Long_Float'Max (WT.Tie, Guide0 * (WT.Tie / Guide0) ** X);
                  Cur := Current_Value (P, S.all, W);
               end if;
               case Opts.Schedule is
                  when Geometric =>
                     if not Runs_Decided and then X >= 0.02 then
                        --  Automatic: as many runs (at most Max_Runs) as the
                        --  budget gives Opts.Run_Moves x tasks ** 2 moves each.
                        Runs_Decided := True;
                        Runs := Positive (Long_Float'Max (1.0, Long_Float'Min
                          (Long_Float (Max_Runs), Long_Float'Floor
                             (Long_Float (Moves) / X
                              / (Opts.Run_Moves * Long_Float (P.Tasks) ** 2)))));
                     end if;
                     declare
                        XR : Long_Float := X * Long_Float (Runs) - Long_Float (Run);
                     begin
                        if XR >= 1.0 and then Run + 1 < Runs then
                           if not Best_Saved then
                              Save_Best;
                           end if;
                           Run := Natural'Min (Runs - 1, Natural (Long_Float'Floor
                                                                   (X * Long_Float (Runs))));
                           Construct (P, S.all, Opts.Criterion, G);
                           if Opts.Check then
                              Verify (P, S.all, No_Move, False);
                           end if;
                           Cur := Current_Value (P, S.all, W);
                           XR := X * Long_Float (Runs) - Long_Float (Run);
                        end if;
                        Temp := T0 * (T1 / T0) ** Long_Float'Min (1.0, XR);
                     end;
                  when Cyclic =>
                     --  Cycles of geometric cooling; each new cycle restarts
                     --  from the best so far, at a start temperature divided
                     --  by Cycle_Drop per cycle.
                     declare
                        C : constant Long_Float := X * Long_Float (Opts.Cycles);
                        K : constant Natural :=
                          Natural (Long_Float'Min (Long_Float (Opts.Cycles - 1),
                                                   Long_Float'Floor (C)));
                        F : constant Long_Float := Long_Float'Min (1.0, C - Long_Float (K));
                        T0K : constant Long_Float :=
                          Long_Float'Max (T1, T0 / Opts.Cycle_Drop ** K);
                     begin
                        if K /= Cycle then
                           Cycle := K;
                           if not Best_Saved then
                              Save_Best;
                           end if;
                           Load (P, S.all, Best);
                           Cur := Current_Value (P, S.all, W);
                        end if;
                        Temp := T0K * (T1 / T0K) ** F;
                     end;
                  when Reheat =>
                     if Since_Improve > 20_000 then
                        Reheat_T := Long_Float'Max (T1, Reheat_T / 1.85);
                        Since_Improve := 0;
                        Cycle_Best := Cur;
                     end if;
                     if Moves - Last_Best_Move > 1_000_000 and then Reheat_T <= T1 then
                        Reheat_T := T0;
                        Last_Best_Move := Moves;
                     end if;
                     Temp := Reheat_T;
               end case;
               if Now >= Next_Report then
                  Next_Report := Now + To_Time_Span (Opts.Report_Every);
                  Send_Report;
               end if;
               if Opts.Adaptive and then Moves mod 8192 = 0 and then Moves > 0 then
                  for M in Move_Kind loop
                     if Tries (M) > 0.0 and then Weight (M) > 0.0 then
                        Weight (M) := 0.8 * Weight (M) + 0.2 * Long_Float'Max
                          (0.05, 20.0 * Score (M) / Tries (M));
                     end if;
                     Score (M) := 0.0;
                     Tries (M) := 0.0;
                  end loop;
               end if;
            end;
         end if;
         Moves := Moves + 1;
         if Ruin_Due then
            Ruin_And_Recreate;
         else
            declare
               Kind : constant Move_Kind := Pick_Kind;
               Mv   : Move;
               Ok   : Boolean;
               D, TV : Long_Float;
            begin
               Propose (Kind, Mv, Ok);
               Tries (Kind) := Tries (Kind) + 1.0;
               Kinds (Kind).Tries := Kinds (Kind).Tries + 1;
               if Ok then
                  Evaluate_Move (P, S.all, W, Mv, Ok);
               end if;
               if Ok then
                  Kinds (Kind).Legal := Kinds (Kind).Legal + 1;
                  D := Mv.Value - Cur;
                  if D <= 0.0 or else (D < 30.0 * Temp
                                        and then Random.Uniform (G) < Exp (-D / Temp))
                  then
                     TV := Objective (WT, Mv.New_Max, Mv.New_Sum, Mv.New_Comp,
                                     Mv.New_Active);
                     if not Best_Saved and then TV > Best_Value then
                        Save_Best;
                     end if;
                     Do_Apply (Mv);
                     Accepted := Accepted + 1;
                     if Mv.Or_Node /= 0 then
                        Switches := Switches + 1;
                     end if;
                     Kinds (Kind).Accepted := Kinds (Kind).Accepted + 1;
                     Cur := Mv.Value;
                     if D < 0.0 then
                        Score (Kind) := Score (Kind) + 1.0;
                        Kinds (Kind).Improving := Kinds (Kind).Improving + 1;
                     end if;
                     if Cur < Cycle_Best then
                        Cycle_Best := Cur;
                        Since_Improve := 0;
                     else
                        Since_Improve := Since_Improve + 1;
                     end if;
                     if TV < Best_Value - 1.0E-9 then
                        Best_Value := TV;
                        Best_Saved := False;
                        Last_Best_Move := Moves;
                        Best_Time := To_Duration (Clock - Start);
                        Score (Kind) := Score (Kind) + 2.0;
                        Kinds (Kind).New_Best := Kinds (Kind).New_Best + 1;
                        if Opts.Target > 0.0 and then True_Value <= Opts.Target then
                           Stop := True;
                           exit Main;
                        end if;
                     end if;
                  else
                     Since_Improve := Since_Improve + 1;
                  end if;
               end if;
            end;
         end if;
      end loop Main;
      if not Best_Saved then
         Save_Best;
      end if;
      W := WT;
      if Opts.Polish then
         Load (P, S.all, Best);
         Cur := Current_Value (P, S.all, W);
         Polish;
         Polish_Gain := Long_Float'Max (0.0, Best_Value - Cur);
         if Cur < Best_Value then
            Best_Value := Cur;
            Best_Time := To_Duration (Clock - Start);
            Store (S.all, Best);
         end if;
      end if;
      Load (P, S.all, Best);
      Elapsed := To_Duration (Clock - Start);
      Best_Value := True_Value;
      Cur := Best_Value;
      Send_Report;
      Stats := (Best => Best_Value, Current => Cur, Temperature => Temp, Moves => Moves,
                Accepted => Accepted, Elapsed => Elapsed,
                Moves_Per_Second => (if Elapsed > 0.0
                                     then Long_Float (Moves) / Long_Float (Elapsed) else 0.0),
                Time_To_Best => Best_Time, Kinds => Kinds, Polish_Gain => Polish_Gain,
                Switches => Switches);
      Free (S);
      Free (D);
   end Solve;

end Sancta.Allocation.Annealers;
