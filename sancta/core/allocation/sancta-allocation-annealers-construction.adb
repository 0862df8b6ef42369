package body Sancta.Allocation.Annealers.Construction is

   procedure Best_Insert (P : Problem; S : in out State; W : Weights; T : Positive;
                          Only : Natural := 0) is
      Best : Move;
      Best_Value : Long_Float := Long_Float'Last;
      Found : Boolean := False;
      L : constant Natural := Location_Of (P, T, S.Choice (T));

      --  T after position After of robot R's tour.
      procedure Try (R : Positive; After : Natural) is
         Mv : Move;
         Ok : Boolean;
      begin
         Mv.A.Robot := R;
         Add (Mv.A, R, 1, After);
         Add_Single (Mv.A, T, L);
         Add (Mv.A, R, After + 1, S.Length (R));
         Evaluate_Move (P, S, W, Mv, Ok);
         if Mv.Value < Best_Value then
            Best_Value := Mv.Value;
            Best := Mv;
            Found := True;
         end if;
      end Try;

      function Allowed (R : Positive) return Boolean is
        ((Only = 0 or else R = Only) and then P.Can_Do (R, T));

      function Near_Placed return Boolean is
        (for some K in 1 .. S.Near_Count (T) =>
           S.Owner (S.Near (T, K)) /= 0 and then Allowed (S.Owner (S.Near (T, K))));
   begin
      if S.Tasks > Candidate_Insertion_Above and then Near_Placed then
         --  Each robot's first and last free place, and both sides of each
         --  of T's nearest tasks already in a tour.
         for R in 1 .. S.Robots loop
            if Allowed (R) then
               Try (R, P.Frozen_Length (R));
               if S.Length (R) > P.Frozen_Length (R) then
                  Try (R, S.Length (R));
               end if;
            end if;
         end loop;
         for K in 1 .. S.Near_Count (T) loop
            declare
               U : constant Positive := S.Near (T, K);
               R : constant Natural := S.Owner (U);
            begin
               if R /= 0 and then Allowed (R) then
                  if S.Position (U) - 1 > P.Frozen_Length (R) then
                     Try (R, S.Position (U) - 1);
                  end if;
                  if S.Position (U) > P.Frozen_Length (R) and then S.Position (U) < S.Length (R)
                  then
                     Try (R, S.Position (U));
                  end if;
               end if;
            end;
         end loop;
      else
         for R in 1 .. S.Robots loop
            if Allowed (R) then
               for After in P.Frozen_Length (R) .. S.Length (R) loop
                  Try (R, After);
               end loop;
            end if;
         end loop;
      end if;
      if not Found then
         raise Program_Error with "no robot can do task" & T'Image;
      end if;
      Apply (P, S, Best);
   end Best_Insert;

   procedure Remove_Tasks (P : Problem; S : in out State; List : Count_Array) is
      Gone : Boolean_Array (1 .. S.Tasks) := [others => False];
      First : Count_Array (1 .. S.Robots) := [others => 0];
   begin
      for T of List loop
         Gone (T) := True;
         declare
            R : constant Positive := S.Owner (T);
         begin
            if First (R) = 0 or else S.Position (T) < First (R) then
               First (R) := S.Position (T);
            end if;
         end;
      end loop;
      for T of List loop
         S.Owner (T) := 0;
         S.Position (T) := 0;
      end loop;
      for R in 1 .. S.Robots loop
         if First (R) /= 0 then
            declare
               N : Natural := First (R) - 1;
            begin
               for I in First (R) .. S.Length (R) loop
                  if not Gone (S.Task_At (R, I)) then
                     N := N + 1;
                     S.Task_At (R, N) := S.Task_At (R, I);
                  end if;
               end loop;
               S.Length (R) := N;
               Rebuild (P, S, R, First (R));
            end;
         end if;
      end loop;
   end Remove_Tasks;

   procedure Construct (P : Problem; S : in out State; C : Criterion; G : in out Generator) is
      Order : Count_Array (1 .. P.Tasks);
      N     : Natural := 0;
      Done  : Boolean_Array (1 .. P.Tasks) := [others => False];
      W     : Weights := (C, 0.0, 0.0);
      Empty_A : Assignment := Empty (P);
   begin
      if Has_Plan (P) then
         Empty_A.Branch := Cheapest_Selection (P);
      end if;
      Load (P, S, Empty_A);
      for T in 1 .. P.Tasks loop
         if not P.Is_Frozen (T) and then S.Active (T) then
            N := N + 1;
            Order (N) := T;
         end if;
      end loop;
      Shuffle (G, Order, N);
      --  Minimum counts first: the nearest free feasible task to each start.
      for R in 1 .. P.Robots loop
         while S.Length (R) < P.Min_Tasks loop
            declare
               Best : Natural := 0;
               Best_Distance : Cost := Cost'Last;
            begin
               for K in 1 .. N loop
                  declare
                     T : constant Positive := Order (K);
                  begin
                     if not Done (T) and then P.Can_Do (R, T)
                       and then Distance (P, P.Start (R), Location_Of (P, T)) < Best_Distance
                     then
                        Best_Distance := Distance (P, P.Start (R), Location_Of (P, T));
                        Best := T;
                     end if;
                  end;
               end loop;
               exit when Best = 0;
               Done (Best) := True;
               Best_Insert (P, S, W, Best, Only => R);
            end;
         end loop;
      end loop;
      W := Make_Weights (P, C, 1 + S.Total_Cost * Cost (P.Tasks));
      for K in 1 .. N loop
         if not Done (Order (K)) then
            Best_Insert (P, S, W, Order (K));
         end if;
      end loop;
   end Construct;

end Sancta.Allocation.Annealers.Construction;
