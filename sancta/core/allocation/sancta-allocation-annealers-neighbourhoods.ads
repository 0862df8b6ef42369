--  The annealer's neighbourhoods: each procedure builds one move (as
--  segment lists, see Moves) from a task and a few drawn numbers, and sets
--  Ok False when the draw does not give a legal move (frozen prefixes,
--  overlapping segments, tasks not in a tour). The neighbour moves start
--  from a task T and one of its candidate neighbours U in a tour
--  (Placed_Neighbour).
--
--     U : constant Natural := Placed_Neighbour (S, T, U_Index => 2);
--     if U /= 0 then
--        Or_Opt (P, S, T, U, Length => 3, Variant => 1, Mv, Ok);
--        --  T and the 2 tasks after it moved next to U, reversed
--     end if;
with Sancta.Allocation.Random;
with Sancta.Allocation.Annealers.Moves; use Sancta.Allocation.Annealers.Moves;
with Sancta.Allocation.Annealers.Tours; use Sancta.Allocation.Annealers.Tours;

private package Sancta.Allocation.Annealers.Neighbourhoods is

   function Random_Task (P : Problem; S : State; G : in out Generator) return Natural;
   --  A movable task drawn uniformly (a few tries), or 0.

   function Random_Robot_Position
     (P : Problem; S : State; G : in out Generator; R : Positive) return Natural
   is (P.Frozen_Length (R) + Random.Below (G, S.Length (R) - P.Frozen_Length (R) + 1));
   --  A place after the frozen prefix of robot R: insert after this position.

   procedure Relocate (S : State; Mv : in out Move; R1 : Positive; I, J : Positive;
                       R2 : Positive; Q : Natural; Rev : Boolean; Ok : out Boolean;
                       New_Location : Natural := 0);
   --  Moves the tasks at positions I .. J of robot R1 to after position Q of
   --  robot R2 (Q in the current numbering of R2), reversed if Rev. With
   --  New_Location /= 0 (I = J), the task moves to that OR alternative.

   function Placed_Neighbour (S : State; T, U_Index : Positive) return Natural is
     (if S.Near (T, U_Index) /= 0 and then S.Owner (S.Near (T, U_Index)) /= 0
      then S.Near (T, U_Index) else 0);
   --  T's U_Index-th candidate neighbour if it is in a tour, else 0.

   procedure Or_Opt
     (P : Problem; S : State; T, U : Positive; Length : Positive;
      Variant : Natural; Mv : in out Move; Ok : out Boolean)
     with Pre => S.Owner (U) /= 0;
   --  Relocate / Or-opt: T and the Length - 1 tasks after it next to U.
   --  Variant mod 4: 0 after U, forward (U -> T); 1 before U, reversed
   --  (T -> U); 2 after U, reversed; 3 before U, forward.

   procedure Two_Opt
     (P : Problem; S : State; T, U : Positive; Variant : Natural;
      Mv : in out Move; Ok : out Boolean)
     with Pre => S.Owner (U) /= 0;
   --  A new arc between T and U: within one tour the segment
   --  between them reversed; across two tours 2-opt* (tails exchanged,
   --  Variant mod 4 in 0 .. 1) or crossed with reversal (2 .. 3: 2-opt
   --  across two tours through a common depot).

   procedure Or_3opt
     (P : Problem; S : State; T, U : Positive; V_Index : Positive; Variant : Natural;
      Mv : in out Move; Ok : out Boolean)
     with Pre => S.Owner (U) /= 0;
   --  Segment exchange within a tour, any segment lengths, both new arcs
   --  next to candidate neighbours: with T at position A and U at B + 1 (U
   --  near T), the tour 1..A, A+1..B, B+1..C, C+1.. becomes 1..A, B+1..C,
   --  A+1..B, C+1.. where C is the position of V, a neighbour of the task at
   --  A + 1 (Variant 0: arcs T-U, V-(A+1), B-(C+1)), or of the task at B
   --  with A+1..B reversed (Variant 1: arcs T-U, V-B, (A+1)-(C+1)).

   procedure Cross_Exchange
     (P : Problem; S : State; T, U : Positive; L1, L2 : Natural;
      Mv : in out Move; Ok : out Boolean)
     with Pre => S.Owner (U) /= 0;
   --  T's tour gives L1 tasks from T on and receives the L2 tasks after U
   --  (nothing when U is in T's tour).

   procedure Swap (S : State; T, U : Positive; Mv : in out Move; Ok : out Boolean);
   --  T and U exchange their places.

   procedure Random_Insert (P : Problem; S : State; G : in out Generator; T : Positive;
                            Other : Boolean; Mv : in out Move; Ok : out Boolean);
   --  T re-inserted at a random place of a random robot (another than its
   --  own when Other).

end Sancta.Allocation.Annealers.Neighbourhoods;
