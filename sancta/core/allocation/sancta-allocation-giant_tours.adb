package body Sancta.Allocation.Giant_Tours is

   function Applies (P : Problem) return Boolean is
     (not Has_Plan (P) and then P.All_Feasible
      and then (for all T in 1 .. P.Tasks =>
                  P.Alt_Count (T) = 1 and then not P.Is_Frozen (T))
      and then (for all R in 1 .. P.Robots =>
                  P.Frozen_Length (R) = 0 and then not Has_Own_Costs (P, R)
                  and then (for all T in 1 .. P.Tasks => P.Can_Do (R, T))));

   function Giant_Tour (A : Assignment) return Count_Array is
      Result : Count_Array (1 .. Assigned (A));
      N : Natural := 0;
   begin
      for R in 1 .. A.Robots loop
         for J in 1 .. A.Length (R) loop
            N := N + 1;
            Result (N) := A.Tour (R, J);
         end loop;
      end loop;
      return Result;
   end Giant_Tour;

   procedure Split
     (P        : Problem;
      Order    : Count_Array;
      Result   : out Assignment;
      Makespan : out Cost;
      Total    : out Cost)
   is
      N : constant Natural := Order'Length;
      M : constant Positive := P.Robots;
      Least : constant Natural := P.Min_Tasks;
      Loc : Location_Array (1 .. N);
      Inner : array (0 .. N) of Cost := [others => 0];
      --  Inner (I): the arcs from the first to the I-th task of Order.
      type Value is record
         Max, Sum : Cost := Cost'Last;
      end record;
      function "<" (A, B : Value) return Boolean is
        (A.Max < B.Max or else (A.Max = B.Max and then A.Sum < B.Sum));
      F : array (0 .. M, 0 .. N) of Value;
      --  F (K, I): the best split of the first I tasks among robots 1 .. K.
      Cut : array (1 .. M, 0 .. N) of Natural := [others => [others => 0]];
      --  Where robot K's segment starts (after the Cut-th task) in F (K, I).
   begin
      for I in 1 .. N loop
         Loc (I) := Location_Of (P, Order (Order'First + I - 1));
         if I > 1 then
            Inner (I) := Inner (I - 1) + Distance (P, Loc (I - 1), Loc (I));
         end if;
      end loop;
      F (0, 0) := (0, 0);
      for K in 1 .. M loop
         declare
            Mult : constant Cost := Cost (P.Multiplier (K));
            S : constant Natural := P.Start (K);
            E : constant Natural := P.Finish (K);
            Empty : constant Cost := Mult * Distance (P, S, E);
         begin
            for I in 0 .. N loop
               --  Robot K takes tasks J + 1 .. I (none when J = I).
               for J in 0 .. I - Least loop
                  if F (K - 1, J).Max /= Cost'Last then
                     declare
                        C : constant Cost :=
                          (if J = I then Empty
                           else Mult * (Distance (P, S, Loc (J + 1)) + Inner (I) - Inner (J + 1)
                                        + Distance (P, Loc (I), E)));
                        V : constant Value :=
                          (Cost'Max (F (K - 1, J).Max, C), F (K - 1, J).Sum + C);
                     begin
                        if V < F (K, I) then
                           F (K, I) := V;
                           Cut (K, I) := J;
                        end if;
                     end;
                  end if;
               end loop;
            end loop;
         end;
      end loop;
      Result := Empty (P);
      declare
         I : Natural := N;
      begin
         for K in reverse 1 .. M loop
            declare
               J : constant Natural := Cut (K, I);
            begin
               for X in J + 1 .. I loop
                  Result.Tour (K, X - J) := Order (Order'First + X - 1);
               end loop;
               Result.Length (K) := I - J;
               I := J;
            end;
         end loop;
      end;
      Makespan := F (M, N).Max;
      Total := F (M, N).Sum;
   end Split;

end Sancta.Allocation.Giant_Tours;
