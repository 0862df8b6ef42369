package body Sancta.Allocation.Annealers.Moves is

   procedure Clear (Mv : in out Move) is
   begin
      Mv.A.Robot := 0;
      Mv.A.Count := 0;
      Mv.B.Robot := 0;
      Mv.B.Count := 0;
      Mv.Or_Node := 0;
   end Clear;

   function No_Move return Move is
   begin
      return M : Move do
         Clear (M);
      end return;
   end No_Move;

   procedure Add (T : in out Tour_Plan; Robot : Positive; First, Last : Natural;
                  Reversed : Boolean := False) is
   begin
      if First <= Last then
         T.Count := T.Count + 1;
         T.Segments (T.Count) := (Kind => Span, Robot => Robot, First => First,
                                  Last => Last, Reversed => Reversed, Task_Id => 0,
                                  Location => 0);
      end if;
   end Add;

   procedure Add_Single (T : in out Tour_Plan; Task_Id, Location : Positive) is
   begin
      T.Count := T.Count + 1;
      T.Segments (T.Count) := (Kind => Single, Task_Id => Task_Id, Location => Location,
                               Robot => 1, First => 1, Last => 0, Reversed => False);
   end Add_Single;

   function Make_Weights (P : Problem; C : Criterion; Scale_Sum : Cost) return Weights is
   begin
      if C.Sum_Weight = 0.0 and then C.Ave_Weight = 0.0 and then P.Robots > 1 then
         --  Pure makespan: plateaus everywhere; a tiny total-cost term
         --  breaks ties without ever trading a unit of makespan.
         return (C, 0.5 / Long_Float (Cost'Max (1, Scale_Sum) * Cost (P.Robots)), 0.0);
      end if;
      return (C, 0.0, 0.0);
   end Make_Weights;

   --  The cost (length, sum of completion times, both with the multiplier
   --  and Infinity per infeasible task) and task count of a planned tour;
   --  the sum of completion times only With_Completion (else 0: two prefix
   --  sum loads per span saved where the criterion has no mean).
   procedure Evaluate_Tour
     (P : Problem; S : State; T : Tour_Plan; With_Completion : Boolean;
      Length, Completion : out Cost; Count : out Natural)
   is
      R    : constant Positive := T.Robot;
      Here : Natural := P.Start (R);
      Time : Cost := 0;
      Sum  : Cost := 0;
      Bad  : Natural := 0;
      M    : constant Cost := Cost (P.Multiplier (R));
   begin
      Count := 0;
      for K in 1 .. T.Count loop
         declare
            G : Segment renames T.Segments (K);
         begin
            if G.Kind = Single then
               Time := Time + Arc (P, S, R, Here, G.Location);
               Sum := Sum + Time;
               Here := G.Location;
               Count := Count + 1;
               if not P.Can_Do (R, G.Task_Id) then
                  Bad := Bad + 1;
               end if;
            else
               declare
                  RS : constant Positive := G.Robot;
                  N  : constant Cost := Cost (G.Last - G.First + 1);
               begin
                  if RS /= R and then S.Compact.Row = null
                    and then (Has_Own_Costs (P, R) or else Has_Own_Costs (P, RS))
                  then
                     --  Another robot's segment in a different metric: arc
                     --  by arc in R's own costs (its prefix sums are RS's).
                     --  Never with a compact matrix (no robot has costs of
                     --  its own then): that test first, the cheaper.
                     for K2 in G.First .. G.Last loop
                        declare
                           I : constant Positive :=
                             (if G.Reversed then G.Last - (K2 - G.First) else K2);
                        begin
                           Time := Time + Arc (P, S, R, Here, S.Location_At (RS, I));
                           Sum := Sum + Time;
                           Here := S.Location_At (RS, I);
                        end;
                     end loop;
                  elsif not G.Reversed then
                     Time := Time + Arc (P, S, R, Here, S.Location_At (RS, G.First));
                     if With_Completion then
                        Sum := Sum + N * (Time - S.Forward_Cost (RS, G.First))
                          + S.Forward_Sum (RS, G.Last) - S.Forward_Sum (RS, G.First - 1);
                     end if;
                     Time := Time + S.Forward_Cost (RS, G.Last) - S.Forward_Cost (RS, G.First);
                     Here := S.Location_At (RS, G.Last);
                  else
                     Time := Time + Arc (P, S, R, Here, S.Location_At (RS, G.Last));
                     if With_Completion then
                        Sum := Sum + N * (Time + S.Backward_Cost (RS, G.Last))
                          - (S.Backward_Sum (RS, G.Last) - S.Backward_Sum (RS, G.First - 1));
                     end if;
                     Time := Time + S.Backward_Cost (RS, G.Last)
                       - S.Backward_Cost (RS, G.First);
                     Here := S.Location_At (RS, G.First);
                  end if;
                  Count := Count + Natural (N);
                  if not P.All_Feasible then
                     for I in G.First .. G.Last loop
                        if not P.Can_Do (R, S.Task_At (RS, I)) then
                           Bad := Bad + 1;
                        end if;
                     end loop;
                  end if;
               end;
            end if;
         end;
      end loop;
      Time := Time + Arc (P, S, R, Here, P.Finish (R));
      Length := M * Time + Cost (Bad) * Infinity;
      Completion := (if With_Completion then M * Sum + Cost (Bad) * Infinity else 0);
   end Evaluate_Tour;

   procedure Evaluate_Move
     (P : Problem; S : State; W : Weights; Mv : in out Move; Valid : out Boolean)
   is
      A : constant Natural := Mv.A.Robot;
      --  Positive but for a switch subtree move (no tour plans).
      B : constant Natural := Mv.B.Robot;
      Max, Sum, Completion : Cost;
      With_Completion : constant Boolean := W.C.Ave_Weight /= 0.0;
      --  Value reads the sum of completion times only then.
   begin
      if Mv.Or_Node /= 0 then
         --  Switch subtree: evaluated when proposed (Plan_Trees).
         Valid := True;
         return;
      end if;
      Mv.New_Active := S.Active_Tasks;
      Mv.Completion_Known := With_Completion;
      Evaluate_Tour (P, S, Mv.A, With_Completion, Mv.New_A_Cost, Mv.New_A_Completion,
                     Mv.New_A_Length);
      Valid := Mv.New_A_Length >= P.Min_Tasks or else Mv.New_A_Length >= S.Length (A);
      Sum := S.Total_Cost - S.Robot_Cost (A) + Mv.New_A_Cost;
      Completion := (if With_Completion
                     then S.Total_Completion - S.Robot_Completion (A) + Mv.New_A_Completion
                     else 0);
      Max := (if W.C.Max_Weight = 0.0 then 0
              else Cost'Max (Max_Except (S, A, B), Mv.New_A_Cost));
      --  The makespan only when the criterion uses it (saves O (log R)).
      if B /= 0 then
         Evaluate_Tour (P, S, Mv.B, With_Completion, Mv.New_B_Cost, Mv.New_B_Completion,
                        Mv.New_B_Length);
         Valid := Valid and then
           (Mv.New_B_Length >= P.Min_Tasks or else Mv.New_B_Length >= S.Length (B));
         Sum := Sum - S.Robot_Cost (B) + Mv.New_B_Cost;
         if With_Completion then
            Completion := Completion - S.Robot_Completion (B) + Mv.New_B_Completion;
         end if;
         if W.C.Max_Weight /= 0.0 then
            Max := Cost'Max (Max, Mv.New_B_Cost);
         end if;
      end if;
      Mv.New_Max := Max;
      Mv.New_Sum := Sum;
      Mv.New_Completion := Completion;
      if W.Square /= 0.0 then
         Mv.New_Square := S.Total_Square - Square_Of (S, S.Robot_Cost (A))
           + Square_Of (S, Mv.New_A_Cost);
         if B /= 0 then
            Mv.New_Square := Mv.New_Square - Square_Of (S, S.Robot_Cost (B))
              + Square_Of (S, Mv.New_B_Cost);
         end if;
      end if;
      Mv.Value := Objective (W, Max, Sum, Completion, S.Active_Tasks, Mv.New_Square);
   end Evaluate_Move;

   --  Writes a planned tour into Buffer (tasks); Keep is the length of the
   --  prefix it shares with the current tour of T.Robot.
   procedure Render (S : State; T : Tour_Plan; Buffer : in out Count_Array;
                     Length : out Natural; Keep : out Natural) is
      First_Segment : Positive := 1;
   begin
      Length := 0;
      Keep := 0;
      if T.Count >= 1 and then T.Segments (1).Kind = Span
        and then T.Segments (1).Robot = T.Robot
        and then not T.Segments (1).Reversed and then T.Segments (1).First = 1
      then
         Keep := T.Segments (1).Last;
         Length := Keep;
         First_Segment := 2;
      end if;
      for K in First_Segment .. T.Count loop
         declare
            G : Segment renames T.Segments (K);
         begin
            if G.Kind = Single then
               Length := Length + 1;
               Buffer (Length) := G.Task_Id;
            elsif not G.Reversed then
               for I in G.First .. G.Last loop
                  Length := Length + 1;
                  Buffer (Length) := S.Task_At (G.Robot, I);
               end loop;
            else
               for I in reverse G.First .. G.Last loop
                  Length := Length + 1;
                  Buffer (Length) := S.Task_At (G.Robot, I);
               end loop;
            end if;
         end;
      end loop;
   end Render;

   --  Rebuild of the robot of T, whose new tour (in S.Task_At, S.Length)
   --  keeps the first Keep positions of its old tour of Old_Length tasks:
   --  when T ends with the end of that old tour (a span neither reversed
   --  nor part of the kept prefix), Rebuild offsets its arcs' old sums.
   procedure Rebuild_Planned
     (P : Problem; S : in out State; T : Tour_Plan; Keep, Old_Length : Natural)
   is
      R : constant Positive := T.Robot;
   begin
      if T.Count >= 1 then
         declare
            Z : Segment renames T.Segments (T.Count);
            --  Z.First now at the position Anchor.
            Anchor : constant Integer := S.Length (R) - (Z.Last - Z.First);
         begin
            if Z.Kind = Span and then Z.Robot = R and then not Z.Reversed
              and then Z.Last = Old_Length and then Anchor > Keep
            then
               Rebuild (P, S, R, Keep + 1, Same_From => Anchor + 1,
                        Shift => Z.First - Anchor);
               return;
            end if;
         end;
      end if;
      Rebuild (P, S, R, Keep + 1);
   end Rebuild_Planned;

   procedure Apply (P : Problem; S : in out State; Mv : Move) is
      Length_A, Length_B, Keep_A, Keep_B : Natural := 0;
      Buffer_A, Buffer_B : Count_Array (1 .. S.Positions);
      A : constant Positive := Mv.A.Robot;
      B : constant Natural := Mv.B.Robot;
      Old_Length_A : constant Natural := S.Length (A);
      Old_Length_B : constant Natural := (if B /= 0 then S.Length (B) else 0);
   begin
      Render (S, Mv.A, Buffer_A, Length_A, Keep_A);
      if B /= 0 then
         Render (S, Mv.B, Buffer_B, Length_B, Keep_B);
      end if;
      if Mv.Switch_Task /= 0 then
         S.Choice (Mv.Switch_Task) := Mv.Switch_To;
      end if;
      for I in Keep_A + 1 .. Length_A loop
         S.Task_At (A, I) := Buffer_A (I);
      end loop;
      S.Length (A) := Length_A;
      if B /= 0 then
         for I in Keep_B + 1 .. Length_B loop
            S.Task_At (B, I) := Buffer_B (I);
         end loop;
         S.Length (B) := Length_B;
      end if;
      Rebuild_Planned (P, S, Mv.A, Keep_A, Old_Length_A);
      if B /= 0 then
         Rebuild_Planned (P, S, Mv.B, Keep_B, Old_Length_B);
      end if;
   end Apply;

   procedure Verify (P : Problem; S : State; Mv : Move; Predicted : Boolean) is
      Sum, Completion, Max : Cost := 0;
      Square : Long_Float := 0.0;
      Seen : Count_Array (1 .. S.Tasks) := [others => 0];

      procedure Fail (What : String) with No_Return;
      procedure Fail (What : String) is
      begin
         raise Program_Error with "annealer check failed: " & What;
      end Fail;

      --  Robot R's locations and prefix sums (Rebuild's caches, which the
      --  moves' predictions read) against its tasks and the distances.
      procedure Check_Caches (R : Positive) is
         N : constant Natural := S.Length (R);
         Forward, Backward, Forward_Sum, Backward_Sum : Cost := 0;
      begin
         if S.Location_At (R, 0) /= P.Start (R) then
            Fail ("robot" & R'Image & " start location");
         end if;
         for I in 1 .. N + 1 loop
            declare
               L : constant Natural :=
                 (if I <= N then Location_Of (P, S.Task_At (R, I), S.Choice (S.Task_At (R, I)))
                  else P.Finish (R));
               Before : constant Natural := S.Location_At (R, I - 1);
            begin
               Forward := Forward + Robot_Distance (P, R, Before, L);
               Backward := Backward + Robot_Distance (P, R, L, Before);
               if I <= N then
                  Forward_Sum := Forward_Sum + Forward;
                  Backward_Sum := Backward_Sum + Backward;
               end if;
               if S.Location_At (R, I) /= L or else S.Forward_Cost (R, I) /= Forward
                 or else S.Backward_Cost (R, I) /= Backward
                 or else (I <= N and then (S.Forward_Sum (R, I) /= Forward_Sum
                                           or else S.Backward_Sum (R, I) /= Backward_Sum))
               then
                  Fail ("caches of robot" & R'Image & " at position" & I'Image);
               end if;
            end;
         end loop;
      end Check_Caches;
   begin
      for R in 1 .. S.Robots loop
         declare
            RC, RCm : Cost;
         begin
            if S.Length (R) < P.Frozen_Length (R) then
               Fail ("robot" & R'Image & " lost frozen tasks");
            end if;
            for I in 1 .. S.Length (R) loop
               declare
                  T : constant Positive := S.Task_At (R, I);
               begin
                  if I <= P.Frozen_Length (R) and then P.Frozen (R, I) /= T then
                     Fail ("frozen prefix of robot" & R'Image & " changed");
                  end if;
                  Seen (T) := Seen (T) + 1;
                  if S.Owner (T) /= R or else S.Position (T) /= I then
                     Fail ("position index of task" & T'Image);
                  end if;
               end;
            end loop;
            Check_Caches (R);
            Cost_From_Scratch (P, R, S.Task_At, S.Length (R), S.Choice, RC, RCm);
            if RC /= S.Robot_Cost (R) or else RCm /= S.Robot_Completion (R) then
               Fail ("robot" & R'Image & " cost" & S.Robot_Cost (R)'Image & " /"
                     & S.Robot_Completion (R)'Image
                     & " recomputed" & RC'Image & " /" & RCm'Image);
            end if;
            if Predicted then
               if R = Mv.A.Robot
                 and then (RC /= Mv.New_A_Cost
                           or else (Mv.Completion_Known and then RCm /= Mv.New_A_Completion))
               then
                  Fail ("move prediction for robot" & R'Image & ":" & Mv.New_A_Cost'Image
                        & " /" & Mv.New_A_Completion'Image & " actual" & RC'Image & " /"
                        & RCm'Image);
               end if;
               if R = Mv.B.Robot
                 and then (RC /= Mv.New_B_Cost
                           or else (Mv.Completion_Known and then RCm /= Mv.New_B_Completion))
               then
                  Fail ("move prediction for robot" & R'Image & ":" & Mv.New_B_Cost'Image
                        & " actual" & RC'Image);
               end if;
            end if;
            Sum := Sum + RC;
            Square := Square + Square_Of (S, RC);
            Completion := Completion + RCm;
            Max := Cost'Max (Max, RC);
         end;
      end loop;
      for T in 1 .. S.Tasks loop
         if S.Active (T) /= Is_Active (P, S.Selection, T) then
            Fail ("active flag of task" & T'Image);
         elsif Seen (T) /= (if S.Active (T) then 1 else 0) then
            Fail ("task" & T'Image & " (active: " & S.Active (T)'Image & ") appears"
                  & Seen (T)'Image & " times");
         elsif not S.Active (T) and then S.Owner (T) /= 0 then
            Fail ("inactive task" & T'Image & " has an owner");
         end if;
      end loop;
      if Active_Count (P, S.Selection) /= S.Active_Tasks then
         Fail ("active count" & S.Active_Tasks'Image);
      end if;
      if Predicted and then Mv.Or_Node /= 0
        and then (Mv.New_Sum /= S.Total_Cost or else Mv.New_Completion /= S.Total_Completion
                  or else Mv.New_Max /= Current_Max (S)
                  or else Mv.New_Active /= S.Active_Tasks)
      then
         Fail ("switch subtree prediction: sum" & Mv.New_Sum'Image & " actual"
               & S.Total_Cost'Image & ", completion" & Mv.New_Completion'Image & " actual"
               & S.Total_Completion'Image & ", max" & Mv.New_Max'Image & " actual"
               & Current_Max (S)'Image);
      end if;
      if Sum /= S.Total_Cost or else Completion /= S.Total_Completion
        or else Max /= Current_Max (S)
      then
         Fail ("totals: sum" & S.Total_Cost'Image & " vs" & Sum'Image & ", max"
               & Current_Max (S)'Image & " vs" & Max'Image);
      end if;
      if abs (Square - S.Total_Square) > 1.0E-7 * Long_Float'Max (1.0, Square) then
         Fail ("sum of squared costs" & S.Total_Square'Image & " vs" & Square'Image);
      end if;
      for A in 1 .. S.Robots loop
         --  Max_Except (its cached top three) for robot A alone and with the next robot.
         declare
            B : constant Positive := A mod S.Robots + 1;
            Alone, Pair : Cost := 0;
         begin
            for R in 1 .. S.Robots loop
               if R /= A then
                  Alone := Cost'Max (Alone, S.Robot_Cost (R));
                  if R /= B then
                     Pair := Cost'Max (Pair, S.Robot_Cost (R));
                  end if;
               end if;
            end loop;
            if Max_Except (S, A, 0) /= Alone or else Max_Except (S, A, B) /= Pair then
               Fail ("largest cost but robot" & A'Image & ":" & Max_Except (S, A, 0)'Image
                     & " vs" & Alone'Image);
            end if;
         end;
      end loop;
   end Verify;

end Sancta.Allocation.Annealers.Moves;
