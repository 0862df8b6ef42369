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

   procedure Set_Distance (This : in out Problem; From, To : Positive; D : Cost) is
   begin
      This.Distance (From, To) := D;
   end Set_Distance;

   procedure Update_Symmetry (This : in out Problem) is
   begin
      This.Symmetric := True;
      for A in 1 .. This.Locations loop
         for B in A + 1 .. This.Locations loop
            if This.Distance (A, B) /= This.Distance (B, A) then
               This.Symmetric := False;
               return;
            end if;
         end loop;
      end loop;
   end Update_Symmetry;

   procedure Set_Symmetric_Distance (This : in out Problem; A, B : Positive; D : Cost) is
   begin
      This.Distance (A, B) := D;
      This.Distance (B, A) := D;
   end Set_Symmetric_Distance;

   procedure Set_Euclidean
     (This : in out Problem; Points : Point_Array; Scale : Long_Float := 1.0;
      Round : Boolean := True)
   is
      use Sancta.Geometry;
   begin
      This.Coordinates := Points;
      This.Has_Coordinates := True;
      This.Scale := Scale;
      This.Symmetric := True;
      for A in Points'Range loop
         for B in Points'Range loop
            declare
               D : constant Long_Float :=
                 Long_Float (Distance (Points (A), Points (B))) * Scale;
            begin
               This.Distance (A, B) :=
                 (if Round then Cost (Long_Float'Floor (D + 0.5))
                  else Cost (Long_Float'Floor (D)));
            end;
         end loop;
      end loop;
   end Set_Euclidean;

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

   function Check (This : Problem) return String is
      Seen : Boolean_Array (1 .. This.Tasks) := [others => False];
   begin
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
