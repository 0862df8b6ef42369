with Ada.Containers.Vectors;
with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with Interfaces.C;
with Sancta.Allocation.GLPK;

package body Sancta.Allocation.Branch_And_Cut is

   use Ada.Real_Time;
   use type Interfaces.C.double;
   package LP renames Sancta.Allocation.GLPK;

   Forbidden : constant Cost := -1;
   --  An arc or edge that no cycle may use.

   Epsilon : constant := 1.0E-6;
   Cut_Tolerance : constant := 1.0E-4;
   --  A cut is violated when the LP's crossing weight is below 2 - this.

   function Symmetric_Cycle (P : Problem) return Boolean is
     (P.Symmetric and then not Has_Own_Costs (P, 1)
      and then (for all R in 1 .. P.Robots => P.Finish (R) = P.Start (R)));
   --  The cycle of robots and tasks has symmetric costs (mostly: the
   --  solver checks every pair).

   function Supports (P : Problem) return String is
   begin
      if Has_Plan (P) then
         return "plan trees (OR nodes) are not supported";
      elsif (for some T in 1 .. P.Tasks => P.Alt_Count (T) > 1) then
         return "tasks with alternative locations are not supported";
      elsif (for some R in 1 .. P.Robots => P.Frozen_Length (R) > 0) then
         return "frozen tour prefixes are not supported";
      elsif P.Min_Tasks > 1 then
         return "a minimum of more than 1 task per robot is not supported";
      elsif (P.Tasks + P.Robots) * (if Symmetric_Cycle (P) then 1 else 2) > Max_Nodes then
         return Natural'Image (P.Tasks + P.Robots) & " tasks and robots make more than"
           & Natural'Image (Max_Nodes) & " cycle nodes";
      end if;
      if P.Robots > 1 then
         for R in 1 .. P.Robots loop
            if Has_Own_Costs (P, R) then
               return "robots with cost functions of their own are not supported";
            elsif P.Multiplier (R) /= P.Multiplier (1) then
               return "robots with different cost multipliers are not supported";
            elsif P.Finish (R) /= P.Finish (1) then
               return "robots ending at different places are not supported";
            end if;
         end loop;
         if not P.All_Feasible then
            return "infeasible robot/task pairs are not supported";
         end if;
      end if;
      return "";
   end Supports;

   --  The directed cycle: tasks 1 .. n, then one depot node per robot.
   function Arc_Cost (P : Problem; U, V : Positive) return Cost is
      N : constant Natural := P.Tasks;
      M : constant Cost := Cost (P.Multiplier (1));
      F : constant Natural := P.Finish (1);
      D : Cost;
   begin
      if U = V then
         return Forbidden;
      elsif U <= N and then V <= N then
         D := Robot_Distance (P, 1, Location_Of (P, U), Location_Of (P, V));
      elsif V <= N then
         D := Robot_Distance (P, U - N, P.Start (U - N), Location_Of (P, V));
      elsif U <= N then
         D := Robot_Distance (P, 1, Location_Of (P, U), F);
      elsif P.Min_Tasks >= 1 then
         return Forbidden;   --  an idle robot
      else
         D := Robot_Distance (P, U - N, P.Start (U - N), F);
      end if;
      return (if D >= Infinity then Forbidden else M * D);
   end Arc_Cost;

   type Cost_Matrix_Access is access Cost_Matrix;
   procedure Free is new Ada.Unchecked_Deallocation (Cost_Matrix, Cost_Matrix_Access);
   type Id_Matrix is array (Positive range <>, Positive range <>) of Natural;
   type Id_Matrix_Access is access Id_Matrix;
   procedure Free is new Ada.Unchecked_Deallocation (Id_Matrix, Id_Matrix_Access);
   type Real_Matrix is array (Positive range <>, Positive range <>) of Long_Float;
   type Real_Matrix_Access is access Real_Matrix;
   procedure Free is new Ada.Unchecked_Deallocation (Real_Matrix, Real_Matrix_Access);
   type Real_Vector is array (Positive range <>) of Long_Float;
   type Node_Set is array (Positive range <>) of Boolean;
   type Node_Set_Access is access Node_Set;
   procedure Free is new Ada.Unchecked_Deallocation (Node_Set, Node_Set_Access);

   type Edge is record
      U, V   : Positive;
      Weight : Cost;
      Fixed_One : Boolean;  --  an in/out pair of the doubled graph
   end record;
   package Edge_Vectors is new Ada.Containers.Vectors (Positive, Edge);
   package Cut_Vectors is new Ada.Containers.Vectors (Positive, Node_Set_Access);
   package Real_Vectors is new Ada.Containers.Vectors (Positive, Long_Float);
   type Cycle is array (Positive range <>) of Positive;
   type Column_List is array (Positive range <>) of Positive;
   No_Teeth : constant Column_List (1 .. 0) := [others => 1];

   procedure Solve
     (P          : Problem;
      Start      : Assignment;
      Time_Limit : Duration;
      Outcome    : out Result)
   is
      Started  : constant Time := Clock;
      Deadline : constant Time := Started + To_Time_Span (Time_Limit);
      Base     : constant Positive := P.Tasks + P.Robots;
      --  Nodes of the directed cycle.
      Symmetric : Boolean := True;
      N        : Positive;
      --  Nodes of the symmetric cycle (Base, or 2 Base: in, then out nodes).
      Costs    : Cost_Matrix_Access;
      --  Edge costs of the symmetric graph (Forbidden: no edge).
      Ids      : Id_Matrix_Access;
      --  The LP column of each edge (0: not in the LP).
      Edges    : Edge_Vectors.Vector;
      Cuts     : Cut_Vectors.Vector;
      --  Cut K is row N + K: the edges leaving the set at least twice.
      Model    : LP.Problem := LP.Create_Problem;
      X        : Real_Vectors.Vector;
      --  The LP solution of the last solve.
      Upper    : Cost;
      Best_Cycle : Cycle (1 .. Base);
      Timed_Out : Boolean := False;
      Lower_At_Timeout : Long_Float := 0.0;
      Root_Done : Boolean := False;
      Nodes    : Natural := 0;
      Pending  : Real_Vectors.Vector;
      --  Bounds of the second children not yet explored (depth first).

      function Ms_Left return Natural is
        (Natural (Long_Float'Max (1.0, 1000.0 * Long_Float (To_Duration (Deadline - Clock)))));

      function Crosses (S : Node_Set; E : Edge) return Boolean is (S (E.U) /= S (E.V));

      procedure Add_Edge (U, V : Positive) is
         E : constant Edge := (U => Positive'Min (U, V), V => Positive'Max (U, V),
                               Weight => Costs (U, V),
                               Fixed_One => not Symmetric and then abs (U - V) = Base);
         Column : constant Positive := LP.Add_Columns (Model, 1);
         Count  : Natural := 2;
         Rows   : LP.Int_Array (1 .. 2 + Natural (Cuts.Length));
         Values : constant LP.Real_Array (1 .. 2 + Natural (Cuts.Length)) := [others => 1.0];
      begin
         pragma Assert (Column = Natural (Edges.Length) + 1);
         Edges.Append (E);
         X.Append (0.0);
         Ids (E.U, E.V) := Column;
         Ids (E.V, E.U) := Column;
         Rows (1) := Interfaces.C.int (E.U);
         Rows (2) := Interfaces.C.int (E.V);
         for K in 1 .. Natural (Cuts.Length) loop
            if Crosses (Cuts (K).all, E) then
               Count := Count + 1;
               Rows (Count) := Interfaces.C.int (N + K);
            end if;
         end loop;
         LP.Set_Column (Model, Column, Rows (1 .. Count), Values (1 .. Count));
         LP.Set_Objective (Model, Column, Long_Float (E.Weight));
         if E.Fixed_One then
            LP.Set_Column_Bounds (Model, Column, 1.0, 1.0);
         else
            LP.Set_Column_Bounds (Model, Column, 0.0, 1.0);
         end if;
      end Add_Edge;

      --  A subtour cut x (delta (S)) >= 2, or with Teeth (an odd number of
      --  disjoint edges of delta (S)) a blossom: x (delta (S) - Teeth) +
      --  sum over Teeth of (1 - x) >= 1, i.e. x (delta (S)) - 2 x (Teeth)
      --  >= 1 - |Teeth|. Edges added later are never teeth.
      procedure Add_Cut (S : Node_Set; Teeth : Column_List := No_Teeth) is
         Row : constant Positive := LP.Add_Rows (Model, 1);
         Count : Natural := 0;
         Columns : LP.Int_Array (1 .. Natural (Edges.Length));
         Values  : LP.Real_Array (1 .. Natural (Edges.Length));
      begin
         Cuts.Append (new Node_Set'(S));
         pragma Assert (Row = N + Natural (Cuts.Length));
         for J in 1 .. Natural (Edges.Length) loop
            if Crosses (S, Edges (J)) then
               Count := Count + 1;
               Columns (Count) := Interfaces.C.int (J);
               Values (Count) := (if (for some T of Teeth => T = J) then -1.0 else 1.0);
            end if;
         end loop;
         LP.Set_Row (Model, Row, Columns (1 .. Count), Values (1 .. Count));
         LP.Set_Row_Lower
           (Model, Row, (if Teeth'Length = 0 then 2.0 else 1.0 - Long_Float (Teeth'Length)));
      end Add_Cut;

      --  Blossoms by the odd-component heuristic: each connected component H
      --  of the fractional edges with an odd number (3 or more) of disjoint
      --  edges at 1 leaving it violates its blossom by 1.
      function Add_Blossoms return Natural is
         Parent : array (1 .. N) of Positive;
         Fractional : array (1 .. N) of Boolean := [others => False];
         Added : Natural := 0;
         function Root (V : Positive) return Positive is
            R : Positive := V;
         begin
            while Parent (R) /= R loop
               R := Parent (R);
            end loop;
            return R;
         end Root;
      begin
         for V in 1 .. N loop
            Parent (V) := V;
         end loop;
         for J in 1 .. Natural (Edges.Length) loop
            if X (J) > Epsilon and then X (J) < 1.0 - Epsilon then
               Fractional (Edges (J).U) := True;
               Fractional (Edges (J).V) := True;
               declare
                  A : constant Positive := Root (Edges (J).U);
                  B : constant Positive := Root (Edges (J).V);
               begin
                  if A /= B then
                     Parent (A) := B;
                  end if;
               end;
            end if;
         end loop;
         for R in 1 .. N loop
            if Fractional (R) and then Root (R) = R then
               declare
                  H : constant Node_Set (1 .. N) :=
                    [for V in 1 .. N => Fractional (V) and then Root (V) = R];
                  Teeth : Column_List (1 .. N);
                  Count : Natural := 0;
                  Outside : Node_Set (1 .. N) := [others => False];
                  Disjoint : Boolean := True;
               begin
                  for J in 1 .. Natural (Edges.Length) loop
                     if X (J) >= 1.0 - Epsilon and then Crosses (H, Edges (J)) then
                        declare
                           W : constant Positive :=
                             (if H (Edges (J).U) then Edges (J).V else Edges (J).U);
                        begin
                           Disjoint := Disjoint and then not Outside (W);
                           Outside (W) := True;
                           Count := Count + 1;
                           Teeth (Count) := J;
                        end;
                     end if;
                  end loop;
                  if Disjoint and then Count >= 3 and then Count mod 2 = 1 then
                     Add_Cut (H, Teeth (1 .. Count));
                     Added := Added + 1;
                  end if;
               end;
            end if;
         end loop;
         return Added;
      end Add_Blossoms;

      procedure Read_Solution is
      begin
         for J in 1 .. Natural (Edges.Length) loop
            X (J) := LP.Column_Value (Model, J);
         end loop;
      end Read_Solution;

      --  Subtour cuts violated by X: the connected components of its
      --  support if there are several; else, with the edges at 1
      --  contracted (safe: a violated cut that separates the ends of such
      --  an edge stays violated with both ends on one side), every cut of
      --  the phase of Stoer-Wagner below 2; else blossoms. Returns how many
      --  were added.
      function Separate_Cuts return Natural is
         Parent : array (1 .. N) of Positive;
         Group  : array (1 .. N) of Natural := [others => 0];
         M      : Natural := 0;
         Added  : Natural := 0;

         function Root (V : Positive) return Positive is
            R : Positive := V;
         begin
            while Parent (R) /= R loop
               Parent (R) := Parent (Parent (R));
               R := Parent (R);
            end loop;
            return R;
         end Root;

         --  Groups the nodes joined by the edges with X above Threshold;
         --  returns how many groups (numbered 1 .. in Group).
         function Join_Above (Threshold : Long_Float) return Natural is
            Count : Natural := 0;
         begin
            for V in 1 .. N loop
               Parent (V) := V;
            end loop;
            for J in 1 .. Natural (Edges.Length) loop
               if X (J) > Threshold then
                  declare
                     A : constant Positive := Root (Edges (J).U);
                     B : constant Positive := Root (Edges (J).V);
                  begin
                     if A /= B then
                        Parent (A) := B;
                     end if;
                  end;
               end if;
            end loop;
            Group := [others => 0];
            for V in 1 .. N loop
               if Root (V) = V then
                  Count := Count + 1;
                  Group (V) := Count;
               end if;
            end loop;
            for V in 1 .. N loop
               Group (V) := Group (Root (V));
            end loop;
            return Count;
         end Join_Above;
      begin
         M := Join_Above (Epsilon);
         if M > 1 then
            for C in 1 .. M loop
               Add_Cut ([for V in 1 .. N => Group (V) = C]);
            end loop;
            return M;
         end if;
         M := Join_Above (1.0 - Epsilon);
         if M < 2 then
            return 0;   --  one cycle of edges at 1
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
            for J in 1 .. Natural (Edges.Length) loop
               declare
                  A : constant Positive := Group (Edges (J).U);
                  B : constant Positive := Group (Edges (J).V);
               begin
                  if X (J) > Epsilon and then A /= B then
                     W (A, B) := W (A, B) + X (J);
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
                  if Last_Key < 2.0 - Cut_Tolerance then
                     declare
                        Inside : array (1 .. M) of Boolean := [others => False];
                        G : Natural := Last;
                     begin
                        while G /= 0 loop
                           Inside (G) := True;
                           G := Next_Member (G);
                        end loop;
                        Add_Cut ([for V in 1 .. N => Inside (Group (V))]);
                        Added := Added + 1;
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
         return (if Added > 0 then Added else Add_Blossoms);
      end Separate_Cuts;

      function Node_Duals return Real_Vector is
        ([for I in 1 .. N => LP.Row_Dual (Model, I)]);

      --  The reduced cost of edge U-V (in the LP or not) for the duals.
      function Reduced (U, V : Positive; Degree : Real_Vector; Cut_Dual : Real_Vector)
        return Long_Float
      is
         R : Long_Float := Long_Float (Costs (U, V)) - Degree (U) - Degree (V);
      begin
         for K in Cut_Dual'Range loop
            if Cut_Dual (K) /= 0.0 and then Cuts (K) (U) /= Cuts (K) (V) then
               R := R - Cut_Dual (K);
            end if;
         end loop;
         return R;
      end Reduced;

      function Cut_Duals return Real_Vector is
         Duals : Real_Vector (1 .. Natural (Cuts.Length));
      begin
         for K in Duals'Range loop
            Duals (K) := LP.Row_Dual (Model, N + K);
            if abs Duals (K) <= 1.0E-9 then
               Duals (K) := 0.0;
            end if;
         end loop;
         return Duals;
      end Cut_Duals;

      --  Edges not in the LP with a negative reduced cost (the most
      --  negative, up to 2 N) are added; returns how many.
      function Price return Natural is
         Degree : constant Real_Vector := Node_Duals;
         Cut_Dual : constant Real_Vector := Cut_Duals;
         type Candidate is record
            U, V : Positive;
            R    : Long_Float;
         end record;
         Best : array (1 .. 2 * N) of Candidate := [others => (1, 1, 0.0)];
         Count : Natural := 0;
      begin
         for U in 1 .. N loop
            for V in U + 1 .. N loop
               if Ids (U, V) = 0 and then Costs (U, V) /= Forbidden then
                  declare
                     R : constant Long_Float := Reduced (U, V, Degree, Cut_Dual);
                     I : Natural;
                  begin
                     if R < -Epsilon and then (Count < Best'Last or else R < Best (Count).R) then
                        if Count < Best'Last then
                           Count := Count + 1;
                        end if;
                        I := Count;
                        while I > 1 and then Best (I - 1).R > R loop
                           Best (I) := Best (I - 1);
                           I := I - 1;
                        end loop;
                        Best (I) := (U, V, R);
                     end if;
                  end;
               end if;
            end loop;
         end loop;
         for K in 1 .. Count loop
            Add_Edge (Best (K).U, Best (K).V);
         end loop;
         return Count;
      end Price;

      function Tour_Cost (C : Cycle) return Cost is
         Sum : Cost := 0;
      begin
         for I in C'Range loop
            Sum := Sum + Arc_Cost (P, C (I), C (if I = C'Last then C'First else I + 1));
         end loop;
         return Sum;
      end Tour_Cost;

      function Start_Cycle return Cycle is
         C : Cycle (1 .. Base);
         K : Natural := 0;
      begin
         for R in 1 .. P.Robots loop
            K := K + 1;
            C (K) := P.Tasks + R;
            for I in 1 .. Start.Length (R) loop
               K := K + 1;
               C (K) := Start.Tour (R, I);
            end loop;
         end loop;
         if K /= Base then
            raise Constraint_Error with "branch and cut: the start allocation is incomplete";
         end if;
         return C;
      end Start_Cycle;

      --  The symmetric graph's edges of a directed cycle.
      procedure Add_Cycle_Edges (C : Cycle) is
      begin
         for I in C'Range loop
            declare
               A : constant Positive := C (I);
               B : constant Positive := C (if I = C'Last then C'First else I + 1);
               U : constant Positive := (if Symmetric then A else A + Base);
            begin
               if Ids (U, B) = 0 then
                  Add_Edge (U, B);
               end if;
            end;
         end loop;
      end Add_Cycle_Edges;

      --  The directed cycle of an integral LP solution, from depot 1.
      function Solution_Cycle return Cycle is
         Next_A, Next_B : array (1 .. N) of Natural := [others => 0];
         procedure Link (From, To : Positive) is
         begin
            if Next_A (From) = 0 then
               Next_A (From) := To;
            else
               Next_B (From) := To;
            end if;
         end Link;
         C : Cycle (1 .. Base);
         Previous, Here : Positive;
         K : Natural := 0;
      begin
         for J in 1 .. Natural (Edges.Length) loop
            if X (J) > 0.5 then
               declare
                  E : constant Edge := Edges (J);
               begin
                  Link (E.U, E.V);
                  Link (E.V, E.U);
               end;
            end if;
         end loop;
         --  Doubled graph: from depot 1's in node to its out node first
         --  (forward); symmetric: either way.
         Previous := P.Tasks + 1;
         Here := (if Symmetric then Next_A (Previous) else Previous + Base);
         K := 1;
         C (1) := P.Tasks + 1;
         while Here /= P.Tasks + 1 loop
            if Symmetric or else Here <= Base then
               K := K + 1;
               C (K) := Here;
            end if;
            declare
               Next : constant Positive :=
                 (if Next_A (Here) /= Previous then Next_A (Here) else Next_B (Here));
            begin
               Previous := Here;
               Here := Next;
            end;
         end loop;
         pragma Assert (K = Base);
         return C;
      end Solution_Cycle;

      function Integral return Boolean is
        (for all J in 1 .. Natural (Edges.Length) =>
           X (J) < Epsilon or else X (J) > 1.0 - Epsilon);

      function Fathomed (Bound : Long_Float) return Boolean is
        (Bound > Long_Float (Upper) - 1.0 + Epsilon);
      --  Integer costs: no tour better than Upper below this node.

      --  Solves the node's LP with cuts until none is violated. Ok False
      --  when the node is infeasible or cannot beat Upper.
      procedure Solve_Node (Bound : out Long_Float; Ok : out Boolean; Dual : Boolean) is
         Use_Dual : Boolean := Dual;
      begin
         loop
            if Clock >= Deadline then
               Timed_Out := True;
               Ok := False;
               Bound := 0.0;
               return;
            end if;
            case LP.Simplex (Model, Use_Dual, Ms_Left) is
               when LP.Optimal =>
                  null;
               when LP.Infeasible =>
                  Ok := False;
                  Bound := Long_Float'Last;
                  return;
               when LP.Unbounded | LP.Failed =>
                  Timed_Out := True;
                  Ok := False;
                  Bound := 0.0;
                  return;
            end case;
            Bound := LP.Objective_Value (Model);
            if Root_Done and then Fathomed (Bound) then
               Ok := False;
               return;
            end if;
            Read_Solution;
            exit when Separate_Cuts = 0;
            Use_Dual := True;
         end loop;
         Ok := True;
      end Solve_Node;

      --  The most fractional edge (ties: the dearest).
      function Branch_Edge return Natural is
         Pick : Natural := 0;
         Best : Long_Float := 0.0;
      begin
         for J in 1 .. Natural (Edges.Length) loop
            declare
               F : constant Long_Float := Long_Float'Min (X (J), 1.0 - X (J));
            begin
               if F > Epsilon and then (F > Best + 1.0E-9
                                        or else (abs (F - Best) <= 1.0E-9
                                                 and then Edges (J).Weight > Edges (Pick).Weight))
               then
                  Pick := J;
                  Best := F;
               end if;
            end;
         end loop;
         return Pick;
      end Branch_Edge;

      procedure Note_Timeout (Parent_Bound : Long_Float) is
         Low : Long_Float := Parent_Bound;
      begin
         for B of Pending loop
            Low := Long_Float'Min (Low, B);
         end loop;
         Lower_At_Timeout := Low;
      end Note_Timeout;

      procedure Explore (Parent_Bound : Long_Float) is
         Bound : Long_Float;
         Ok : Boolean;
         J : Natural;
      begin
         Nodes := Nodes + 1;
         Solve_Node (Bound, Ok, Dual => True);
         if Timed_Out then
            Note_Timeout (Parent_Bound);
            return;
         elsif not Ok then
            return;
         end if;
         if Integral then
            declare
               C : constant Cycle := Solution_Cycle;
               Length : constant Cost := Tour_Cost (C);
            begin
               if Length < Upper then
                  Upper := Length;
                  Best_Cycle := C;
               end if;
            end;
            return;
         end if;
         J := Branch_Edge;
         Pending.Append (Bound);
         LP.Set_Column_Bounds (Model, J, 1.0, 1.0);
         Explore (Bound);
         LP.Set_Column_Bounds (Model, J, 0.0, 1.0);
         Pending.Delete_Last;
         if Timed_Out then
            return;
         end if;
         LP.Set_Column_Bounds (Model, J, 0.0, 0.0);
         Explore (Bound);
         LP.Set_Column_Bounds (Model, J, 0.0, 1.0);
      end Explore;

      --  After the root: with the root duals, edges that cannot be in a
      --  tour better than Upper are dropped (LP columns fixed at 0), the
      --  others all join the LP, so that no pricing is needed below.
      procedure Fix_By_Reduced_Cost (Root_Bound : Long_Float) is
         Degree : constant Real_Vector := Node_Duals;
         Cut_Dual : constant Real_Vector := Cut_Duals;
         Gap : constant Long_Float := Long_Float (Upper) - 1.0 + Epsilon - Root_Bound;
      begin
         for J in 1 .. Natural (Edges.Length) loop
            if not Edges (J).Fixed_One and then X (J) < Epsilon
              and then LP.Reduced_Cost (Model, J) > Gap
            then
               LP.Set_Column_Bounds (Model, J, 0.0, 0.0);
            end if;
         end loop;
         for U in 1 .. N loop
            for V in U + 1 .. N loop
               if Ids (U, V) = 0 and then Costs (U, V) /= Forbidden
                 and then Reduced (U, V, Degree, Cut_Dual) <= Gap
               then
                  Add_Edge (U, V);
               end if;
            end loop;
         end loop;
      end Fix_By_Reduced_Cost;

      procedure Cleanup is
      begin
         LP.Delete_Problem (Model);
         for S of Cuts loop
            declare
               Z : Node_Set_Access := S;
            begin
               Free (Z);
            end;
         end loop;
         Free (Costs);
         Free (Ids);
      end Cleanup;

   begin
      for I in 1 .. Base loop
         for J in I + 1 .. Base loop
            if Arc_Cost (P, I, J) /= Arc_Cost (P, J, I) then
               Symmetric := False;
            end if;
         end loop;
      end loop;
      N := (if Symmetric then Base else 2 * Base);
      Costs := new Cost_Matrix (1 .. N, 1 .. N);
      Ids := new Id_Matrix'(1 .. N => [1 .. N => 0]);
      for U in 1 .. N loop
         for V in 1 .. N loop
            if Symmetric then
               Costs (U, V) := Arc_Cost (P, U, V);
            elsif U <= Base and then V > Base then
               --  In node U, out node V: the arc V - Base -> U (or the pair).
               Costs (U, V) := (if V - Base = U then 0 else Arc_Cost (P, V - Base, U));
            elsif U > Base and then V <= Base then
               Costs (U, V) := (if U - Base = V then 0 else Arc_Cost (P, U - Base, V));
            else
               Costs (U, V) := Forbidden;
            end if;
         end loop;
      end loop;

      LP.Set_Minimize (Model);
      declare
         First : constant Positive := LP.Add_Rows (Model, N);
      begin
         pragma Assert (First = 1);
         for I in 1 .. N loop
            LP.Set_Row_Fixed (Model, I, 2.0);
         end loop;
      end;
      if not Symmetric then
         for U in 1 .. Base loop
            Add_Edge (U, U + Base);
         end loop;
      end if;
      Best_Cycle := Start_Cycle;
      Upper := Tour_Cost (Best_Cycle);
      Add_Cycle_Edges (Best_Cycle);
      --  Candidate edges: the 8 cheapest of each node.
      for U in 1 .. N loop
         declare
            K : constant := 8;
            Near : array (1 .. K) of Natural := [others => 0];
            Count : Natural := 0;
         begin
            for V in 1 .. N loop
               if Costs (U, V) /= Forbidden then
                  declare
                     I : Natural;
                  begin
                     if Count < K or else Costs (U, V) < Costs (U, Near (Count)) then
                        if Count < K then
                           Count := Count + 1;
                        end if;
                        I := Count;
                        while I > 1 and then Costs (U, Near (I - 1)) > Costs (U, V) loop
                           Near (I) := Near (I - 1);
                           I := I - 1;
                        end loop;
                        Near (I) := V;
                     end if;
                  end;
               end if;
            end loop;
            for I in 1 .. Count loop
               if Ids (U, Near (I)) = 0 then
                  Add_Edge (U, Near (I));
               end if;
            end loop;
         end;
      end loop;

      --  The root: cuts and pricing until neither adds anything.
      declare
         Bound : Long_Float := 0.0;
         Ok : Boolean;
         Dual : Boolean := False;
      begin
         loop
            Solve_Node (Bound, Ok, Dual);
            exit when not Ok;
            exit when Price = 0;
            Dual := False;
         end loop;
         if Ok then
            Root_Done := True;
            Nodes := 1;
            if not Fathomed (Bound) then
               Fix_By_Reduced_Cost (Bound);
               Nodes := 0;
               Explore (Bound);
            end if;
            if not Timed_Out then
               Lower_At_Timeout := Long_Float (Upper);
            end if;
         elsif not Timed_Out then
            raise Program_Error with "branch and cut: the root LP is infeasible";
         end if;
      end;

      Outcome.Upper := Upper;
      Outcome.Proven := Root_Done and then not Timed_Out;
      Outcome.Lower :=
        (if Outcome.Proven then Upper
         elsif Root_Done then
            Cost'Min (Upper, Cost (Long_Float'Ceiling (Lower_At_Timeout - Epsilon)))
         else 0);
      Outcome.Nodes := Nodes;
      Outcome.Cuts := Natural (Cuts.Length);
      Outcome.Edges := Natural (Edges.Length);
      declare
         A : Assignment (P.Robots, P.Tasks);
         R : Positive := 1;
      begin
         A.Length := [others => 0];
         for Node of Best_Cycle loop
            if Node > P.Tasks then
               R := Node - P.Tasks;
            else
               Append (A, R, Node);
            end if;
         end loop;
         Outcome.Best := A;
      end;
      Outcome.Elapsed := To_Duration (Clock - Started);
      Cleanup;
   exception
      when others =>
         Cleanup;
         raise;
   end Solve;

end Sancta.Allocation.Branch_And_Cut;
