with Ada.Real_Time;
with Sancta.Allocation.Random;

package body Sancta.Allocation.Local_Search is

   use Ada.Real_Time;

   function Applies (P : Problem) return Boolean is
     (P.Robots = 1 and then P.Tasks >= 8 and then P.Symmetric
      and then not Has_Own_Costs (P, 1) and then P.Finish (1) = P.Start (1)
      and then not Has_Plan (P) and then P.Frozen_Length (1) = 0
      and then (for all T in 1 .. P.Tasks => P.Alt_Count (T) = 1)
      and then P.All_Feasible);

   procedure Improve
     (P          : Problem;
      A          : in out Assignment;
      Time_Limit : Duration;
      Seed       : Interfaces.Unsigned_64;
      Stats      : out Statistics;
      Neighbours : Positive := 8;
      Check      : Boolean := False)
   is
      N : constant Positive := P.Tasks + 1;
      --  Nodes 0 (the depot) .. Tasks, at positions 0 .. N - 1 of the cycle.
      subtype Node is Natural range 0 .. N - 1;
      type Node_Array is array (Node) of Node;
      type Flag_Array is array (Node) of Boolean;
      K : constant Positive := Positive'Min (Neighbours, N - 2);
      type Near_Matrix is array (Node, 1 .. K) of Node;
      type Near_Access is access Near_Matrix;
      Location : constant array (Node) of Positive :=
        [for V in Node => (if V = 0 then P.Start (1) else Location_Of (P, V))];
      Order, Position, Saved_Order, Saved_Position : Node_Array;
      Near : constant Near_Access := new Near_Matrix;
      Queue : Node_Array;
      Queued : Flag_Array := [others => False];
      Head, Count : Natural := 0;
      Length, Saved_Length : Cost := 0;
      G : Random.Generator := Random.Seeded (Seed);
      Started  : constant Time := Clock;
      Deadline : constant Time := Started + To_Time_Span (Time_Limit);

      function D (U, V : Node) return Cost is (P.Distance (Location (U), Location (V)))
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

      function Tour_Length return Cost is
         Sum : Cost := 0;
      begin
         for I in 0 .. N - 1 loop
            Sum := Sum + D (Order (I), Order ((I + 1) mod N));
         end loop;
         return Sum;
      end Tour_Length;

      procedure Descend is
      begin
         while Count > 0 loop
            declare
               V : constant Node := Queue (Head);
            begin
               Head := (Head + 1) mod N;
               Count := Count - 1;
               Queued (V) := False;
               while Improve_From (V) loop
                  if Check and then Length /= Tour_Length then
                     raise Program_Error with "local search: length" & Length'Image
                       & " /= recomputed" & Tour_Length'Image;
                  end if;
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


   begin
      Stats := (others => <>);
      --  Candidate lists: the K nearest nodes of each node.
      for U in Node loop
         declare
            Best : array (1 .. K) of Cost := [others => Cost'Last];
            Found : Natural := 0;
         begin
            for V in Node loop
               if V /= U and then (Found < K or else D (U, V) < Best (Found)) then
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
         end;
      end loop;
      Order (0) := 0;
      for I in 1 .. A.Length (1) loop
         Order (I) := A.Tour (1, I);
      end loop;
      for I in Node loop
         Position (Order (I)) := I;
         Push (Order (I));
      end loop;
      Length := Tour_Length;
      Stats.Before := Length;
      Descend;
      Stats.Time_To_Best := To_Duration (Clock - Started);
      if Time_Limit > 0.0 then
         Saved_Order := Order;
         Saved_Position := Position;
         Saved_Length := Length;
         loop
            if Stats.Kicks mod 16 = 0 and then Clock >= Deadline then
               exit;
            end if;
            Stats.Kicks := Stats.Kicks + 1;
            Kick;
            Descend;
            if Length < Saved_Length then
               Stats.Improving := Stats.Improving + 1;
               Stats.Time_To_Best := To_Duration (Clock - Started);
            end if;
            if Length <= Saved_Length then
               Saved_Order := Order;
               Saved_Position := Position;
               Saved_Length := Length;
            else
               Order := Saved_Order;
               Position := Saved_Position;
               Length := Saved_Length;
            end if;
         end loop;
      end if;
      pragma Assert (Length = Tour_Length, "local search: length drifted");
      --  Back to the assignment, from the depot on.
      declare
         Z : constant Node := Position (0);
      begin
         for I in 1 .. N - 1 loop
            A.Tour (1, I) := Order ((Z + I) mod N);
         end loop;
      end;
      Stats.After := Length;
      Stats.Elapsed := To_Duration (Clock - Started);
   end Improve;

end Sancta.Allocation.Local_Search;
