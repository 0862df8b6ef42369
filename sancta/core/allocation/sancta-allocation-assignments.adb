package body Sancta.Allocation.Assignments is

   function Empty (P : Problem) return Assignment is
   begin
      return A : Assignment (P.Robots, P.Tasks) do
         for R in 1 .. P.Robots loop
            for K in 1 .. P.Frozen_Length (R) loop
               A.Tour (R, K) := P.Frozen (R, K);
            end loop;
            A.Length (R) := P.Frozen_Length (R);
         end loop;
         A.Branch := Default_Selection (P);
      end return;
   end Empty;

   procedure Append (This : in out Assignment; Robot, T : Positive) is
   begin
      This.Length (Robot) := This.Length (Robot) + 1;
      This.Tour (Robot, This.Length (Robot)) := T;
   end Append;

   procedure Insert (This : in out Assignment; Robot, T : Positive; After : Natural) is
   begin
      for K in reverse After + 1 .. This.Length (Robot) loop
         This.Tour (Robot, K + 1) := This.Tour (Robot, K);
      end loop;
      This.Tour (Robot, After + 1) := T;
      This.Length (Robot) := This.Length (Robot) + 1;
   end Insert;

   function Assigned (This : Assignment) return Natural is
      N : Natural := 0;
   begin
      for R in 1 .. This.Robots loop
         N := N + This.Length (R);
      end loop;
      return N;
   end Assigned;

   procedure Robot_Costs
     (P : Problem; This : Assignment; Robot : Positive; Length, Completion : out Cost)
   is
      Here : Positive := P.Start (Robot);
      Time : Cost := 0;
      Bad  : Cost := 0;
      M    : constant Cost := Cost (P.Multiplier (Robot));
   begin
      Completion := 0;
      for K in 1 .. This.Length (Robot) loop
         declare
            T    : constant Positive := This.Tour (Robot, K);
            Next : constant Positive := Location_Of (P, T, This.Choice (T));
         begin
            Time := Time + Robot_Distance (P, Robot, Here, Next);
            Completion := Completion + M * Time;
            if not P.Can_Do (Robot, T) then
               Bad := Bad + 1;
            end if;
            Here := Next;
         end;
      end loop;
      Time := Time + Robot_Distance (P, Robot, Here, P.Finish (Robot));
      Length := M * Time + Bad * Infinity;
      Completion := Completion + Bad * Infinity;
   end Robot_Costs;

   function Tour_Cost
     (P : Problem; This : Assignment; Robot : Positive) return Cost
   is
      L, C : Cost;
   begin
      Robot_Costs (P, This, Robot, L, C);
      return L;
   end Tour_Cost;

   function Insertion_Cost
     (P : Problem; This : Assignment; Robot : Positive; Location : Natural; After : Natural)
     return Cost
   is
      function Place (K : Natural) return Natural is
        (if K = 0 then P.Start (Robot)
         elsif K > This.Length (Robot) then P.Finish (Robot)
         else Location_Of (P, This.Tour (Robot, K), This.Choice (This.Tour (Robot, K))));
      Before : constant Natural := Place (After);
      Next   : constant Natural := Place (After + 1);
   begin
      return Cost (P.Multiplier (Robot))
        * (Robot_Distance (P, Robot, Before, Location) + Robot_Distance (P, Robot, Location, Next)
           - Robot_Distance (P, Robot, Before, Next));
   end Insertion_Cost;

   function Evaluate
     (P : Problem; This : Assignment; C : Criterion) return Evaluation
   is
   begin
      return E : Evaluation (This.Robots) do
         for R in 1 .. This.Robots loop
            Robot_Costs (P, This, R, E.Robot_Cost (R), E.Robot_Completion (R));
            E.Max := Cost'Max (E.Max, E.Robot_Cost (R));
            E.Sum := E.Sum + E.Robot_Cost (R);
            E.Completion_Sum := E.Completion_Sum + E.Robot_Completion (R);
         end loop;
         E.Active := Active_Count (P, This.Branch);
         E.Value := Value (C, E.Max, E.Sum, E.Completion_Sum, E.Active);
      end return;
   end Evaluate;

   function Validate (P : Problem; This : Assignment) return String is
      Seen : Boolean_Array (1 .. P.Tasks) := [others => False];
   begin
      if This.Robots /= P.Robots or else This.Tasks /= P.Tasks then
         return "assignment does not match the problem's size";
      end if;
      for R in 1 .. P.Robots loop
         if This.Length (R) < P.Min_Tasks then
            return "robot" & R'Image & " has" & This.Length (R)'Image
              & " tasks, fewer than" & P.Min_Tasks'Image;
         end if;
         for K in 1 .. P.Frozen_Length (R) loop
            if K > This.Length (R) or else This.Tour (R, K) /= P.Frozen (R, K) then
               return "robot" & R'Image & " lost its frozen task at position" & K'Image;
            end if;
         end loop;
         for K in 1 .. This.Length (R) loop
            declare
               T : constant Natural := This.Tour (R, K);
            begin
               if T not in 1 .. P.Tasks then
                  return "robot" & R'Image & " has unknown task" & T'Image;
               elsif Seen (T) then
                  return "task" & T'Image & " assigned twice";
               elsif not P.Can_Do (R, T) then
                  return "robot" & R'Image & " cannot do task" & T'Image;
               end if;
               Seen (T) := True;
            end;
         end loop;
      end loop;
      for O in 1 .. Or_Count (P) loop
         if This.Branch (O) not in 1 .. Alternatives (P, O) then
            return "OR node" & O'Image & " has invalid alternative" & This.Branch (O)'Image;
         end if;
      end loop;
      for T in 1 .. P.Tasks loop
         if Seen (T) and then not Is_Active (P, This.Branch, T) then
            return "task" & T'Image & " is assigned but lies in an unchosen alternative";
         elsif not Seen (T) and then Is_Active (P, This.Branch, T) then
            return "task" & T'Image & " is not assigned";
         elsif This.Choice (T) not in 1 .. P.Alt_Count (T) then
            return "task" & T'Image & " has invalid choice" & This.Choice (T)'Image;
         end if;
      end loop;
      return "";
   end Validate;

end Sancta.Allocation.Assignments;
