with Ada.Unchecked_Deallocation;

package body Sancta.Allocation.Branch_And_Cut.Separation is

   Epsilon : constant := 1.0E-6;

   type Real_Vector is array (Positive range <>) of Long_Float;

   function Coefficient (C : Cut; U, V : Positive) return Integer is
      Value : Integer := (if C.Handle (U) /= C.Handle (V) then 1 else 0);
   begin
      case C.Kind is
         when Subtour =>
            null;
         when Blossom =>
            if Value = 1 then
               for T of C.Edges loop
                  if (T.U = U and then T.V = V) or else (T.U = V and then T.V = U) then
                     return -1;
                  end if;
               end loop;
            end if;
         when Comb =>
            if C.Tooth (U) /= C.Tooth (V) then
               Value := Value + (if C.Tooth (U) > 0 then 1 else 0)
                 + (if C.Tooth (V) > 0 then 1 else 0);
            end if;
      end case;
      return Value;
   end Coefficient;

   function Right_Side (C : Cut) return Long_Float is
     (case C.Kind is
         when Subtour => 2.0,
         when Blossom => 1.0 - Long_Float (C.Edges'Length),
         when Comb    => Long_Float (3 * C.Teeth + 1));

   function Left_Side (C : Cut; Edges : Support) return Long_Float is
      Sum : Long_Float := 0.0;
   begin
      for E of Edges loop
         if E.X /= 0.0 then
            Sum := Sum + Long_Float (Coefficient (C, E.U, E.V)) * E.X;
         end if;
      end loop;
      return Sum;
   end Left_Side;

   function Subtour_Cut (Inside : Node_Flags) return Cut is
     (N => Inside'Length, Tooth_Edges => 0, Kind => Subtour, Handle => Inside,
      Tooth => [others => 0], Teeth => 0, Edges => []);

   --  Union-find over 1 .. N.
   type Parents is array (Positive range <>) of Positive;

   function Root (Parent : in out Parents; V : Positive) return Positive is
      R : Positive := V;
   begin
      while Parent (R) /= R loop
         Parent (R) := Parent (Parent (R));
         R := Parent (R);
      end loop;
      return R;
   end Root;

   --  Groups of the nodes joined by the edges with Low < x < High;
   --  returns how many (numbered 1 .. in Group).
   function Components
     (N : Positive; Edges : Support; Low, High : Long_Float; Group : out Node_Labels)
      return Natural
   is
      Parent : Parents (1 .. N);
      Count  : Natural := 0;
   begin
      for V in 1 .. N loop
         Parent (V) := V;
      end loop;
      for E of Edges loop
         if E.X > Low and then E.X < High then
            declare
               A : constant Positive := Root (Parent, E.U);
               B : constant Positive := Root (Parent, E.V);
            begin
               if A /= B then
                  Parent (A) := B;
               end if;
            end;
         end if;
      end loop;
      Group := [others => 0];
      for V in 1 .. N loop
         if Root (Parent, V) = V then
            Count := Count + 1;
            Group (V) := Count;
         end if;
      end loop;
      for V in 1 .. N loop
         Group (V) := Group (Root (Parent, V));
      end loop;
      return Count;
   end Components;

   type Real_Matrix is array (Positive range <>, Positive range <>) of Long_Float;
   type Real_Matrix_Access is access Real_Matrix;
   procedure Free is new Ada.Unchecked_Deallocation (Real_Matrix, Real_Matrix_Access);

   function Subtours (N : Positive; Edges : Support) return Cut_Lists.Vector is
      Found : Cut_Lists.Vector;
      Group : Node_Labels (1 .. N);
      M     : Natural := Components (N, Edges, Epsilon, 2.0, Group);
   begin
      if M > 1 then
         for C in 1 .. M loop
            Found.Append (Subtour_Cut ([for V in 1 .. N => Group (V) = C]));
         end loop;
         return Found;
      end if;
      --  Contract the edges at 1: a violated cut that separates the ends
      --  of one stays violated with both ends on one side.
      M := Components (N, Edges, 1.0 - Epsilon, 2.0, Group);
      if M < 2 then
         return Found;   --  one cycle of edges at 1
      end if;
      --  Stoer-Wagner on the contracted support: each phase orders the
      --  active vertices by maximum adjacency; the last one's group
      --  against the rest is a cut of weight Key (Last); then Last merges
      --  into the one before it.
      declare
         W : Real_Matrix_Access := new Real_Matrix'(1 .. M => [1 .. M => 0.0]);
         Active   : array (1 .. M) of Boolean := [others => True];
         Next_Member, Last_Member : array (1 .. M) of Natural;
         Key      : array (1 .. M) of Long_Float;
         Added_To : array (1 .. M) of Boolean;
         Active_Count : Natural := M;
      begin
         for E of Edges loop
            declare
               A : constant Positive := Group (E.U);
               B : constant Positive := Group (E.V);
            begin
               if E.X > Epsilon and then A /= B then
                  W (A, B) := W (A, B) + E.X;
                  W (B, A) := W (A, B);
               end if;
            end;
         end loop;
         for V in 1 .. M loop
            Next_Member (V) := 0;
            Last_Member (V) := V;
         end loop;
         while Active_Count > 1 loop
            declare
               Previous, Last : Natural := 0;
               Last_Key : Long_Float := 0.0;
            begin
               for V in 1 .. M loop
                  Key (V) := 0.0;
                  Added_To (V) := False;
               end loop;
               for Step in 1 .. Active_Count loop
                  declare
                     Pick : Natural := 0;
                  begin
                     for V in 1 .. M loop
                        if Active (V) and then not Added_To (V)
                          and then (Pick = 0 or else Key (V) > Key (Pick))
                        then
                           Pick := V;
                        end if;
                     end loop;
                     Added_To (Pick) := True;
                     Previous := Last;
                     Last := Pick;
                     Last_Key := Key (Pick);
                     for V in 1 .. M loop
                        if Active (V) and then not Added_To (V) then
                           Key (V) := Key (V) + W (Pick, V);
                        end if;
                     end loop;
                  end;
               end loop;
               if Last_Key < 2.0 - Tolerance then
                  declare
                     Inside : array (1 .. M) of Boolean := [others => False];
                     G : Natural := Last;
                  begin
                     while G /= 0 loop
                        Inside (G) := True;
                        G := Next_Member (G);
                     end loop;
                     Found.Append (Subtour_Cut ([for V in 1 .. N => Inside (Group (V))]));
                  end;
               end if;
               --  Merge Last into Previous.
               for V in 1 .. M loop
                  W (Previous, V) := W (Previous, V) + W (Last, V);
                  W (V, Previous) := W (Previous, V);
               end loop;
               W (Previous, Previous) := 0.0;
               Next_Member (Last_Member (Previous)) := Last;
               Last_Member (Previous) := Last_Member (Last);
               Active (Last) := False;
               Active_Count := Active_Count - 1;
            end;
         end loop;
         Free (W);
      end;
      return Found;
   end Subtours;

   --  The blossom of handle H whose teeth are the edges at 1 leaving it,
   --  if they are odd (3 or more); Count = 0 when not.
   function Blossom_Of (N : Positive; Edges : Support; H : Node_Flags) return Cut is
      Teeth : End_Pairs (1 .. N);
      Count : Natural := 0;
   begin
      for E of Edges loop
         if E.X >= 1.0 - Epsilon and then H (E.U) /= H (E.V) then
            exit when Count = N;
            Count := Count + 1;
            Teeth (Count) := (E.U, E.V);
         end if;
      end loop;
      if Count < 3 or else Count mod 2 = 0 then
         Count := 0;
      end if;
      return (N => N, Tooth_Edges => Count, Kind => Blossom, Handle => H,
              Tooth => [others => 0], Teeth => 0, Edges => Teeth (1 .. Count));
   end Blossom_Of;

   function Blossoms_Heuristic (N : Positive; Edges : Support) return Cut_Lists.Vector is
      Found : Cut_Lists.Vector;
      Group : Node_Labels (1 .. N);
      Fractional : Node_Flags (1 .. N) := [others => False];
      M : constant Natural := Components (N, Edges, Epsilon, 1.0 - Epsilon, Group);
   begin
      for E of Edges loop
         if E.X > Epsilon and then E.X < 1.0 - Epsilon then
            Fractional (E.U) := True;
            Fractional (E.V) := True;
         end if;
      end loop;
      for G in 1 .. M loop
         declare
            H : Node_Flags := [for V in 1 .. N => Fractional (V) and then Group (V) = G];
            Met : Node_Labels (1 .. N);
            Grown : Boolean := True;
         begin
            if (for some V in 1 .. N => H (V)) then
               --  Outside nodes met by two teeth join the handle.
               while Grown loop
                  Grown := False;
                  Met := [others => 0];
                  for E of Edges loop
                     if E.X >= 1.0 - Epsilon and then H (E.U) /= H (E.V) then
                        declare
                           W : constant Positive := (if H (E.U) then E.V else E.U);
                        begin
                           Met (W) := Met (W) + 1;
                        end;
                     end if;
                  end loop;
                  for W in 1 .. N loop
                     if Met (W) >= 2 then
                        H (W) := True;
                        Grown := True;
                     end if;
                  end loop;
               end loop;
               declare
                  C : constant Cut := Blossom_Of (N, Edges, H);
               begin
                  if C.Tooth_Edges > 0 and then Violation (C, Edges) > Tolerance then
                     Found.Append (C);
                  end if;
               end;
            end if;
         end;
      end loop;
      return Found;
   end Blossoms_Heuristic;

   ---------------------------------------------------------------------------
   --  Maximum flow (Dinic) on an undirected graph with real capacities.

   type Arc is record
      To       : Positive;
      Residual : Long_Float;
      Next     : Natural;   --  the next arc out of the same node
   end record;
   type Arc_Array is array (Positive range <>) of Arc;
   type Index_Array is array (Positive range <>) of Natural;

   type Flow_Graph (Nodes, Max_Arcs : Positive) is record
      Arcs     : Arc_Array (1 .. Max_Arcs);
      Capacity : Real_Vector (1 .. Max_Arcs);
      Count    : Natural := 0;
      First    : Index_Array (1 .. Nodes) := [others => 0];
   end record;
   type Flow_Graph_Access is access Flow_Graph;
   procedure Free is new Ada.Unchecked_Deallocation (Flow_Graph, Flow_Graph_Access);

   procedure Connect (G : in out Flow_Graph; A, B : Positive; Capacity : Long_Float) is
   begin
      --  Arcs 2k - 1 and 2k are each other's reverse.
      G.Count := G.Count + 1;
      G.Arcs (G.Count) := (To => B, Residual => Capacity, Next => G.First (A));
      G.Capacity (G.Count) := Capacity;
      G.First (A) := G.Count;
      G.Count := G.Count + 1;
      G.Arcs (G.Count) := (To => A, Residual => Capacity, Next => G.First (B));
      G.Capacity (G.Count) := Capacity;
      G.First (B) := G.Count;
   end Connect;

   function Reverse_Of (A : Positive) return Positive is (if A mod 2 = 1 then A + 1 else A - 1);

   --  A minimum S-T cut: Source_Side (V) for the nodes reachable from S in
   --  the residual graph; returns the cut's weight.
   function Minimum_Cut (G : in out Flow_Graph; S, T : Positive; Source_Side : out Node_Flags)
     return Long_Float
   is
      Level : array (1 .. G.Nodes) of Integer;
      Current : Index_Array (1 .. G.Nodes);
      Queue : array (1 .. G.Nodes) of Positive;
      Flow : Long_Float := 0.0;

      function Build_Levels return Boolean is
         Head, Tail : Natural := 0;
      begin
         Level := [others => -1];
         Level (S) := 0;
         Tail := 1;
         Queue (1) := S;
         while Head < Tail loop
            Head := Head + 1;
            declare
               V : constant Positive := Queue (Head);
               A : Natural := G.First (V);
            begin
               while A /= 0 loop
                  if G.Arcs (A).Residual > Epsilon and then Level (G.Arcs (A).To) < 0 then
                     Level (G.Arcs (A).To) := Level (V) + 1;
                     Tail := Tail + 1;
                     Queue (Tail) := G.Arcs (A).To;
                  end if;
                  A := G.Arcs (A).Next;
               end loop;
            end;
         end loop;
         return Level (T) >= 0;
      end Build_Levels;

      function Push (V : Positive; Limit : Long_Float) return Long_Float is
      begin
         if V = T then
            return Limit;
         end if;
         while Current (V) /= 0 loop
            declare
               A : constant Positive := Current (V);
               W : constant Positive := G.Arcs (A).To;
            begin
               if G.Arcs (A).Residual > Epsilon and then Level (W) = Level (V) + 1 then
                  declare
                     Sent : constant Long_Float :=
                       Push (W, Long_Float'Min (Limit, G.Arcs (A).Residual));
                  begin
                     if Sent > 0.0 then
                        G.Arcs (A).Residual := G.Arcs (A).Residual - Sent;
                        G.Arcs (Reverse_Of (A)).Residual :=
                          G.Arcs (Reverse_Of (A)).Residual + Sent;
                        return Sent;
                     end if;
                  end;
               end if;
               Current (V) := G.Arcs (A).Next;
            end;
         end loop;
         return 0.0;
      end Push;

   begin
      for A in 1 .. G.Count loop
         G.Arcs (A).Residual := G.Capacity (A);
      end loop;
      while Build_Levels loop
         Current := G.First;
         loop
            declare
               Sent : constant Long_Float := Push (S, Long_Float'Last);
            begin
               exit when Sent <= 0.0;
               Flow := Flow + Sent;
            end;
         end loop;
      end loop;
      Source_Side := [for V in 1 .. G.Nodes => Level (V) >= 0];
      return Flow;
   end Minimum_Cut;

   function Blossoms_Exact (N : Positive; Edges : Support) return Cut_Lists.Vector is
      Found : Cut_Lists.Vector;
      Used  : Natural := 0;
   begin
      for E of Edges loop
         if E.X > Epsilon then
            Used := Used + 1;
         end if;
      end loop;
      if Used = 0 then
         return Found;
      end if;
      declare
         --  Nodes 1 .. N, then one per used edge (its x side towards U, its
         --  1 - x side towards V). A node is odd when an odd number of
         --  1 - x sides meet it: a cut then crosses an odd number of 1 - x
         --  sides (the teeth) exactly when it has an odd number of odd
         --  nodes on one side.
         Size : constant Positive := N + Used;
         G : Flow_Graph_Access := new Flow_Graph (Size, 4 * Used);
         Odd : Node_Flags (1 .. Size) := [others => False];
         Split_Edge : array (1 .. Used) of Positive;
         K : Natural := 0;
      begin
         for J in Edges'Range loop
            if Edges (J).X > Epsilon then
               K := K + 1;
               Split_Edge (K) := J;
               Connect (G.all, Edges (J).U, N + K, Long_Float'Min (1.0, Edges (J).X));
               Connect (G.all, N + K, Edges (J).V, Long_Float'Max (0.0, 1.0 - Edges (J).X));
               Odd (N + K) := True;
               Odd (Edges (J).V) := not Odd (Edges (J).V);
            end if;
         end loop;
         declare
            Parent : Node_Labels (1 .. Size) := [others => 1];
            Flow   : Real_Vector (1 .. Size) := [others => 0.0];
            Side   : Node_Flags (1 .. Size);

            --  A cut of G' (Inside: one side) that is odd and below 1 gives
            --  the blossom of handle Inside (1 .. N) whose teeth are the
            --  edges cut on their 1 - x side.
            procedure Consider (Inside : Node_Flags) is
               Weight : Long_Float := 0.0;
               Odd_Inside : Natural := 0;
            begin
               for V in 1 .. Size loop
                  if Inside (V) and then Odd (V) then
                     Odd_Inside := Odd_Inside + 1;
                  end if;
               end loop;
               if Odd_Inside mod 2 = 0 then
                  return;
               end if;
               for L in 1 .. Used loop
                  declare
                     E : constant Support_Edge := Edges (Split_Edge (L));
                  begin
                     if Inside (E.U) /= Inside (N + L) then
                        Weight := Weight + Long_Float'Min (1.0, E.X);
                     end if;
                     if Inside (N + L) /= Inside (E.V) then
                        Weight := Weight + Long_Float'Max (0.0, 1.0 - E.X);
                     end if;
                  end;
               end loop;
               if Weight >= 1.0 - Tolerance then
                  return;
               end if;
               declare
                  H : constant Node_Flags (1 .. N) := Inside (1 .. N);
                  Teeth : End_Pairs (1 .. Used);
                  Tooth_Count : Natural := 0;
               begin
                  for L in 1 .. Used loop
                     declare
                        E : constant Support_Edge := Edges (Split_Edge (L));
                     begin
                        --  A tooth: the cut goes through the 1 - x side.
                        if H (E.U) /= H (E.V) and then Inside (N + L) = H (E.U) then
                           Tooth_Count := Tooth_Count + 1;
                           Teeth (Tooth_Count) := (E.U, E.V);
                        end if;
                     end;
                  end loop;
                  declare
                     C : constant Cut :=
                       (if Tooth_Count = 1 then Subtour_Cut (H)
                        else (N => N, Tooth_Edges => Tooth_Count, Kind => Blossom,
                              Handle => H, Tooth => [others => 0], Teeth => 0,
                              Edges => Teeth (1 .. Tooth_Count)));
                  begin
                     if Tooth_Count mod 2 = 1
                       and then (for some V in 1 .. N => H (V))
                       and then (for some V in 1 .. N => not H (V))
                       and then Violation (C, Edges) > Tolerance
                       and then not (for some F of Found =>
                                       F.Kind = C.Kind and then F.Handle = C.Handle
                                       and then F.Edges = C.Edges)
                     then
                        Found.Append (C);
                     end if;
                  end;
               end;
            end Consider;
         begin
            --  Gusfield's Gomory-Hu cut tree: node S's minimum cut against
            --  its parent T; the nodes of S's side hanging on T move to S;
            --  if T's parent is on S's side, S takes T's place.
            for S in 2 .. Size loop
               declare
                  T : constant Positive := Parent (S);
                  Weight : constant Long_Float := Minimum_Cut (G.all, S, T, Side);
               begin
                  Flow (S) := Weight;
                  for V in 1 .. Size loop
                     if V /= S and then Side (V) and then Parent (V) = T then
                        Parent (V) := S;
                     end if;
                  end loop;
                  if T /= 1 and then Side (Parent (T)) then
                     Parent (S) := Parent (T);
                     Parent (T) := S;
                     Flow (S) := Flow (T);
                     Flow (T) := Weight;
                  end if;
                  if Weight < 1.0 - Tolerance then
                     Consider (Side);
                  end if;
               end;
            end loop;
            --  The tree's fundamental cuts (each node's subtree) below 1:
            --  the minimum odd cut is among them (Padberg-Rao).
            for S in 2 .. Size loop
               if Flow (S) < 1.0 - Tolerance then
                  declare
                     Below : Node_Flags (1 .. Size) := [others => False];
                  begin
                     for V in 1 .. Size loop
                        declare
                           A : Natural := V;
                           Steps : Natural := 0;
                        begin
                           --  V is below S when S is on V's path to the root.
                           while A /= 1 and then A /= S and then Steps <= Size loop
                              A := Parent (A);
                              Steps := Steps + 1;
                           end loop;
                           Below (V) := A = S;
                        end;
                     end loop;
                     Consider (Below);
                  end;
               end if;
            end loop;
         end;
         Free (G);
      end;
      return Found;
   end Blossoms_Exact;

   function Combs (N : Positive; Edges : Support) return Cut_Lists.Vector is
      Found : Cut_Lists.Vector;
      --  The fractional edges as adjacency lists.
      Degree : Node_Labels (1 .. N) := [others => 0];
      First  : Node_Labels (1 .. N + 1);
   begin
      for E of Edges loop
         if E.X > Epsilon and then E.X < 1.0 - Epsilon then
            Degree (E.U) := Degree (E.U) + 1;
            Degree (E.V) := Degree (E.V) + 1;
         end if;
      end loop;
      First (1) := 1;
      for V in 1 .. N loop
         First (V + 1) := First (V) + Degree (V);
      end loop;
      declare
         Neighbour : Node_Labels (1 .. Natural'Max (1, First (N + 1) - 1));
         Fill : Node_Labels (1 .. N) := First (1 .. N);
         --  Tarjan's blocks: depth-first order, low points, a stack of
         --  visited nodes; a block is popped when a child's low point does
         --  not reach above its parent.
         Order : Node_Labels (1 .. N) := [others => 0];
         Low   : Node_Labels (1 .. N) := [others => 0];
         Stack : Node_Labels (1 .. N);
         Top   : Natural := 0;
         Counter : Natural := 0;

         procedure Try_Handle (H : Node_Flags) is
            Tooth : Node_Labels (1 .. N) := [others => 0];
            Teeth : Natural := 0;
            Queue : Node_Labels (1 .. N);
         begin
            --  Teeth: the part of the fractional support hanging at a node
            --  of H; then edges at 1 from H to a node in no tooth.
            for A in 1 .. N loop
               if H (A) then
                  declare
                     Head, Tail : Natural := 0;
                  begin
                     for K in First (A) .. First (A + 1) - 1 loop
                        if not H (Neighbour (K)) and then Tooth (Neighbour (K)) = 0 then
                           if Tail = 0 then
                              Teeth := Teeth + 1;
                              Tooth (A) := Teeth;
                           end if;
                           Tail := Tail + 1;
                           Queue (Tail) := Neighbour (K);
                           Tooth (Neighbour (K)) := Teeth;
                        end if;
                     end loop;
                     while Head < Tail loop
                        Head := Head + 1;
                        for K in First (Queue (Head)) .. First (Queue (Head) + 1) - 1 loop
                           declare
                              W : constant Positive := Neighbour (K);
                           begin
                              if not H (W) and then Tooth (W) = 0 then
                                 Tail := Tail + 1;
                                 Queue (Tail) := W;
                                 Tooth (W) := Teeth;
                              end if;
                           end;
                        end loop;
                     end loop;
                  end;
               end if;
            end loop;
            for E of Edges loop
               if E.X >= 1.0 - Epsilon and then H (E.U) /= H (E.V) then
                  declare
                     Inner : constant Positive := (if H (E.U) then E.U else E.V);
                     Outer : constant Positive := (if H (E.U) then E.V else E.U);
                  begin
                     if Tooth (Inner) = 0 and then Tooth (Outer) = 0 then
                        Teeth := Teeth + 1;
                        Tooth (Inner) := Teeth;
                        Tooth (Outer) := Teeth;
                     end if;
                  end;
               end if;
            end loop;
            if Teeth < 3 then
               return;
            end if;
            declare
               Best : Long_Float := Tolerance;
               Best_Drop : Integer := -1;
            begin
               --  Odd: all the teeth; even: all but one (each tried).
               for Drop in (if Teeth mod 2 = 1 then 0 else 1)
                        .. (if Teeth mod 2 = 1 then 0 else Teeth)
               loop
                  declare
                     C : constant Cut :=
                       (N => N, Tooth_Edges => 0, Kind => Comb, Handle => H,
                        Tooth => [for V in 1 .. N =>
                                   (if Tooth (V) = Drop then 0
                                    elsif Drop > 0 and then Tooth (V) > Drop then Tooth (V) - 1
                                    else Tooth (V))],
                        Teeth => (if Drop = 0 then Teeth else Teeth - 1), Edges => []);
                     Amount : constant Long_Float := Violation (C, Edges);
                  begin
                     if C.Teeth >= 3 and then Amount > Best then
                        Best := Amount;
                        Best_Drop := Drop;
                     end if;
                  end;
               end loop;
               if Best_Drop >= 0 then
                  Found.Append
                    (Cut'(N => N, Tooth_Edges => 0, Kind => Comb, Handle => H,
                          Tooth => [for V in 1 .. N =>
                                     (if Tooth (V) = Best_Drop then 0
                                      elsif Best_Drop > 0 and then Tooth (V) > Best_Drop
                                      then Tooth (V) - 1
                                      else Tooth (V))],
                          Teeth => (if Best_Drop = 0 then Teeth else Teeth - 1), Edges => []));
               end if;
            end;
         end Try_Handle;

         procedure Visit (V : Positive; Parent : Natural) is
         begin
            Counter := Counter + 1;
            Order (V) := Counter;
            Low (V) := Counter;
            Top := Top + 1;
            Stack (Top) := V;
            for K in First (V) .. First (V + 1) - 1 loop
               declare
                  W : constant Positive := Neighbour (K);
               begin
                  if Order (W) = 0 then
                     Visit (W, V);
                     Low (V) := Natural'Min (Low (V), Low (W));
                     if Low (W) >= Order (V) then
                        --  V and the nodes above W on the stack: a block.
                        declare
                           H : Node_Flags (1 .. N) := [others => False];
                           Size : Natural := 1;
                        begin
                           H (V) := True;
                           loop
                              H (Stack (Top)) := True;
                              Size := Size + 1;
                              Top := Top - 1;
                              exit when Stack (Top + 1) = W;
                           end loop;
                           if Size >= 3 then
                              Try_Handle (H);
                           end if;
                        end;
                     end if;
                  elsif W /= Parent then
                     Low (V) := Natural'Min (Low (V), Order (W));
                  end if;
               end;
            end loop;
         end Visit;
      begin
         for E of Edges loop
            if E.X > Epsilon and then E.X < 1.0 - Epsilon then
               Neighbour (Fill (E.U)) := E.V;
               Fill (E.U) := Fill (E.U) + 1;
               Neighbour (Fill (E.V)) := E.U;
               Fill (E.V) := Fill (E.V) + 1;
            end if;
         end loop;
         for V in 1 .. N loop
            if Order (V) = 0 and then Degree (V) > 0 then
               Top := 0;
               Visit (V, 0);
            end if;
         end loop;
      end;
      return Found;
   end Combs;

end Sancta.Allocation.Branch_And_Cut.Separation;
