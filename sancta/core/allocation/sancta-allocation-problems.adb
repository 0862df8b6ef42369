with Ada.Strings.Fixed;

package body Sancta.Allocation.Problems is

   function Create
     (Locations, Tasks, Robots : Positive; Alternatives : Natural := 0)
      return Problem_Access
   is
      Alts : constant Positive := Tasks + Alternatives;
      P    : constant Problem_Access :=
        new Problem (Locations, Tasks, Robots, Alts);
   begin
      for T in 1 .. Tasks loop
         P.Alt_First (T) := T;
         P.Alt_Count (T) := 1;
         P.Alt_Location (T) := Positive'Min (T, Locations);
      end loop;
      P.Next_Alt := Tasks + 1;
      return P;
   end Create;

   --  A new matrix over all locations (0 .. Locations) holding Cost_Of.
   generic
      with function Cost_Of (From, To : Natural) return Cost;
   function Filled_Matrix (Locations : Natural) return Cost_Matrix_Access;

   function Filled_Matrix (Locations : Natural) return Cost_Matrix_Access is
      M : constant Cost_Matrix_Access := new Cost_Matrix (0 .. Locations, 0 .. Locations);
   begin
      for A in M'Range (1) loop
         for B in M'Range (2) loop
            M (A, B) := Cost_Of (A, B);
         end loop;
      end loop;
      return M;
   end Filled_Matrix;

   --  The matrix, allocated with the current distances if there is none.
   procedure Need_Matrix (This : in out Problem) is
      function Current (From, To : Natural) return Cost is (Distance (This, From, To));
      function Current_Matrix is new Filled_Matrix (Current);
   begin
      if This.Rule = From_Matrix and then This.Matrix /= null then
         return;
      end if;
      This.Matrix := Current_Matrix (This.Locations);
      This.Rule := From_Matrix;
   end Need_Matrix;

   procedure Set_Distance (This : in out Problem; From, To : Positive; D : Cost) is
   begin
      Need_Matrix (This);
      This.Matrix (From, To) := D;
   end Set_Distance;

   procedure Update_Symmetry (This : in out Problem) is
   begin
      This.Symmetric := True;
      if This.Rule /= From_Matrix or else This.Matrix = null then
         return;
      end if;
      for A in 1 .. This.Locations loop
         for B in A + 1 .. This.Locations loop
            if This.Matrix (A, B) /= This.Matrix (B, A) then
               This.Symmetric := False;
               return;
            end if;
         end loop;
      end loop;
   end Update_Symmetry;

   procedure Set_Symmetric_Distance (This : in out Problem; A, B : Positive; D : Cost) is
   begin
      Set_Distance (This, A, B, D);
      This.Matrix (B, A) := D;
   end Set_Symmetric_Distance;

   procedure Set_Euclidean
     (This : in out Problem; Points : Point_Array; Scale : Long_Float := 1.0;
      Round : Boolean := True; Rule : Distance_Rule := Euclidean_Nearest;
      Keep_Matrix_Up_To : Natural := Matrix_Limit) is
   begin
      This.Coordinates := Points;
      This.Has_Coordinates := True;
      This.Scale := Scale;
      This.Symmetric := True;
      This.Rule := (if Round then Rule else Euclidean_Floor);
      This.Matrix := null;
      if This.Locations <= Keep_Matrix_Up_To then
         Need_Matrix (This);
      end if;
   end Set_Euclidean;

   procedure Copy_Distances (From : Problem; To : in out Problem) is
   begin
      To.Rule := From.Rule;
      To.Matrix := (if From.Matrix = null then null else new Cost_Matrix'(From.Matrix.all));
      To.Symmetric := From.Symmetric;
      To.Coordinates := From.Coordinates;
      To.Has_Coordinates := From.Has_Coordinates;
      To.Scale := From.Scale;
   end Copy_Distances;

   procedure Set_From (This : in out Problem; F : not null Cost_Function) is
   begin
      for A in 1 .. This.Locations loop
         for B in 1 .. This.Locations loop
            Set_Distance (This, A, B, (if A = B then 0 else F (A, B)));
         end loop;
      end loop;
      Update_Symmetry (This);
   end Set_From;

   procedure Set_Task (This : in out Problem; T : Positive; Location : Positive) is
   begin
      This.Alt_First (T) := T;
      This.Alt_Location (T) := Location;
      This.Alt_Count (T) := 1;
   end Set_Task;

   procedure Set_Task_Alternatives
     (This : in out Problem; T : Positive; Locations : Location_Array) is
   begin
      if Locations'Length = 1 then
         This.Alt_First (T) := T;
         This.Alt_Count (T) := 1;
         This.Alt_Location (T) := Locations (Locations'First);
         return;
      end if;
      if This.Next_Alt + Locations'Length - 1 > This.Alternatives then
         raise Constraint_Error with "no room for the alternatives of task" & T'Image;
      end if;
      This.Alt_First (T) := This.Next_Alt;
      This.Alt_Count (T) := Locations'Length;
      for K in Locations'Range loop
         This.Alt_Location (This.Next_Alt) := Locations (K);
         This.Next_Alt := This.Next_Alt + 1;
      end loop;
   end Set_Task_Alternatives;

   procedure Set_Robot
     (This : in out Problem; R : Positive; Start : Positive; Closed : Boolean;
      Multiplier : Positive := 1) is
   begin
      This.Start (R) := Start;
      This.Finish (R) := (if Closed then Start else Nowhere);
      This.Multiplier (R) := Multiplier;
   end Set_Robot;

   procedure Set_Robot_End (This : in out Problem; R : Positive; Finish : Natural) is
   begin
      This.Finish (R) := Finish;
   end Set_Robot_End;

   procedure Forbid (This : in out Problem; R, T : Positive) is
   begin
      This.Can_Do (R, T) := False;
      This.All_Feasible := False;
   end Forbid;

   procedure Freeze (This : in out Problem; R : Positive; Tasks : Location_Array) is
   begin
      This.Frozen_Length (R) := Tasks'Length;
      for K in Tasks'Range loop
         This.Frozen (R, K - Tasks'First + 1) := Tasks (K);
         This.Is_Frozen (Tasks (K)) := True;
      end loop;
   end Freeze;

   --  Robot R's own matrix, from its current distances if it has none.
   procedure Own_Matrix (This : in out Problem; R : Positive) is
      function Current (From, To : Natural) return Cost is
        (Robot_Distance (This, R, From, To));
      function Current_Matrix is new Filled_Matrix (Current);
   begin
      if This.Own (R) = null then
         This.Own (R) := Current_Matrix (This.Locations);
      end if;
      This.Own_Factor (R) := 0.0;
   end Own_Matrix;

   procedure Set_Robot_Distance
     (This : in out Problem; R : Positive; From, To : Positive; D : Cost) is
   begin
      Own_Matrix (This, R);
      This.Own (R) (From, To) := D;
   end Set_Robot_Distance;

   procedure Set_Robot_Costs
     (This : in out Problem; R : Positive; F : not null Robot_Cost_Function) is
   begin
      Own_Matrix (This, R);
      for A in 1 .. This.Locations loop
         for B in 1 .. This.Locations loop
            This.Own (R) (A, B) :=
              (if A = B then 0 else Cost'Max (0, Cost'Min (Infinity, F (R, A, B))));
         end loop;
      end loop;
   end Set_Robot_Costs;

   procedure Set_Robot_Factor (This : in out Problem; R : Positive; Factor : Long_Float) is
   begin
      This.Own (R) := null;
      This.Own_Factor (R) := Factor;
   end Set_Robot_Factor;

   procedure Link (This : in out Problem; Parent : Natural; Child : in out Plan_Node;
                   Id : Positive) is
   begin
      Child.Parent := Parent;
      if Parent = 0 then
         return;
      end if;
      declare
         Up : Plan_Node := This.Plan (Parent);
      begin
         Up.Children := Up.Children + 1;
         if Up.Last_Child = 0 then
            Up.First_Child := Id;
         else
            declare
               Prev : Plan_Node := This.Plan (Up.Last_Child);
            begin
               Prev.Next := Id;
               This.Plan.Replace_Element (Up.Last_Child, Prev);
            end;
         end if;
         Up.Last_Child := Id;
         if Up.Kind = Or_Node then
            Child.Or_Anc := Up.Or_Index;
            Child.Branch := Up.Children;
         else
            Child.Or_Anc := Up.Or_Anc;
            Child.Branch := Up.Branch;
         end if;
         This.Plan.Replace_Element (Parent, Up);
      end;
   end Link;

   procedure Add_Node
     (This : in out Problem; Kind : Inner_Kind; Parent : Natural; Node : out Positive)
   is
      N : Plan_Node := (Kind => Kind, others => <>);
   begin
      if Kind = Or_Node then
         if Or_Count (This) >= This.Tasks then
            raise Constraint_Error with "plan: more OR nodes than tasks";
         end if;
         N.Or_Index := Or_Count (This) + 1;
      end if;
      Node := Natural (This.Plan.Length) + 1;
      Link (This, Parent, N, Node);
      This.Plan.Append (N);
      if Kind = Or_Node then
         This.Or_Nodes.Append (Node);
      end if;
   end Add_Node;

   procedure Add_Plan_Task (This : in out Problem; Parent : Positive; T : Positive) is
      N  : Plan_Node := (Kind => Task_Node, Task_Id => T, others => <>);
      Id : constant Positive := Natural (This.Plan.Length) + 1;
   begin
      if This.In_Plan (T) then
         raise Constraint_Error with "plan: task" & T'Image & " placed twice";
      end if;
      Link (This, Parent, N, Id);
      This.Plan.Append (N);
      This.In_Plan (T) := True;
      This.Task_Or (T) := N.Or_Anc;
      This.Task_Branch (T) := N.Branch;
   end Add_Plan_Task;

   function Or_Active (This : Problem; Sel : Location_Array; O : Natural) return Boolean is
      X : Natural := O;
   begin
      while X /= 0 loop
         declare
            Up : constant Natural := Or_Parent (This, X);
         begin
            if Up /= 0 and then Sel (Up) /= Or_Branch (This, X) then
               return False;
            end if;
            X := Up;
         end;
      end loop;
      return True;
   end Or_Active;

   function Active_Count (This : Problem; Sel : Location_Array) return Natural is
      N : Natural := 0;
   begin
      if not Has_Plan (This) then
         return This.Tasks;
      end if;
      for T in 1 .. This.Tasks loop
         if Is_Active (This, Sel, T) then
            N := N + 1;
         end if;
      end loop;
      return N;
   end Active_Count;

   --  Forces, in Sel, the alternatives above every frozen task; Conflict
   --  names the first frozen task that another one excludes (0: none).
   procedure Force_Frozen (This : Problem; Sel : in out Location_Array;
                           Forced : in out Boolean_Array; Conflict : out Natural) is
   begin
      Conflict := 0;
      for T in 1 .. This.Tasks loop
         if This.Is_Frozen (T) and then This.Task_Or (T) /= 0 then
            declare
               O : Natural := This.Task_Or (T);
               B : Natural := This.Task_Branch (T);
            begin
               while O /= 0 loop
                  if Forced (O) and then Sel (O) /= B then
                     if Conflict = 0 then
                        Conflict := T;
                     end if;
                  end if;
                  Forced (O) := True;
                  Sel (O) := B;
                  B := Or_Branch (This, O);
                  O := Or_Parent (This, O);
               end loop;
            end;
         end if;
      end loop;
   end Force_Frozen;

   function Default_Selection (This : Problem) return Location_Array is
      Sel    : Location_Array (1 .. This.Tasks) := [others => 1];
      Forced : Boolean_Array (1 .. This.Tasks) := [others => False];
      Conflict : Natural;
   begin
      Force_Frozen (This, Sel, Forced, Conflict);
      return Sel;
   end Default_Selection;

   function Is_Locked (This : Problem; O : Positive) return Boolean is
      Sel    : Location_Array (1 .. This.Tasks) := [others => 1];
      Forced : Boolean_Array (1 .. This.Tasks) := [others => False];
      Conflict : Natural;
   begin
      Force_Frozen (This, Sel, Forced, Conflict);
      return Forced (O);
   end Is_Locked;

   function Cheapest_Selection (This : Problem) return Location_Array is
      Sel    : Location_Array (1 .. This.Tasks) := [others => 1];
      Forced : Boolean_Array (1 .. This.Tasks) := [others => False];
      Conflict : Natural;

      function Task_Estimate (T : Positive) return Cost is
         Best : Cost := Infinity;
         L    : constant Positive := Location_Of (This, T);
      begin
         for R in 1 .. This.Robots loop
            if This.Can_Do (R, T) then
               Best := Cost'Min
                 (Best, Cost (This.Multiplier (R))
                    * (Robot_Distance (This, R, This.Start (R), L)
                       + Robot_Distance (This, R, L, This.Finish (R))));
            end if;
         end loop;
         return Cost'Min (Best, Infinity);
      end Task_Estimate;

      function Estimate (N : Positive) return Cost is
         Node : constant Plan_Node := This.Plan (N);
         C    : Natural := Node.First_Child;
         K    : Natural := 0;
         Sum  : Cost := 0;
         Best : Cost := Cost'Last;
      begin
         case Node.Kind is
            when Task_Node =>
               return Task_Estimate (Node.Task_Id);
            when And_Node =>
               while C /= 0 loop
                  Sum := Cost'Min (Sum + Estimate (C), 64 * Infinity);
                  C := This.Plan (C).Next;
               end loop;
               return Sum;
            when Or_Node =>
               while C /= 0 loop
                  K := K + 1;
                  declare
                     E : constant Cost := Estimate (C);
                  begin
                     if Forced (Node.Or_Index) then
                        if K = Sel (Node.Or_Index) then
                           Best := E;
                        end if;
                     elsif E < Best then
                        Best := E;
                        Sel (Node.Or_Index) := K;
                     end if;
                  end;
                  C := This.Plan (C).Next;
               end loop;
               return (if Best = Cost'Last then 0 else Best);
         end case;
      end Estimate;
   begin
      Force_Frozen (This, Sel, Forced, Conflict);
      for N in 1 .. Natural (This.Plan.Length) loop
         if This.Plan (N).Parent = 0 then
            declare
               Unused : constant Cost := Estimate (N);
            begin
               null;
            end;
         end if;
      end loop;
      return Sel;
   end Cheapest_Selection;

   function Task_Name (This : Problem; T : Positive) return String is
     (if T <= Natural (This.Task_Names.Length) then This.Task_Names (T)
      else Ada.Strings.Fixed.Trim (T'Image, Ada.Strings.Left));

   function Or_Name (This : Problem; O : Positive) return String is
     (if O <= Natural (This.Or_Names.Length) then This.Or_Names (O)
      else "or" & Ada.Strings.Fixed.Trim (O'Image, Ada.Strings.Left));

   function Check (This : Problem) return String is
      Seen : Boolean_Array (1 .. This.Tasks) := [others => False];
   begin
      if Has_Plan (This) then
         declare
            Sel    : Location_Array (1 .. This.Tasks) := [others => 1];
            Forced : Boolean_Array (1 .. This.Tasks) := [others => False];
            Conflict : Natural;
            Holds  : Boolean_Array (1 .. Natural (This.Plan.Length)) := [others => False];
         begin
            Force_Frozen (This, Sel, Forced, Conflict);
            if Conflict /= 0 then
               return "frozen task" & Conflict'Image
                 & " lies in an OR alternative that another frozen task excludes";
            end if;
            --  Every inner node must hold a task below it.
            for N in 1 .. Natural (This.Plan.Length) loop
               if This.Plan (N).Kind = Task_Node then
                  declare
                     X : Natural := N;
                  begin
                     while X /= 0 and then not Holds (X) loop
                        Holds (X) := True;
                        X := This.Plan (X).Parent;
                     end loop;
                  end;
               end if;
            end loop;
            for N in 1 .. Natural (This.Plan.Length) loop
               if not Holds (N) then
                  return "plan node" & N'Image & " (" & This.Plan (N).Kind'Image
                    & ") has no task below it";
               end if;
            end loop;
         end;
      end if;
      for R in 1 .. This.Robots loop
         for K in 1 .. This.Frozen_Length (R) loop
            declare
               T : constant Natural := This.Frozen (R, K);
            begin
               if T not in 1 .. This.Tasks or else Seen (T) then
                  return "frozen task" & T'Image & " of robot" & R'Image
                    & " is unknown or frozen twice";
               end if;
               Seen (T) := True;
            end;
         end loop;
      end loop;
      if This.Min_Tasks * This.Robots > This.Tasks then
         return "too few tasks:" & This.Tasks'Image & " for" & This.Robots'Image
           & " robots needing" & This.Min_Tasks'Image & " each";
      end if;
      for T in 1 .. This.Tasks loop
         declare
            Any : Boolean := False;
         begin
            for R in 1 .. This.Robots loop
               Any := Any or else This.Can_Do (R, T);
            end loop;
            if not Any then
               return "no robot can do task" & T'Image;
            end if;
         end;
      end loop;
      return "";
   end Check;

end Sancta.Allocation.Problems;
