with Ada.Containers.Vectors;
with Ada.Execution_Time;
with Ada.Real_Time;
with Ada.Unchecked_Deallocation;
with Interfaces.C;
with Sancta.Allocation.Branch_And_Cut.Separation;
with Sancta.Allocation.GLPK;

package body Sancta.Allocation.Branch_And_Cut is

   use Ada.Real_Time;
   package LP renames Sancta.Allocation.GLPK;

   Forbidden : constant Cost := -1;
   --  An arc or edge that no cycle may use.

   Epsilon : constant := 1.0E-6;

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
   type Real_Vector is array (Positive range <>) of Long_Float;

   type Edge is record
      U, V   : Positive;
      Weight : Cost;
      Fixed_One : Boolean;  --  an in/out pair of the doubled graph
   end record;
   package Edge_Vectors is new Ada.Containers.Vectors (Positive, Edge);
   package Real_Vectors is new Ada.Containers.Vectors (Positive, Long_Float);
   package Natural_Vectors is new Ada.Containers.Vectors (Positive, Natural);

   type Fix is record
      Column : Positive;
      Value  : Natural range 0 .. 1;
   end record;
   package Fix_Vectors is new Ada.Containers.Vectors (Positive, Fix);

   type Open_Node is record
      Bound : Long_Float;
      --  The parent's LP value (a lower bound below this node).
      Fixes : Fix_Vectors.Vector;
      --  Columns fixed on the path from the root (branching, reduced costs).
   end record;
   package Node_Vectors is new Ada.Containers.Vectors (Positive, Open_Node);

   type Cycle is array (Positive range <>) of Positive;

   Purge_Age : constant := 3;
   --  Rounds a cut stays slack before it leaves the LP.
   Pool_Limit : constant := 20_000;
   Strong_Iterations : constant := 50;
   --  Dual simplex steps per strong-branching child.
   Tailing_Rounds : constant := 4;
   Tailing_Share : constant := 0.02;
   --  A node stops cutting (and branches) when its last Tailing_Rounds
   --  rounds closed less than this share of the gap to the upper bound.

   procedure Solve
     (P       : Problem;
      Start   : Assignment;
      Outcome : out Result;
      Config  : Settings := Default_Settings)
   is
      use Separation;
      Started  : constant Time := Clock;
      CPU_Started : constant Ada.Execution_Time.CPU_Time := Ada.Execution_Time.Clock;
      Deadline : constant Time := Started + To_Time_Span (Config.Time_Limit);
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
      Cuts     : Cut_Lists.Vector;
      --  Cut K is row N + K.
      Ages     : Natural_Vectors.Vector;
      --  Rounds each cut has been slack.
      Pool     : Cut_Lists.Vector;
      Model    : LP.Problem := LP.Create_Problem;
      X        : Real_Vectors.Vector;
      --  The LP solution of the last solve.
      Root_Low, Root_High : Natural_Vectors.Vector;
      --  Each column's bounds at the root (after the global fixing).
      Touched  : Natural_Vectors.Vector;
      --  Columns whose bounds differ from the root's in the LP now.
      Fixed_Now : Natural_Vectors.Vector;
      --  1: the column is fixed in the LP now (at the root or the node).
      Upper    : Cost;
      Best_Cycle : Cycle (1 .. Base);
      Timed_Out : Boolean := False;
      Root_Done : Boolean := False;
      Open     : Node_Vectors.Vector;
      Stats    : Result (P.Robots, P.Tasks);
      --  The counters (Nodes, By_Class, ...).

      function Time_Up return Boolean is
        (if Config.CPU_Time_Limit
         then Ada.Execution_Time."-" (Ada.Execution_Time.Clock, CPU_Started)
              >= To_Time_Span (Config.Time_Limit)
         else Clock >= Deadline);

      function Ms_Left return Natural is
        (if Config.CPU_Time_Limit then 0
         else Natural (Long_Float'Max (1.0, 1000.0 * Long_Float (To_Duration (Deadline - Clock)))));

      function Column_Count return Natural is (Natural (Edges.Length));

      procedure Set_Bounds (Column : Positive; Low, High : Natural) is
      begin
         LP.Set_Column_Bounds (Model, Column, Long_Float (Low), Long_Float (High));
      end Set_Bounds;

      procedure Add_Edge (U, V : Positive) is
         E : constant Edge := (U => Positive'Min (U, V), V => Positive'Max (U, V),
                               Weight => Costs (U, V),
                               Fixed_One => not Symmetric and then abs (U - V) = Base);
         Column : constant Positive := LP.Add_Columns (Model, 1);
         Count  : Natural := 2;
         Rows   : LP.Int_Array (1 .. 2 + Natural (Cuts.Length));
         Values : LP.Real_Array (1 .. 2 + Natural (Cuts.Length)) := [others => 1.0];
      begin
         pragma Assert (Column = Column_Count + 1);
         Edges.Append (E);
         X.Append (0.0);
         Ids (E.U, E.V) := Column;
         Ids (E.V, E.U) := Column;
         Rows (1) := Interfaces.C.int (E.U);
         Rows (2) := Interfaces.C.int (E.V);
         for K in 1 .. Natural (Cuts.Length) loop
            declare
               A : constant Integer := Coefficient (Cuts (K), E.U, E.V);
            begin
               if A /= 0 then
                  Count := Count + 1;
                  Rows (Count) := Interfaces.C.int (N + K);
                  Values (Count) := Interfaces.C.double (A);
               end if;
            end;
         end loop;
         LP.Set_Column (Model, Column, Rows (1 .. Count), Values (1 .. Count));
         LP.Set_Objective (Model, Column, Long_Float (E.Weight));
         Root_Low.Append (if E.Fixed_One then 1 else 0);
         Root_High.Append (1);
         Fixed_Now.Append (Root_Low (Column));
         Set_Bounds (Column, Root_Low (Column), 1);
      end Add_Edge;

      procedure Add_Cut (C : Cut) is
         Row : constant Positive := LP.Add_Rows (Model, 1);
         Count : Natural := 0;
         Columns : LP.Int_Array (1 .. Column_Count);
         Values  : LP.Real_Array (1 .. Column_Count);
      begin
         Cuts.Append (C);
         Ages.Append (0);
         pragma Assert (Row = N + Natural (Cuts.Length));
         for J in 1 .. Column_Count loop
            declare
               A : constant Integer := Coefficient (C, Edges (J).U, Edges (J).V);
            begin
               if A /= 0 then
                  Count := Count + 1;
                  Columns (Count) := Interfaces.C.int (J);
                  Values (Count) := Interfaces.C.double (A);
               end if;
            end;
         end loop;
         LP.Set_Row (Model, Row, Columns (1 .. Count), Values (1 .. Count));
         LP.Set_Row_Lower (Model, Row, Right_Side (C));
         Stats.Cuts := Stats.Cuts + 1;
      end Add_Cut;

      procedure Read_Solution is
      begin
         for J in 1 .. Column_Count loop
            X (J) := LP.Column_Value (Model, J);
         end loop;
      end Read_Solution;

      function Current_Support return Support is
         Count : Natural := 0;
      begin
         for J in 1 .. Column_Count loop
            if X (J) > Epsilon then
               Count := Count + 1;
            end if;
         end loop;
         return S : Support (1 .. Count) do
            Count := 0;
            for J in 1 .. Column_Count loop
               if X (J) > Epsilon then
                  Count := Count + 1;
                  S (Count) := (Edges (J).U, Edges (J).V, X (J));
               end if;
            end loop;
         end return;
      end Current_Support;

      --  Cuts slack for Purge_Age rounds leave the LP (basic rows: the
      --  basis stays valid) for the pool.
      procedure Purge_Slack_Cuts is
         Leaving : LP.Int_Array (1 .. Natural (Cuts.Length));
         Count : Natural := 0;
      begin
         for K in 1 .. Natural (Cuts.Length) loop
            if LP.Row_Is_Basic (Model, N + K) then
               Ages (K) := Ages (K) + 1;
               if Ages (K) >= Purge_Age then
                  Count := Count + 1;
                  Leaving (Count) := Interfaces.C.int (N + K);
               end if;
            else
               Ages (K) := 0;
            end if;
         end loop;
         if Count = 0 then
            return;
         end if;
         LP.Delete_Rows (Model, Leaving (1 .. Count));
         for I in reverse 1 .. Count loop
            declare
               K : constant Positive := Natural (Leaving (I)) - N;
            begin
               if Natural (Pool.Length) >= Pool_Limit then
                  Pool.Delete_First;
               end if;
               Pool.Append (Cuts (K));
               Cuts.Delete (K);
               Ages.Delete (K);
            end;
         end loop;
         Stats.Purged := Stats.Purged + Count;
      end Purge_Slack_Cuts;

      function Same (A, B : Cut) return Boolean is
        (A.Kind = B.Kind and then A.Tooth_Edges = B.Tooth_Edges and then A.Teeth = B.Teeth
         and then (A.Handle = B.Handle
                   or else (for all V in A.Handle'Range => A.Handle (V) /= B.Handle (V)))
         and then A.Tooth = B.Tooth and then A.Edges = B.Edges);

      --  Cuts violated by X, from the pool first, then by each separator
      --  in turn until one finds some; returns how many were added.
      function Separate_Cuts return Natural is
         S : constant Support := Current_Support;
         Batch : Cut_Lists.Vector;
         procedure Take (Found : Cut_Lists.Vector) is
         begin
            for C of Found loop
               if not (for some B of Batch => Same (B, C)) then
                  Batch.Append (C);
                  Stats.By_Class (C.Kind) := Stats.By_Class (C.Kind) + 1;
               end if;
            end loop;
         end Take;
      begin
         declare
            K : Natural := 1;
         begin
            while K <= Natural (Pool.Length) loop
               if Violation (Pool (K), S) > Tolerance then
                  Batch.Append (Pool (K));
                  Pool.Delete (K);
               else
                  K := K + 1;
               end if;
            end loop;
         end;
         Take (Subtours (N, S));
         if Batch.Is_Empty and then Config.Heuristic_Blossoms then
            Take (Blossoms_Heuristic (N, S));
         end if;
         if Batch.Is_Empty and then Config.Exact_Blossoms then
            Take (Blossoms_Exact (N, S));
         end if;
         if Batch.Is_Empty and then Config.Combs then
            Take (Combs (N, S));
         end if;
         for C of Batch loop
            Add_Cut (C);
         end loop;
         return Natural (Batch.Length);
      end Separate_Cuts;

      function Node_Duals return Real_Vector is
        ([for I in 1 .. N => LP.Row_Dual (Model, I)]);

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

      --  The reduced cost of edge U-V (in the LP or not) for the duals.
      function Reduced (U, V : Positive; Degree : Real_Vector; Cut_Dual : Real_Vector)
        return Long_Float
      is
         R : Long_Float := Long_Float (Costs (U, V)) - Degree (U) - Degree (V);
      begin
         for K in Cut_Dual'Range loop
            if Cut_Dual (K) /= 0.0 then
               R := R - Long_Float (Coefficient (Cuts (K), U, V)) * Cut_Dual (K);
            end if;
         end loop;
         return R;
      end Reduced;

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
         for J in 1 .. Column_Count loop
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
        (for all J in 1 .. Column_Count => X (J) < Epsilon or else X (J) > 1.0 - Epsilon);

      function Fathomed (Bound : Long_Float) return Boolean is
        (Bound > Long_Float (Upper) - 1.0 + Epsilon);
      --  Integer costs: no tour better than Upper below this node.

      type Node_Outcome is (Branch, Pruned, Stopped);
      --  Branch: X is fractional with no cut found (or cutting tails off);
      --  Pruned: infeasible, fathomed or integral; Stopped: time is up or
      --  the simplex failed.

      --  Solves the LP with cuts until none is violated or cutting tails
      --  off (not at the root: Tail False).
      procedure Cut_Loop
        (Bound : out Long_Float; Outcome_Of : out Node_Outcome; Dual : Boolean;
         Tail : Boolean)
      is
         Use_Dual : Boolean := Dual;
         History : Real_Vectors.Vector;
      begin
         loop
            if Time_Up then
               Timed_Out := True;
               Outcome_Of := Stopped;
               Bound := 0.0;
               return;
            end if;
            case LP.Simplex (Model, Use_Dual, Ms_Left) is
               when LP.Optimal =>
                  null;
               when LP.Infeasible =>
                  Outcome_Of := Pruned;
                  Bound := Long_Float'Last;
                  return;
               when LP.Unbounded | LP.Failed | LP.Limit_Reached | LP.Above_Limit =>
                  Timed_Out := True;
                  Outcome_Of := Stopped;
                  Bound := 0.0;
                  return;
            end case;
            Bound := LP.Objective_Value (Model);
            if Root_Done and then Fathomed (Bound) then
               Outcome_Of := Pruned;
               return;
            end if;
            Read_Solution;
            if Config.Purge then
               Purge_Slack_Cuts;
            end if;
            History.Append (Bound);
            if Tail and then Natural (History.Length) > Tailing_Rounds and then not Integral
              and then Bound - History (Natural (History.Length) - Tailing_Rounds)
                       < Tailing_Share * (Long_Float (Upper) - Bound)
            then
               Outcome_Of := Branch;
               return;
            end if;
            exit when Separate_Cuts = 0;
            Use_Dual := True;
         end loop;
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
            Outcome_Of := Pruned;
         else
            Outcome_Of := Branch;
         end if;
      end Cut_Loop;

      --  Columns at 0 whose reduced cost exceeds the gap are fixed at 0,
      --  columns at 1 whose reduced cost is below minus the gap at 1; the
      --  fixes join Fixes (Global: the root bounds change instead).
      procedure Fix_By_Reduced_Cost
        (Bound : Long_Float; Fixes : in out Fix_Vectors.Vector; Global : Boolean)
      is
         Gap : constant Long_Float := Long_Float (Upper) - 1.0 + Epsilon - Bound;
      begin
         for J in 1 .. Column_Count loop
            if not Edges (J).Fixed_One then
               declare
                  D : constant Long_Float := LP.Reduced_Cost (Model, J);
                  Value : Integer := -1;
               begin
                  if X (J) < Epsilon and then D > Gap then
                     Value := 0;
                  elsif X (J) > 1.0 - Epsilon and then -D > Gap then
                     Value := 1;
                  end if;
                  if Value >= 0 and then Fixed_Now (J) = 0 then
                     Set_Bounds (J, Value, Value);
                     Fixed_Now (J) := 1;
                     Stats.Fixed := Stats.Fixed + 1;
                     if Global then
                        Root_Low (J) := Value;
                        Root_High (J) := Value;
                     else
                        Fixes.Append (Fix'(J, Value));
                        Touched.Append (J);
                     end if;
                  end if;
               end;
            end if;
         end loop;
      end Fix_By_Reduced_Cost;

      --  After the root: with the root duals (dual feasible for every
      --  edge once pricing has ended), edges that cannot be in a tour
      --  better than Upper stay out, the others all join the LP, so that
      --  no pricing is needed below.
      procedure Add_Promising_Edges (Root_Bound : Long_Float) is
         Degree : constant Real_Vector := Node_Duals;
         Cut_Dual : constant Real_Vector := Cut_Duals;
         Gap : constant Long_Float := Long_Float (Upper) - 1.0 + Epsilon - Root_Bound;
      begin
         for U in 1 .. N loop
            for V in U + 1 .. N loop
               if Ids (U, V) = 0 and then Costs (U, V) /= Forbidden
                 and then Reduced (U, V, Degree, Cut_Dual) <= Gap
               then
                  Add_Edge (U, V);
               end if;
            end loop;
         end loop;
      end Add_Promising_Edges;

      --  The LP's column bounds become the root's and then Fixes.
      procedure Enter (Fixes : Fix_Vectors.Vector) is
      begin
         for J of Touched loop
            Set_Bounds (J, Root_Low (J), Root_High (J));
            Fixed_Now (J) := (if Root_Low (J) = Root_High (J) then 1 else 0);
         end loop;
         Touched.Clear;
         for F of Fixes loop
            Set_Bounds (F.Column, F.Value, F.Value);
            Fixed_Now (F.Column) := 1;
            Touched.Append (F.Column);
         end loop;
      end Enter;

      --  The LP value with column J fixed at Value, by a few dual simplex
      --  steps (a lower bound on it); Long_Float'Last when that child is
      --  infeasible or cannot beat Upper. The basis is restored.
      function Trial (J : Positive; Value : Natural; Fallback : Long_Float) return Long_Float is
         Saved : constant LP.Basis := LP.Current_Basis (Model);
         Found : Long_Float;
      begin
         Set_Bounds (J, Value, Value);
         case LP.Simplex (Model, True, Iteration_Limit => Strong_Iterations,
                          Objective_Limit => Long_Float (Upper) - 1.0 + Epsilon)
         is
            when LP.Optimal | LP.Limit_Reached =>
               Found := LP.Objective_Value (Model);
               if Fathomed (Found) then
                  Found := Long_Float'Last;
               end if;
            when LP.Infeasible | LP.Above_Limit =>
               Found := Long_Float'Last;
            when LP.Unbounded | LP.Failed =>
               Found := Fallback;
         end case;
         --  J is fractional: not fixed, at its root bounds.
         Set_Bounds (J, Root_Low (J), Root_High (J));
         LP.Restore_Basis (Model, Saved);
         return Found;
      end Trial;

      --  The column to branch on: among the Strong_Branching most
      --  fractional, the one whose children's bounds rise most (product
      --  score); a child found fathomed fixes its column the other way
      --  (Fixed True: then re-solve instead of branching).
      procedure Choose_Branch
        (Bound : Long_Float; Fixes : in out Fix_Vectors.Vector; Column : out Natural;
         Fixed : out Boolean; Dead : out Boolean)
      is
         K : constant Natural := Natural'Max (1, Config.Strong_Branching);
         Picks : array (1 .. K) of Natural := [others => 0];
         Closeness : array (1 .. K) of Long_Float := [others => 0.0];
         Count : Natural := 0;
         Best_Score : Long_Float := -1.0;
      begin
         Column := 0;
         Fixed := False;
         Dead := False;
         for J in 1 .. Column_Count loop
            declare
               F : constant Long_Float := Long_Float'Min (X (J), 1.0 - X (J));
               I : Natural;
            begin
               if F > Epsilon and then (Count < K or else F > Closeness (Count)) then
                  if Count < K then
                     Count := Count + 1;
                  end if;
                  I := Count;
                  while I > 1 and then (Closeness (I - 1) < F
                                        or else (Closeness (I - 1) = F
                                                 and then Edges (Picks (I - 1)).Weight
                                                          < Edges (J).Weight))
                  loop
                     Picks (I) := Picks (I - 1);
                     Closeness (I) := Closeness (I - 1);
                     I := I - 1;
                  end loop;
                  Picks (I) := J;
                  Closeness (I) := F;
               end if;
            end;
         end loop;
         if Count = 0 then
            return;
         end if;
         Column := Picks (1);
         if Config.Strong_Branching = 0 then
            return;
         end if;
         for I in 1 .. Count loop
            declare
               J : constant Positive := Picks (I);
               Down : constant Long_Float := Trial (J, 0, Bound);
               Up   : constant Long_Float := Trial (J, 1, Bound);
            begin
               if Down = Long_Float'Last and then Up = Long_Float'Last then
                  Dead := True;
                  return;
               elsif Down = Long_Float'Last or else Up = Long_Float'Last then
                  Set_Bounds (J, (if Down = Long_Float'Last then 1 else 0),
                              (if Down = Long_Float'Last then 1 else 0));
                  Fixes.Append (Fix'(J, (if Down = Long_Float'Last then 1 else 0)));
                  Fixed_Now (J) := 1;
                  Touched.Append (J);
                  Fixed := True;
               elsif not Fixed then
                  declare
                     Score : constant Long_Float :=
                       Long_Float'Max (Down - Bound, 1.0E-6) * Long_Float'Max (Up - Bound, 1.0E-6);
                  begin
                     if Score > Best_Score then
                        Best_Score := Score;
                        Column := J;
                     end if;
                  end;
               end if;
            end;
         end loop;
      end Choose_Branch;

      procedure Cleanup is
      begin
         LP.Delete_Problem (Model);
         Free (Costs);
         Free (Ids);
      end Cleanup;

      Lowest_Open : Long_Float := 0.0;
      --  At a time-out: the least bound of the nodes left.

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
      if Config.Pricing then
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
      else
         for U in 1 .. N loop
            for V in U + 1 .. N loop
               if Ids (U, V) = 0 and then Costs (U, V) /= Forbidden then
                  Add_Edge (U, V);
               end if;
            end loop;
         end loop;
      end if;

      --  The root: cuts and pricing until neither adds anything.
      declare
         Bound : Long_Float := 0.0;
         Status : Node_Outcome;
         Dual : Boolean := False;
         Root_Fixes : Fix_Vectors.Vector;
      begin
         loop
            Cut_Loop (Bound, Status, Dual, Tail => False);
            exit when Status /= Branch and then Status /= Pruned;
            exit when Status = Pruned and then Bound = Long_Float'Last;
            exit when Price = 0;
            Dual := False;
         end loop;
         if Status = Stopped then
            null;
         elsif Bound = Long_Float'Last then
            raise Program_Error with "branch and cut: the root LP is infeasible";
         else
            Root_Done := True;
            Stats.Nodes := 1;
            Stats.Root_Bound := Bound;
            if Status = Branch and then not Fathomed (Bound) then
               Fix_By_Reduced_Cost (Bound, Root_Fixes, Global => True);
               Add_Promising_Edges (Bound);
               Open.Append (Open_Node'(Bound => Bound, Fixes => <>));
               Stats.Nodes := 0;
            end if;
         end if;
      end;

      --  Branch and bound: the open node of least bound (or the last).
      while not Open.Is_Empty and then not Timed_Out loop
         declare
            Pick : Positive := Open.Last_Index;
         begin
            if Config.Best_Bound then
               for I in 1 .. Open.Last_Index loop
                  if Open (I).Bound < Open (Pick).Bound then
                     Pick := I;
                  end if;
               end loop;
            end if;
            declare
               Here : Open_Node := Open (Pick);
               Bound : Long_Float;
               Status : Node_Outcome;
               Column : Natural;
               Fixed, Dead : Boolean;
            begin
               Open.Delete (Pick);
               if not Fathomed (Here.Bound) then
                  Stats.Nodes := Stats.Nodes + 1;
                  Enter (Here.Fixes);
                  loop
                     Cut_Loop (Bound, Status, Dual => True, Tail => True);
                     if Status = Stopped then
                        Open.Append (Here);
                        exit;
                     end if;
                     exit when Status = Pruned;
                     if Config.Node_Fixing then
                        Fix_By_Reduced_Cost (Bound, Here.Fixes, Global => False);
                     end if;
                     Choose_Branch (Bound, Here.Fixes, Column, Fixed, Dead);
                     exit when Dead;
                     if not Fixed then
                        if Column = 0 then
                           raise Program_Error with "branch and cut: no column to branch on";
                        end if;
                        for Value in reverse 0 .. 1 loop
                           declare
                              Child : Open_Node := (Bound => Bound, Fixes => Here.Fixes);
                           begin
                              Child.Fixes.Append (Fix'(Column, Value));
                              Open.Append (Child);
                           end;
                        end loop;
                        exit;
                     end if;
                     if Time_Up then
                        Here.Bound := Bound;
                        Open.Append (Here);
                        exit;
                     end if;
                  end loop;
                  if Time_Up and then not Open.Is_Empty then
                     Timed_Out := True;
                  end if;
               end if;
            end;
         end;
      end loop;
      if Timed_Out then
         Lowest_Open := Long_Float'Last;
         for Node of Open loop
            Lowest_Open := Long_Float'Min (Lowest_Open, Node.Bound);
         end loop;
         if Open.Is_Empty then
            Lowest_Open := Stats.Root_Bound;
         end if;
      end if;

      Outcome.Upper := Upper;
      Outcome.Proven := Root_Done and then not Timed_Out;
      Outcome.Lower :=
        (if Outcome.Proven then Upper
         elsif Root_Done then
            Cost'Min (Upper, Cost (Long_Float'Ceiling (Lowest_Open - Epsilon)))
         else 0);
      Outcome.Nodes := Stats.Nodes;
      Outcome.Cuts := Stats.Cuts;
      Outcome.By_Class := Stats.By_Class;
      Outcome.Purged := Stats.Purged;
      Outcome.Fixed := Stats.Fixed;
      Outcome.Root_Bound := Stats.Root_Bound;
      Outcome.Edges := Column_Count;
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
      Outcome.CPU := To_Duration (Ada.Execution_Time."-" (Ada.Execution_Time.Clock, CPU_Started));
      Cleanup;
   exception
      when others =>
         Cleanup;
         raise;
   end Solve;

end Sancta.Allocation.Branch_And_Cut;
