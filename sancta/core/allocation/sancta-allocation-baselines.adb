package body Sancta.Allocation.Baselines is

   function Solve (P : Problem; How : Method; C : Criterion := Min_Sum) return Assignment is
      A    : Assignment := Empty (P);
      Sel  : constant Location_Array := Cheapest_Selection (P);
      Done : Boolean_Array (1 .. P.Tasks) := P.Is_Frozen;
      RC   : Cost_Array (1 .. P.Robots);
      Left : Natural := 0;

      function Loc (R : Positive; K : Natural) return Natural is
        (if K = 0 then P.Start (R)
         elsif K > A.Length (R) then P.Finish (R)
         else Location_Of (P, A.Tour (R, K)));

      --  Task T put after position K of robot R: what it adds (Added) and
      --  the key the method chooses by (the least; then the least Added).
      type Candidate is record
         Robot, Task_Id, After : Natural := 0;
         Key, Added : Cost := Cost'Last;
      end record;

      function Better (X, Than : Candidate) return Boolean is
        (X.Key < Than.Key or else (X.Key = Than.Key and then X.Added < Than.Added));

      --  Best becomes T's best place in robot R's tour if that is better.
      procedure Consider (R, T : Positive; Best : in out Candidate) is
         First : constant Natural :=
           (if How = Best_Pair then A.Length (R) else P.Frozen_Length (R));
      begin
         for K in First .. A.Length (R) loop
            declare
               D : constant Cost :=
                 (if How = Best_Pair
                  then Cost (P.Multiplier (R))
                       * Robot_Distance (P, R, Loc (R, K), Location_Of (P, T))
                  else Insertion_Cost (P, A, R, Location_Of (P, T), K));
               Key : constant Cost :=
                 (case How is
                    when Best_Pair => D,
                    when Min_Makespan => RC (R) + D,
                    when Auction =>
                      (if C.Max_Weight > 0.0 and then C.Sum_Weight = 0.0 then RC (R) + D else D));
               Here : constant Candidate :=
                 (Robot => R, Task_Id => T, After => K, Key => Key, Added => D);
            begin
               if Better (Here, Than => Best) then
                  Best := Here;
               end if;
            end;
         end loop;
      end Consider;
   begin
      A.Branch := Sel;
      for T in 1 .. P.Tasks loop
         Done (T) := Done (T) or else not Is_Active (P, Sel, T);
      end loop;
      for R in 1 .. P.Robots loop
         RC (R) := Tour_Cost (P, A, R);
      end loop;
      for T in 1 .. P.Tasks loop
         if not Done (T) then
            Left := Left + 1;
         end if;
      end loop;
      while Left > 0 loop
         declare
            Needy : constant Boolean :=
              (for some R in 1 .. P.Robots => A.Length (R) < P.Min_Tasks);
            Best : Candidate;
         begin
            for R in 1 .. P.Robots loop
               if not Needy or else A.Length (R) < P.Min_Tasks then
                  for T in 1 .. P.Tasks loop
                     if not Done (T) and then P.Can_Do (R, T) then
                        Consider (R, T, Best);
                     end if;
                  end loop;
               end if;
            end loop;
            if Best.Robot = 0 then
               raise Constraint_Error with "baseline: no robot can take the remaining tasks";
            end if;
            Insert (A, Best.Robot, Best.Task_Id, Best.After);
            RC (Best.Robot) := Tour_Cost (P, A, Best.Robot);
            Done (Best.Task_Id) := True;
            Left := Left - 1;
         end;
      end loop;
      return A;
   end Solve;

end Sancta.Allocation.Baselines;
