--  Cut separation for the branch and cut (not for users: a private child;
--  the tests see it): given the LP point x on the support graph of the
--  symmetric cycle (nodes 1 .. N, each with degree 2 in every tour), the
--  classes of valid TSP inequalities that x violates.
--
--     Edges : constant Support := [(1, 2, 0.5), (2, 3, 0.5), ...];
--     Found : constant Cut_Lists.Vector := Blossoms_Exact (N, Edges);
--     --  each C in Found: Left_Side (C, Edges) < Right_Side (C) - Tolerance
--
--  A cut is stated over node sets so that edges that join the LP later
--  get their coefficient from the same rule:
--  * Subtour (handle S): x (delta (S)) >= 2.
--  * Blossom (handle H, an odd set T of edges of delta (H)):
--    x (delta (H)) - 2 x (T) >= 1 - |T|, the 2-matching inequality
--    (valid whether or not the teeth share ends).
--  * Comb (handle H, k >= 3 odd pairwise disjoint teeth T_j, each meeting
--    H and leaving it): x (delta (H)) + sum x (delta (T_j)) >= 3 k + 1.
with Ada.Containers.Indefinite_Vectors;

private package Sancta.Allocation.Branch_And_Cut.Separation is

   Tolerance : constant := 1.0E-4;
   --  A cut is violated when its left side is below the right by more.

   type Support_Edge is record
      U, V : Positive;
      X    : Long_Float;
   end record;
   type Support is array (Positive range <>) of Support_Edge;
   --  The edges with x > 0 (others may be listed with x = 0).

   subtype Cut_Kind is Cut_Class;
   type Node_Flags is array (Positive range <>) of Boolean;
   type Node_Labels is array (Positive range <>) of Natural;
   type End_Pair is record
      U, V : Positive;
   end record;
   type End_Pairs is array (Positive range <>) of End_Pair;

   type Cut (N : Positive; Tooth_Edges : Natural) is record
      Kind   : Cut_Kind;
      Handle : Node_Flags (1 .. N);
      Tooth  : Node_Labels (1 .. N) := [others => 0];
      --  Comb: the tooth (1 .. Teeth) of each node, 0 = none.
      Teeth  : Natural := 0;
      Edges  : End_Pairs (1 .. Tooth_Edges);
      --  Blossom: the teeth (edges of delta (Handle)).
   end record;

   function Coefficient (C : Cut; U, V : Positive) return Integer;
   --  The coefficient of edge U-V in C's left side.

   function Right_Side (C : Cut) return Long_Float;

   function Left_Side (C : Cut; Edges : Support) return Long_Float;

   function Violation (C : Cut; Edges : Support) return Long_Float is
     (Right_Side (C) - Left_Side (C, Edges));
   --  > Tolerance: x violates C.

   function Subtour_Cut (Inside : Node_Flags) return Cut;

   package Cut_Lists is new Ada.Containers.Indefinite_Vectors (Positive, Cut);

   function Subtours (N : Positive; Edges : Support) return Cut_Lists.Vector;
   --  The connected components of the support if there are several; else,
   --  with the edges at 1 contracted, every cut below 2 met by the phases
   --  of Stoer-Wagner's minimum cut (exact: the minimum cut is among them).

   function Blossoms_Heuristic (N : Positive; Edges : Support) return Cut_Lists.Vector;
   --  Odd components (Groetschel-Holland): each connected component of the
   --  fractional edges is a handle, the edges at 1 leaving it the teeth;
   --  an outside node met by two teeth joins the handle (repeated); kept
   --  when the teeth are odd (3 or more) and the blossom is violated.

   function Blossoms_Exact (N : Positive; Edges : Support) return Cut_Lists.Vector;
   --  Padberg-Rao: every edge split by a node into an x side and a 1 - x
   --  side; the minimum cuts between odd-labelled nodes (a Gomory-Hu tree
   --  on them by Gusfield's method) that are odd and below 1 are the
   --  violated blossoms (a most violated one is among them). A one-tooth
   --  blossom is returned as the subtour cut it implies.

   function Combs (N : Positive; Edges : Support) return Cut_Lists.Vector;
   --  Combs from the blocks of the fractional support: with the paths of
   --  edges at 1 seen as teeth candidates, each 2-connected block of the
   --  fractional edges is a handle; its teeth are the edges at 1 leaving
   --  it and, where such an edge's outer end sits on a path of edges at 1,
   --  that path (kept disjoint); kept when odd (3 or more) and violated.

end Sancta.Allocation.Branch_And_Cut.Separation;
