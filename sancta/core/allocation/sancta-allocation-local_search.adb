with Ada.Containers.Generic_Constrained_Array_Sort;
with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with Sancta.Allocation.Random;

package body Sancta.Allocation.Local_Search is

   use Ada.Real_Time;

   function Applies (P : Problem) return Boolean is
     (P.Robots = 1 and then P.Tasks >= 8 and then P.Symmetric
      and then not Has_Own_Costs (P, 1) and then P.Finish (1) = P.Start (1)
      and then not Has_Plan (P) and then P.Frozen_Length (1) = 0
      and then (for all T in 1 .. P.Tasks => P.Alt_Count (T) = 1)
      and then P.All_Feasible);

   Local_Limit : constant := 1_000;
   --  Routes of at most this many nodes (tasks, depot, end) of a problem
   --  with a distance matrix are searched on a matrix of their own (32
   --  bits, 4 MB at most, freed after the route); longer ones, and those
   --  of problems with computed distances (no matrix, memory O (n)), read
   --  the problem's distances. In the anneal's route searches (10 robots,
   --  300-1000 tasks) 3-6% less CPU for the same moves.

   Bound : constant Cost := 2 ** 56;
   --  Minus the cost of the forced arc between a route's depot and its
   --  separate end node (so that no improving move ever breaks it).

   --  Iterated local search on one robot's route: from location Depot
   --  through the tasks Route (their locations in Route_Location), back to
   --  Depot or, when Has_End, to End_Location (0: anywhere). The route is
   --  held as a cycle of nodes 0 (the depot), 1 .. M (the tasks) and, with
   --  an end, M + 1 joined to the depot by an arc of cost -Bound.
   procedure Search_Route
     (P              : Problem;
      Robot          : Positive;
      Depot          : Positive;
      Has_End        : Boolean;
      End_Location   : Natural;
      Route          : in out Count_Array;
      Route_Location : Count_Array;
      Opts           : Search_Options;
      Stats          : in out Statistics;
      Distance       : access function (R : Positive; From, To : Natural) return Cost := null)
   is
      --  Opts.Target > 0: closed routes only. Distance: see Polish_Routes.
      M : constant Natural := Route'Length;
      Route_In : constant Count_Array (1 .. M) := Route;
      N : constant Positive := M + 1 + (if Has_End then 1 else 0);
      --  Nodes 0 .. N - 1, at positions 0 .. N - 1 of the cycle.
      Last : constant Natural := N - 1;
      subtype Node is Natural range 0 .. N - 1;
      type Node_Array is array (Node) of Node;
      type Flag_Array is array (Node) of Boolean;
      K : constant Positive := Positive'Min (Opts.Neighbours, N - 2);
      type Near_Matrix is array (Node, 1 .. K) of Node;
      type Near_Access is access Near_Matrix;
      Location : constant array (Node) of Natural :=
        [for V in Node =>
           (if V = 0 then Depot
            elsif V <= M then Route_Location (Route'First + V - 1)
            else End_Location)];
      Order, Position, Saved_Order, Saved_Position : Node_Array;
      Near : Near_Access := new Near_Matrix;
      procedure Free is new Ada.Unchecked_Deallocation (Near_Matrix, Near_Access);
      Queue : Node_Array;
      Queued : Flag_Array := [others => False];
      Head, Count : Natural := 0;
      Length, Saved_Length : Cost := 0;
      G : Random.Generator := Random.Seeded (Opts.Seed);
      Started  : constant Time := Budget_Clocks.Clock (Opts.Budget_Clock);
      Deadline : constant Time := Started + To_Time_Span (Opts.Time_Limit);

      function Forced (U, V : Node) return Boolean is
        (Has_End and then ((U = 0 and then V = Last) or else (V = 0 and then U = Last)))
        with Inline;
      type Local_Matrix is array (Natural range <>) of Interfaces.Integer_32;
      type Local_Access is access Local_Matrix;
      procedure Free is new Ada.Unchecked_Deallocation (Local_Matrix, Local_Access);
      Local : Local_Access;
      --  The route's distances, node by node (U * N + V), when it has at
      --  most Local_Limit nodes, P a matrix, and they fit in 32 bits
      --  (filled before the candidate lists): a dense, small matrix for
      --  the hot reads instead of scattered rows of the problem's.
      By_Location : Node_Array := [for V in Node => V];
      function Location_Before (U, V : Node) return Boolean is (Location (U) < Location (V));
      procedure Sort is new Ada.Containers.Generic_Constrained_Array_Sort
        (Node, Node, Node_Array, Location_Before);
      --  The nodes by location, the order in which Local is filled: each
      --  row of the problem's matrix read forwards, not at random.
      function D (U, V : Node) return Cost is
        (if Forced (U, V) then -Bound
         elsif Local /= null then Cost (Local (U * N + V))
         else Robot_Distance (P, Robot, Location (U), Location (V)))
        with Inline;
      function Next (V : Node) return Node is (Order ((Position (V) + 1) mod N)) with Inline;
      function Previous (V : Node) return Node is (Order ((Position (V) + N - 1) mod N))
        with Inline;

      procedure Push (V : Node) is
      begin
         if not Queued (V) then
            Queued (V) := True;
            Queue ((Head + Count) mod N) := V;
            Count := Count + 1;
         end if;
      end Push;

      --  Reverses the path at positions I .. J (forward, cyclic), or the
      --  rest of the cycle when shorter (the same cycle).
      procedure Reverse_Path (I, J : Node) is
         Inner : constant Natural := (J - I + N) mod N + 1;
         Outer : constant Boolean := 2 * Inner > N;
         L : Natural := (if Outer then (J + 1) mod N else I);
         R : Natural := (if Outer then (I + N - 1) mod N else J);
      begin
         for Step in 1 .. (if Outer then N - Inner else Inner) / 2 loop
            declare
               X : constant Node := Order (L);
            begin
               Order (L) := Order (R);
               Order (R) := X;
               Position (Order (L)) := L;
               Position (Order (R)) := R;
            end;
            L := (L + 1) mod N;
            R := (R + N - 1) mod N;
         end loop;
      end Reverse_Path;

      --  Edges {A, B} and {C, D2} become {A, C} and {B, D2} (B follows A
      --  and D2 follows C in one direction of the cycle).
      procedure Two_Opt_Move (A, B, C, D2 : Node) is
      begin
         if Next (A) = B then
            Reverse_Path (Position (B), Position (C));
         else
            Reverse_Path (Position (A), Position (D2));
         end if;
      end Two_Opt_Move;

      --  The path Prev S1 .. S2 After ... C D2 (in one direction) becomes
      --  Prev After ... C S1 .. S2 D2 (Same) or ... C S2 .. S1 D2.
      procedure Or_Move (Prev, S1, S2, After, C, D2 : Node; Same : Boolean) is
      begin
         Two_Opt_Move (Prev, S1, C, D2);         --  Prev C ... After S2 .. S1 D2
         if C /= After then
            Two_Opt_Move (Prev, C, After, S2);   --  Prev After ... C S2 .. S1 D2
         end if;
         if Same and then S1 /= S2 then
            Two_Opt_Move (C, S2, S1, D2);        --  ... C S1 .. S2 D2
         end if;
      end Or_Move;

      function Tour_Length return Cost is
         Sum : Cost := 0;
      begin
         for I in 0 .. N - 1 loop
            Sum := Sum + D (Order (I), Order ((I + 1) mod N));
         end loop;
         return Sum;
      end Tour_Length;

      Max_Depth : constant := 5;
      --  LK chains of at most this many 2-opt steps (a sequential move of
      --  depth 5: 5 arcs out, 5 in), the widest first levels.
      function Breadth (Level : Positive) return Positive is
        (case Level is when 1 => 5, when 2 => 3, when others => 1);

      procedure Verify is
      begin
         if Opts.Check and then Length /= Tour_Length then
            raise Program_Error with "local search: length" & Length'Image
              & " /= recomputed" & Tour_Length'Image;
         end if;
      end Verify;

      --  One level of a Lin-Kernighan chain: the arc (T1, T2) is out (its
      --  cost less the arcs added so far is Gain); for the best few T3 near
      --  T2 with Gain - D (T2, T3) > 0, the 2-opt move that adds (T2, T3)
      --  and (T1, T4) is applied (T4 the neighbour of T3 that keeps a
      --  cycle), and the chain goes on from (T1, T4) until the tour is
      --  shorter than Start_Length (kept) or the depth is reached (undone).
      function Chain
        (T1, T2 : Node; Gain : Cost; Level : Positive; Start_Length : Cost) return Boolean
      is
         Width : constant Positive := Breadth (Level);
         Forward : constant Boolean := Next (T1) = T2;
         Pick_3, Pick_4 : array (1 .. 5) of Node := [others => 0];
         Score : array (1 .. 5) of Cost := [others => 0];
         Found : Natural := 0;
      begin
         for I in 1 .. K loop
            declare
               T3 : constant Node := Near (T2, I);
               G1 : constant Cost := Gain - D (T2, T3);
            begin
               exit when G1 <= 0;
               if T3 /= T1 and then T3 /= Next (T2) and then T3 /= Previous (T2) then
                  declare
                     T4 : constant Node := (if Forward then Previous (T3) else Next (T3));
                     G2 : constant Cost := G1 + D (T3, T4);
                     J : Natural;
                  begin
                     if G2 > 0 and then (Found < Width or else G2 > Score (Found)) then
                        if Found < Width then
                           Found := Found + 1;
                        end if;
                        J := Found;
                        while J > 1 and then Score (J - 1) < G2 loop
                           Score (J) := Score (J - 1);
                           Pick_3 (J) := Pick_3 (J - 1);
                           Pick_4 (J) := Pick_4 (J - 1);
                           J := J - 1;
                        end loop;
                        Score (J) := G2;
                        Pick_3 (J) := T3;
                        Pick_4 (J) := T4;
                     end if;
                  end;
               end if;
            end;
         end loop;
         for C in 1 .. Found loop
            declare
               T3 : constant Node := Pick_3 (C);
               T4 : constant Node := Pick_4 (C);
               Saving : constant Cost := D (T1, T2) + D (T4, T3) - D (T2, T3) - D (T1, T4);
            begin
               Two_Opt_Move (T1, T2, T4, T3);
               Length := Length - Saving;
               Verify;
               if Length < Start_Length
                 or else (Level < Max_Depth
                          and then Chain (T1, T4, Score (C), Level + 1, Start_Length))
               then
                  Push (T2); Push (T3); Push (T4);
                  return True;
               end if;
               Two_Opt_Move (T1, T4, T2, T3);
               Length := Length + Saving;
               Verify;
            end;
         end loop;
         return False;
      end Chain;

      function Chain_From (T1 : Node) return Boolean is
      begin
         for Side in 1 .. 2 loop
            declare
               T2 : constant Node := (if Side = 1 then Next (T1) else Previous (T1));
            begin
               if Chain (T1, T2, D (T1, T2), 1, Length) then
                  Push (T1);
                  return True;
               end if;
            end;
         end loop;
         return False;
      end Chain_From;

      function Improve_From (A : Node) return Boolean is
      begin
         --  2-opt, both tour neighbours of A.
         for Side in 1 .. 2 loop
            declare
               B : constant Node := (if Side = 1 then Next (A) else Previous (A));
               AB : constant Cost := D (A, B);
            begin
               for I in 1 .. K loop
                  declare
                     C : constant Node := Near (A, I);
                     AC : constant Cost := D (A, C);
                  begin
                     exit when AC >= AB;
                     declare
                        D2 : constant Node := (if Side = 1 then Next (C) else Previous (C));
                     begin
                        if C /= B and then D2 /= A
                          and then AB + D (C, D2) - AC - D (B, D2) > 0
                        then
                           Length := Length - (AB + D (C, D2) - AC - D (B, D2));
                           Two_Opt_Move (A, B, C, D2);
                           Push (A); Push (B); Push (C); Push (D2);
                           return True;
                        end if;
                     end;
                  end;
               end loop;
            end;
         end loop;
         --  Or-opt: segments of 1 .. 3 nodes starting (Side 1) or ending
         --  (Side 2) at A, put next to a neighbour C of A.
         for Seg_Length in 1 .. 3 loop
            for Side in 1 .. 2 loop
               declare
                  function Step (V : Node) return Node is
                    (if Side = 1 then Next (V) else Previous (V));
                  function Back (V : Node) return Node is
                    (if Side = 1 then Previous (V) else Next (V));
                  S1 : constant Node := A;
                  S2 : Node := A;
                  Prev : constant Node := Back (A);
                  After : Node;
               begin
                  for I in 2 .. Seg_Length loop
                     S2 := Step (S2);
                  end loop;
                  After := Step (S2);
                  if After /= Prev and then After /= S1 and then Prev /= S2
                    and then Seg_Length + 2 < N
                  then
                     declare
                        Removed : constant Cost := D (Prev, S1) + D (S2, After) - D (Prev, After);
                        function In_Segment (V : Node) return Boolean is
                          (V = S1 or else V = S2
                           or else (Seg_Length = 3 and then V = Step (S1)));
                     begin
                        if Removed > 0 then
                           for I in 1 .. K loop
                              declare
                                 C : constant Node := Near (A, I);
                                 AC : constant Cost := D (A, C);
                              begin
                                 exit when AC >= Removed;
                                 if not In_Segment (C) then
                                    --  A next to C: C S1 .. S2 Step (C), or
                                    --  Back (C) S2 .. S1 C (in direction Step).
                                    for Variant in 1 .. 2 loop
                                       declare
                                          C1 : constant Node :=
                                            (if Variant = 1 then C else Back (C));
                                          C2 : constant Node :=
                                            (if Variant = 1 then Step (C) else C);
                                          Added : constant Cost :=
                                            (if Variant = 1
                                             then AC + D (S2, C2) - D (C1, C2)
                                             else AC + D (S2, C1) - D (C1, C2));
                                       begin
                                          if not In_Segment (C1) and then not In_Segment (C2)
                                            and then C2 /= Prev and then Added < Removed
                                          then
                                             Length := Length - (Removed - Added);
                                             --  In direction Step: Prev S1..S2 After ...
                                             --  C1 C2 (C1 C2 lie on After .. Prev).
                                             Or_Move (Prev, S1, S2, After, C1, C2,
                                                      Same => Variant = 1);
                                             Push (Prev); Push (After); Push (S1); Push (S2);
                                             Push (C1); Push (C2);
                                             return True;
                                          end if;
                                       end;
                                    end loop;
                                 end if;
                              end;
                           end loop;
                        end if;
                     end;
                  end if;
               end;
            end loop;
         end loop;
         return False;
      end Improve_From;


      --  Until no move improves, or past the deadline when there is one.
      procedure Descend is
         Pops : Natural := 0;
      begin
         while Count > 0 loop
            Pops := Pops + 1;
            exit when Opts.Time_Limit > 0.0 and then Pops mod 128 = 0
              and then Budget_Clocks.Clock (Opts.Budget_Clock) >= Deadline;
            exit when Opts.Target > 0 and then Length <= Opts.Target;
            declare
               V : constant Node := Queue (Head);
            begin
               Head := (Head + 1) mod N;
               Count := Count - 1;
               Queued (V) := False;
               while Improve_From (V) or else Chain_From (V) loop
                  Verify;
               end loop;
            end;
         end loop;
      end Descend;

      --  A double bridge inside a window of up to 50 positions from a
      --  random one: A B C -> A C B.
      procedure Kick is
         W : constant Positive := Positive'Min (50, N - 1);
         Start : constant Node := Random.Below (G, N);
         Cuts : array (1 .. 3) of Positive;
         Copy : array (0 .. W) of Node;
         K2 : Natural := 0;
      begin
         for I in Cuts'Range loop
            Cuts (I) := 1 + Random.Below (G, W - 1);
         end loop;
         for I in 2 .. 3 loop
            for J in reverse 2 .. I loop
               if Cuts (J) < Cuts (J - 1) then
                  declare
                     X : constant Positive := Cuts (J);
                  begin
                     Cuts (J) := Cuts (J - 1);
                     Cuts (J - 1) := X;
                  end;
               end if;
            end loop;
         end loop;
         if Cuts (1) = Cuts (2) or else Cuts (2) = Cuts (3) then
            return;
         end if;
         for I in 0 .. W loop
            Copy (I) := Order ((Start + I) mod N);
         end loop;
         --  Window offsets: A = 0 .. C1 - 1, B = C1 .. C2 - 1, C = C2 .. C3 - 1.
         declare
            Before : constant Cost :=
              D (Copy (Cuts (1) - 1), Copy (Cuts (1))) + D (Copy (Cuts (2) - 1), Copy (Cuts (2)))
              + D (Copy (Cuts (3) - 1), Copy (Cuts (3)));
            After : constant Cost :=
              D (Copy (Cuts (1) - 1), Copy (Cuts (2))) + D (Copy (Cuts (3) - 1), Copy (Cuts (1)))
              + D (Copy (Cuts (2) - 1), Copy (Cuts (3)));
            procedure Put (From, To : Natural) is
            begin
               for I in From .. To loop
                  Order ((Start + K2) mod N) := Copy (I);
                  Position (Copy (I)) := (Start + K2) mod N;
                  K2 := K2 + 1;
               end loop;
            end Put;
         begin
            if Before < -Bound / 2 then
               return;   --  it would break the forced arc
            end if;
            Length := Length - Before + After;
            Put (0, Cuts (1) - 1);
            Put (Cuts (2), Cuts (3) - 1);
            Put (Cuts (1), Cuts (2) - 1);
            for I in Cuts'Range loop
               Push (Copy (Cuts (I) - 1));
               Push (Copy (Cuts (I)));
            end loop;
         end;
      end Kick;

      Started_Length : Cost;
   begin
      if M < 5 then
         Free (Near);
         return;
      end if;
      if N <= Local_Limit and then Has_Matrix (P) then
         --  The distances between the route's nodes are symmetric (both
         --  callers check it: Applies, Symmetric_For): each pair is read
         --  once, U before V by location (row U of the problem's matrix
         --  read forwards), and written to both halves; through Distance
         --  when the caller has a faster copy of the same values.
         Local := new Local_Matrix (0 .. N * N - 1);
         Sort (By_Location);
         Fill :
         for I in By_Location'Range loop
            for J in I .. By_Location'Last loop
               declare
                  U : constant Node := By_Location (I);
                  V : constant Node := By_Location (J);
                  X : constant Cost :=
                    (if Distance = null
                     then Robot_Distance (P, Robot, Location (U), Location (V))
                     else Distance (Robot, Location (U), Location (V)));
               begin
                  if X not in Cost (Interfaces.Integer_32'First)
                              .. Cost (Interfaces.Integer_32'Last)
                  then
                     Free (Local);
                     exit Fill;
                  end if;
                  Local (U * N + V) := Interfaces.Integer_32 (X);
                  Local (V * N + U) := Interfaces.Integer_32 (X);
               end;
            end loop;
         end loop Fill;
      end if;
      --  Candidate lists: the K nearest nodes of each node (never the
      --  forced arc's other end); O (M^2): past the deadline, the route is
      --  left as it is.
      for U in Node loop
         if Opts.Time_Limit > 0.0 and then U mod 64 = 63
           and then Budget_Clocks.Clock (Opts.Budget_Clock) >= Deadline
         then
            Free (Near);
            Free (Local);
            return;
         end if;
         declare
            Best : array (1 .. K) of Cost := [others => Cost'Last];
            Found : Natural := 0;
         begin
            for V in Node loop
               if V /= U and then not Forced (U, V)
                 and then (Found < K or else D (U, V) < Best (Found))
               then
                  declare
                     I : Natural;
                  begin
                     if Found < K then
                        Found := Found + 1;
                     end if;
                     I := Found;
                     while I > 1 and then Best (I - 1) > D (U, V) loop
                        Best (I) := Best (I - 1);
                        Near (U, I) := Near (U, I - 1);
                        I := I - 1;
                     end loop;
                     Best (I) := D (U, V);
                     Near (U, I) := V;
                  end;
               end if;
            end loop;
            for I in Found + 1 .. K loop
               Near (U, I) := Near (U, 1);
            end loop;
         end;
      end loop;
      for I in Node loop
         Order (I) := I;
         Position (I) := I;
         Push (I);
      end loop;
      Length := Tour_Length;
      Started_Length := Length;
      Stats.Before := Stats.Before + Length + (if Has_End then Bound else 0);
      Descend;
      if Length < Started_Length then
         Stats.Time_To_Best := To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started);
      end if;
      if Opts.Time_Limit > 0.0 and then Opts.Kicks
        and then not (Opts.Target > 0 and then Length <= Opts.Target)
      then
         Saved_Order := Order;
         Saved_Position := Position;
         Saved_Length := Length;
         for Kick_Number in Long_Long_Integer range 0 .. Long_Long_Integer'Last loop
            if Kick_Number mod 16 = 0
              and then Budget_Clocks.Clock (Opts.Budget_Clock) >= Deadline
            then
               exit;
            end if;
            Stats.Kicks := Stats.Kicks + 1;
            Kick;
            Descend;
            if Length < Saved_Length then
               Stats.Improving := Stats.Improving + 1;
               Stats.Time_To_Best :=
                 To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started);
            end if;
            if Length <= Saved_Length then
               Saved_Order := Order;
               Saved_Position := Position;
               Saved_Length := Length;
               exit when Opts.Target > 0 and then Length <= Opts.Target;
            else
               Order := Saved_Order;
               Position := Saved_Position;
               Length := Saved_Length;
            end if;
         end loop;
      end if;
      pragma Assert (Length = Tour_Length, "local search: length drifted");
      --  Back to the route, from the depot on (towards the end node last).
      declare
         Z : constant Node := Position (0);
         Forward : constant Boolean := not Has_End or else Order ((Z + N - 1) mod N) = Last;
      begin
         for I in 1 .. M loop
            Route (Route'First + I - 1) :=
              Route_In (Order ((if Forward then Z + I else Z + N - I) mod N));
         end loop;
      end;
      Stats.After := Stats.After + Length + (if Has_End then Bound else 0);
      Free (Near);
      Free (Local);
   end Search_Route;

   procedure Improve
     (P : Problem; A : in out Assignment; Opts : Search_Options; Stats : out Statistics)
   is
      Started : constant Time := Budget_Clocks.Clock (Opts.Budget_Clock);
      Route : Count_Array (1 .. P.Tasks) := [for I in 1 .. P.Tasks => A.Tour (1, I)];
   begin
      Stats := (others => <>);
      Search_Route (P, 1, P.Start (1), False, 0, Route,
                    [for I in 1 .. P.Tasks => Location_Of (P, Route (I))], Opts, Stats);
      for I in Route'Range loop
         A.Tour (1, I) := Route (I);
      end loop;
      Stats.Elapsed := To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started);
   end Improve;

   function Nearest_Neighbour_Tour (P : Problem) return Assignment is
      Visited : Boolean_Array (1 .. P.Tasks) := [others => False];
      Here : Positive := P.Start (1);
   begin
      return A : Assignment (1, P.Tasks) do
         for Step in 1 .. P.Tasks loop
            declare
               Best : Natural := 0;
               Best_Cost : Cost := Cost'Last;
            begin
               for T in 1 .. P.Tasks loop
                  if not Visited (T)
                    and then Distance (P, Here, Location_Of (P, T)) < Best_Cost
                  then
                     Best := T;
                     Best_Cost := Distance (P, Here, Location_Of (P, T));
                  end if;
               end loop;
               Visited (Best) := True;
               Append (A, 1, Best);
               Here := Location_Of (P, Best);
            end;
         end loop;
      end return;
   end Nearest_Neighbour_Tour;

   function Symmetric_For (P : Problem; R : Positive; A : Assignment) return Boolean is
   begin
      if not Has_Own_Costs (P, R) then
         return P.Symmetric;
      end if;
      declare
         Here : constant Count_Array (1 .. A.Length (R) + 1) :=
           [for I in 1 .. A.Length (R) + 1 =>
              (if I = 1 then P.Start (R)
               else Location_Of (P, A.Tour (R, I - 1), A.Choice (A.Tour (R, I - 1))))];
      begin
         return (for all I in Here'Range =>
                   (for all J in I + 1 .. Here'Last =>
                      Robot_Distance (P, R, Here (I), Here (J))
                      = Robot_Distance (P, R, Here (J), Here (I))))
           and then (P.Finish (R) = Nowhere or else
                     (for all I in Here'Range =>
                        Robot_Distance (P, R, Here (I), P.Finish (R))
                        = Robot_Distance (P, R, P.Finish (R), Here (I))));
      end;
   end Symmetric_For;

   procedure Polish_Routes
     (P : Problem; A : in out Assignment; Opts : Search_Options; Stats : out Statistics;
      Distance : access function (R : Positive; From, To : Natural) return Cost := null)
   is
      use type Interfaces.Unsigned_64;
      Started : constant Time := Budget_Clocks.Clock (Opts.Budget_Clock);
      Free_Tasks : Natural := 0;
   begin
      Stats := (others => <>);
      for R in 1 .. A.Robots loop
         Free_Tasks := Free_Tasks
           + (A.Length (R) - Natural'Min (A.Length (R), P.Frozen_Length (R)));
      end loop;
      for R in 1 .. A.Robots loop
         declare
            F : constant Natural := Natural'Min (A.Length (R), P.Frozen_Length (R));
            Free : constant Natural := A.Length (R) - F;
         begin
            if Free >= 5 and then Symmetric_For (P, R, A) then
               declare
                  Route : Count_Array (1 .. Free) := [for I in 1 .. Free => A.Tour (R, F + I)];
                  Depot : constant Positive :=
                    (if F = 0 then P.Start (R)
                     else Location_Of (P, A.Tour (R, F), A.Choice (A.Tour (R, F))));
                  Closed_At_Depot : constant Boolean := P.Finish (R) = Depot;
                  Share : constant Duration :=
                    (if Opts.Time_Limit = 0.0 then 0.0
                     else Opts.Time_Limit * Free / Free_Tasks);
               begin
                  Search_Route
                    (P, R, Depot, not Closed_At_Depot, P.Finish (R), Route,
                     [for I in 1 .. Free => Location_Of (P, Route (I), A.Choice (Route (I)))],
                     (Opts with delta Time_Limit => Share,
                                      Seed => Opts.Seed + Interfaces.Unsigned_64 (R)),
                     Stats, Distance);
                  for I in 1 .. Free loop
                     A.Tour (R, F + I) := Route (I);
                  end loop;
               end;
            end if;
         end;
      end loop;
      Stats.Elapsed := To_Duration (Budget_Clocks.Clock (Opts.Budget_Clock) - Started);
   end Polish_Routes;

end Sancta.Allocation.Local_Search;
