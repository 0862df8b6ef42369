package body Sancta.Allocation.Annealers.Neighbourhoods is

   function Random_Task (P : Problem; S : State; G : in out Generator) return Natural is
   begin
      if S.Active_Tasks < S.Tasks then
         --  Plan trees: a uniform pick among the tasks in the tours (O (R)).
         for Try in 1 .. 8 loop
            declare
               K : Natural := Random.Below (G, Positive'Max (1, S.Active_Tasks));
            begin
               for R in 1 .. S.Robots loop
                  if K < S.Length (R) then
                     if K + 1 > P.Frozen_Length (R) then
                        return S.Task_At (R, K + 1);
                     end if;
                     exit;
                  end if;
                  K := K - S.Length (R);
               end loop;
            end;
         end loop;
         return 0;
      end if;
      for Try in 1 .. 8 loop
         declare
            T : constant Positive := 1 + Random.Below (G, S.Tasks);
         begin
            if Movable (P, S, T) then
               return T;
            end if;
         end;
      end loop;
      return 0;
   end Random_Task;

   procedure Relocate (S : State; Mv : in out Move; R1 : Positive; I, J : Positive;
                       R2 : Positive; Q : Natural; Rev : Boolean; Ok : out Boolean;
                       New_Location : Natural := 0)
   is
      procedure Moved (T : in out Tour_Plan) is
      begin
         if New_Location /= 0 then
            Add_Single (T, S.Task_At (R1, I), New_Location);
         else
            Add (T, R1, I, J, Rev);
         end if;
      end Moved;
   begin
      Clear (Mv);
      Ok := True;
      if R1 /= R2 then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, J + 1, S.Length (R1));
         Mv.B.Robot := R2;
         Add (Mv.B, R2, 1, Q);
         Moved (Mv.B);
         Add (Mv.B, R2, Q + 1, S.Length (R2));
      elsif Q + 1 < I then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, Q);
         Moved (Mv.A);
         Add (Mv.A, R1, Q + 1, I - 1);
         Add (Mv.A, R1, J + 1, S.Length (R1));
      elsif Q > J then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, J + 1, Q);
         Moved (Mv.A);
         Add (Mv.A, R1, Q + 1, S.Length (R1));
      elsif New_Location /= 0 then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Moved (Mv.A);
         Add (Mv.A, R1, J + 1, S.Length (R1));
      elsif Rev and then I < J then
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, I, J, True);
         Add (Mv.A, R1, J + 1, S.Length (R1));
      else
         Ok := False;
      end if;
   end Relocate;

   procedure Or_Opt
     (P : Problem; S : State; T, U : Positive; Length : Positive;
      Variant : Natural; Mv : in out Move; Ok : out Boolean)
   is
      R1 : constant Positive := S.Owner (T);
      I  : constant Positive := S.Position (T);
      J  : constant Positive := Positive'Min (I + Length - 1, S.Length (R1));
      R2 : constant Positive := S.Owner (U);
      Q  : Natural;
      Rev : Boolean;
   begin
      Ok := False;
      case Variant mod 4 is
         when 0 => Q := S.Position (U); Rev := False;
         when 1 => Q := S.Position (U) - 1; Rev := True;
         when 2 => Q := S.Position (U); Rev := True;
         when others => Q := S.Position (U) - 1; Rev := False;
      end case;
      if Q < P.Frozen_Length (R2) then
         return;
      end if;
      if R2 = R1 and then Q + 1 >= I and then Q <= J then
         return;
      end if;
      Relocate (S, Mv, R1, I, J, R2, Q, Rev, Ok);
   end Or_Opt;

   procedure Two_Opt
     (P : Problem; S : State; T, U : Positive; Variant : Natural;
      Mv : in out Move; Ok : out Boolean)
   is
      R1 : constant Positive := S.Owner (T);
      I  : constant Positive := S.Position (T);
      R2 : constant Positive := S.Owner (U);
      J  : constant Positive := S.Position (U);
   begin
      Ok := False;
      Clear (Mv);
      if R1 = R2 then
         declare
            Lo, Hi : Natural;
         begin
            if I < J then
               if Variant mod 2 = 0 then
                  Lo := I + 1; Hi := J;       --  T, U adjacent after
               else
                  Lo := I; Hi := J - 1;
               end if;
            else
               if Variant mod 2 = 0 then
                  Lo := J + 1; Hi := I;
               else
                  Lo := J; Hi := I - 1;
               end if;
            end if;
            if Hi <= Lo or else Lo <= P.Frozen_Length (R1) then
               return;
            end if;
            Mv.A.Robot := R1;
            Add (Mv.A, R1, 1, Lo - 1);
            Add (Mv.A, R1, Lo, Hi, True);
            Add (Mv.A, R1, Hi + 1, S.Length (R1));
            Ok := True;
         end;
      else
         Mv.A.Robot := R1;
         Mv.B.Robot := R2;
         if Variant mod 4 = 2 then
            --  Crossed, new arc T -> U: R1: 1..I then R2's J..1 reversed;
            --  R2: R1's I+1..end reversed then R2's J+1.. (tours through a
            --  common depot are cycles: this is 2-opt across two of them).
            if P.Frozen_Length (R2) > 0 or else I < P.Frozen_Length (R1) then
               return;
            end if;
            Add (Mv.A, R1, 1, I);
            Add (Mv.A, R2, 1, J, True);
            Add (Mv.B, R1, I + 1, S.Length (R1), True);
            Add (Mv.B, R2, J + 1, S.Length (R2));
         elsif Variant mod 4 = 3 then
            --  Crossed, new arc U -> T: R1: R2's end..J reversed then R1's
            --  I..; R2: 1..J-1 then R1's 1..I-1 reversed.
            if P.Frozen_Length (R1) > 0 or else J - 1 < P.Frozen_Length (R2) then
               return;
            end if;
            Add (Mv.A, R2, J, S.Length (R2), True);
            Add (Mv.A, R1, I, S.Length (R1));
            Add (Mv.B, R2, 1, J - 1);
            Add (Mv.B, R1, 1, I - 1, True);
         elsif Variant mod 2 = 0 then
            --  R1: 1..I then R2's J..; R2: 1..J-1 then R1's I+1..
            if J - 1 < P.Frozen_Length (R2) then
               return;
            end if;
            Add (Mv.A, R1, 1, I);
            Add (Mv.A, R2, J, S.Length (R2));
            Add (Mv.B, R2, 1, J - 1);
            Add (Mv.B, R1, I + 1, S.Length (R1));
         else
            --  R2: 1..J then R1's I..; R1: 1..I-1 then R2's J+1..
            if J < P.Frozen_Length (R2) then
               return;
            end if;
            Add (Mv.A, R1, 1, I - 1);
            Add (Mv.A, R2, J + 1, S.Length (R2));
            Add (Mv.B, R2, 1, J);
            Add (Mv.B, R1, I, S.Length (R1));
         end if;
         Ok := True;
      end if;
   end Two_Opt;

   procedure Or_3opt
     (P : Problem; S : State; T, U : Positive; V_Index : Positive; Variant : Natural;
      Mv : in out Move; Ok : out Boolean)
   is
      R  : constant Positive := S.Owner (T);
      A  : constant Positive := S.Position (T);
      B, C : Natural;
      Pivot, V : Natural;
   begin
      Ok := False;
      if S.Owner (U) /= R or else S.Position (U) < A + 2
        or else A < P.Frozen_Length (R)
      then
         return;
      end if;
      B := S.Position (U) - 1;
      Pivot := S.Task_At (R, (if Variant mod 2 = 0 then A + 1 else B));
      V := S.Near (Pivot, V_Index);
      if V = 0 or else S.Owner (V) /= R or else S.Position (V) <= B then
         return;
      end if;
      C := S.Position (V);
      Clear (Mv);
      Mv.A.Robot := R;
      Add (Mv.A, R, 1, A);
      Add (Mv.A, R, B + 1, C);
      Add (Mv.A, R, A + 1, B, Reversed => Variant mod 2 = 1);
      Add (Mv.A, R, C + 1, S.Length (R));
      Ok := True;
   end Or_3opt;

   procedure Cross_Exchange
     (P : Problem; S : State; T, U : Positive; L1, L2 : Natural;
      Mv : in out Move; Ok : out Boolean)
   is
      R1 : constant Positive := S.Owner (T);
      I  : constant Positive := S.Position (T);
      R2 : constant Positive := S.Owner (U);
      J  : constant Positive := S.Position (U);
      E1, E2 : Natural;
   begin
      Ok := False;
      if R1 = R2 or else J < P.Frozen_Length (R2) then
         return;
      end if;
      E1 := Natural'Min (I + L1 - 1, S.Length (R1));
      E2 := Natural'Min (J + L2, S.Length (R2));
      Clear (Mv);
      Mv.A.Robot := R1;
      Add (Mv.A, R1, 1, I - 1);
      Add (Mv.A, R2, J + 1, E2);
      Add (Mv.A, R1, E1 + 1, S.Length (R1));
      Mv.B.Robot := R2;
      Add (Mv.B, R2, 1, J);
      Add (Mv.B, R1, I, E1);
      Add (Mv.B, R2, E2 + 1, S.Length (R2));
      Ok := True;
   end Cross_Exchange;

   procedure Swap (S : State; T, U : Positive; Mv : in out Move; Ok : out Boolean) is
      R1 : constant Positive := S.Owner (T);
      R2 : constant Positive := S.Owner (U);
      I  : Positive := S.Position (T);
      J  : Positive := S.Position (U);
   begin
      Ok := False;
      if T = U then
         return;
      end if;
      Clear (Mv);
      if R1 = R2 then
         if J < I then
            declare
               X : constant Positive := I;
            begin
               I := J;
               J := X;
            end;
         end if;
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R1, J, J);
         Add (Mv.A, R1, I + 1, J - 1);
         Add (Mv.A, R1, I, I);
         Add (Mv.A, R1, J + 1, S.Length (R1));
      else
         Mv.A.Robot := R1;
         Add (Mv.A, R1, 1, I - 1);
         Add (Mv.A, R2, J, J);
         Add (Mv.A, R1, I + 1, S.Length (R1));
         Mv.B.Robot := R2;
         Add (Mv.B, R2, 1, J - 1);
         Add (Mv.B, R1, I, I);
         Add (Mv.B, R2, J + 1, S.Length (R2));
      end if;
      Ok := True;
   end Swap;

   procedure Random_Insert (P : Problem; S : State; G : in out Generator; T : Positive;
                            Other : Boolean; Mv : in out Move; Ok : out Boolean) is
      R1 : constant Positive := S.Owner (T);
      R2 : Positive;
      Q  : Natural;
   begin
      Ok := False;
      if Other then
         if S.Robots = 1 then
            return;
         end if;
         R2 := 1 + Random.Below (G, S.Robots - 1);
         if R2 >= R1 then
            R2 := R2 + 1;
         end if;
      else
         R2 := (if Random.Below (G, 2) = 0 then R1 else 1 + Random.Below (G, S.Robots));
      end if;
      Q := Random_Robot_Position (P, S, G, R2);
      if R2 = R1 and then (Q = S.Position (T) or else Q + 1 = S.Position (T)) then
         return;
      end if;
      Relocate (S, Mv, R1, S.Position (T), S.Position (T), R2, Q, False, Ok);
   end Random_Insert;

end Sancta.Allocation.Annealers.Neighbourhoods;
