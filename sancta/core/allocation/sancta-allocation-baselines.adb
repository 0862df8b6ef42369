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

      --  Added cost of T after position K of robot R.
      function Added (R, T : Positive; K : Natural) return Cost is
         L : constant Natural := Location_Of (P, T);
      begin
         return (if P.Can_Do (R, T) then 0 else Infinity)
           + Cost (P.Multiplier (R))
             * (Robot_Distance (P, R, Loc (R, K), L) + Robot_Distance (P, R, L, Loc (R, K + 1))
                - Robot_Distance (P, R, Loc (R, K), Loc (R, K + 1)));
      end Added;
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
            Needy : Boolean := False;
            Best_R, Best_T : Natural := 0;
            Best_K : Natural := 0;
            Best_Key, Best_Tie : Cost := Cost'Last;
         begin
            for R in 1 .. P.Robots loop
               Needy := Needy or else A.Length (R) < P.Min_Tasks;
            end loop;
            for R in 1 .. P.Robots loop
               if not Needy or else A.Length (R) < P.Min_Tasks then
                  for T in 1 .. P.Tasks loop
                     if not Done (T) and then P.Can_Do (R, T) then
                        declare
                           First : constant Natural :=
                             (if How = Best_Pair then A.Length (R)
                              else Natural'Max (P.Frozen_Length (R), 0));
                        begin
                           for K in First .. A.Length (R) loop
                              declare
                                 D : constant Cost :=
                                   (if How = Best_Pair
                                    then Cost (P.Multiplier (R))
                                         * Robot_Distance (P, R, Loc (R, K),
                                                           Location_Of (P, T))
                                    else Added (R, T, K));
                                 Key : constant Cost :=
                                   (case How is
                                      when Best_Pair => D,
                                      when Min_Makespan => RC (R) + D,
                                      when Auction =>
                                        (if C.Max_Weight > 0.0 and then C.Sum_Weight = 0.0
                                         then RC (R) + D else D));
                              begin
                                 if Key < Best_Key or else (Key = Best_Key and then D < Best_Tie)
                                 then
                                    Best_Key := Key;
                                    Best_Tie := D;
                                    Best_R := R;
                                    Best_T := T;
                                    Best_K := K;
                                 end if;
                              end;
                           end loop;
                        end;
                     end if;
                  end loop;
               end if;
            end loop;
            if Best_R = 0 then
               raise Constraint_Error with "baseline: no robot can take the remaining tasks";
            end if;
            Insert (A, Best_R, Best_T, Best_K);
            RC (Best_R) := Tour_Cost (P, A, Best_R);
            Done (Best_T) := True;
            Left := Left - 1;
         end;
      end loop;
      return A;
   end Solve;

end Sancta.Allocation.Baselines;
