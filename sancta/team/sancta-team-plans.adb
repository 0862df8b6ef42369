with Ada.Strings.Fixed;
with Sancta.Allocation;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Assignments;
with Sancta.Allocation.Problems;
with Sancta.Runtime.Values;

package body Sancta.Team.Plans is

   use Sancta.Geometry;
   use type Ada.Containers.Count_Type;

   package String_Vectors is new Ada.Containers.Vectors (Positive, Unbounded_String);

   function Split (Text : String; Sep : Character) return String_Vectors.Vector is
      Result : String_Vectors.Vector;
      First  : Positive := Text'First;
   begin
      for I in Text'Range loop
         if Text (I) = Sep then
            Result.Append (To_Unbounded_String (Text (First .. I - 1)));
            First := I + 1;
         end if;
      end loop;
      Result.Append (To_Unbounded_String (Text (First .. Text'Last)));
      return Result;
   end Split;

   function Img (X : Long_Float) return String renames Runtime.Values.Real_Image;

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   --  Snapshots -----------------------------------------------------------------

   function Encode (S : Snapshot) return String is
      Result : Unbounded_String := To_Unbounded_String (Trim (S.Generation) & "|");
   begin
      for R in 1 .. Natural (S.Robots.Length) loop
         Append (Result, (if R > 1 then ";" else "") & S.Robots (R).Id & "@"
                 & Img (Long_Float (S.Robots (R).Where.X)) & ","
                 & Img (Long_Float (S.Robots (R).Where.Y)));
      end loop;
      Append (Result, "|");
      for T in 1 .. Natural (S.Tasks.Length) loop
         Append (Result, (if T > 1 then "," else "") & S.Tasks (T).Id);
      end loop;
      return To_String (Result);
   end Encode;

   procedure Decode
     (Text     : String;
      S        : out Snapshot;
      Task_Ids : out Missions.Task_Vectors.Vector)
   is
      Parts : constant String_Vectors.Vector := Split (Text, '|');
   begin
      S := (others => <>);
      Task_Ids.Clear;
      if Parts.Length /= 3 then
         raise Format_Error with "snapshot """ & Text & """: expected 3 parts";
      end if;
      S.Generation := Natural'Value (To_String (Parts (1)));
      if Parts (2) /= "" then
         for R of Split (To_String (Parts (2)), ';') loop
            declare
               Item  : constant String := To_String (R);
               At_I  : constant Natural := Ada.Strings.Fixed.Index (Item, "@");
               Comma : constant Natural := Ada.Strings.Fixed.Index (Item, ",");
            begin
               if At_I = 0 or else Comma < At_I then
                  raise Format_Error with "snapshot robot """ & Item & """";
               end if;
               S.Robots.Append
                 (Robot_Position'(To_Unbounded_String (Item (Item'First .. At_I - 1)),
                   Point'(Real'Value (Item (At_I + 1 .. Comma - 1)),
                    Real'Value (Item (Comma + 1 .. Item'Last)))));
            end;
         end loop;
      end if;
      if Parts (3) /= "" then
         for T of Split (To_String (Parts (3)), ',') loop
            Task_Ids.Append (Missions.Mission_Task'(Id => T, others => <>));
         end loop;
      end if;
   exception
      when Constraint_Error =>
         raise Format_Error with "snapshot """ & Text & """: malformed number";
   end Decode;

   function Task_Of (S : Snapshot; Id : String) return Missions.Mission_Task is
   begin
      for T of S.Tasks loop
         if T.Id = Id then
            return T;
         end if;
      end loop;
      raise Format_Error with "task " & Id & " is not in round" & S.Generation'Image;
   end Task_Of;

   --  Plans ---------------------------------------------------------------------

   function Task_Index (S : Snapshot; Id : Unbounded_String) return Natural is
   begin
      for T in 1 .. Natural (S.Tasks.Length) loop
         if S.Tasks (T).Id = Id then
            return T;
         end if;
      end loop;
      return 0;
   end Task_Index;
   --  The position of task Id in S.Tasks; 0 when S does not hold it.

   function Robot_Index (S : Snapshot; Id : Unbounded_String) return Natural is
   begin
      for R in 1 .. Natural (S.Robots.Length) loop
         if S.Robots (R).Id = Id then
            return R;
         end if;
      end loop;
      return 0;
   end Robot_Index;
   --  The position of robot Id in S.Robots; 0 when S does not hold it.


   function Encode (P : Plan; S : Snapshot) return String is
      Result : Unbounded_String := To_Unbounded_String
        (Trim (P.Generation) & "|" & Img (P.Value) & "|" & To_String (P.Proposer) & "|");
   begin
      for R in 1 .. Natural (S.Robots.Length) loop
         Append (Result, (if R > 1 then ";" else "") & S.Robots (R).Id & "=");
         if R <= Natural (P.Tours.Length) then
            for K in 1 .. Natural (P.Tours (R).Length) loop
               Append (Result, (if K > 1 then "," else "") & P.Tours (R) (K).Task_Id & "."
                       & Trim (P.Tours (R) (K).Choice));
            end loop;
         end if;
      end loop;
      return To_String (Result);
   end Encode;

   function Decode_Tour (Item : String; Robot_Id : String) return Step_Vectors.Vector is
      Eq   : constant Natural := Ada.Strings.Fixed.Index (Item, "=");
      Tour : Step_Vectors.Vector;
   begin
      if Eq = 0 or else Item (Item'First .. Eq - 1) /= Robot_Id then
         raise Format_Error with "plan tour """ & Item & """ does not fit the round";
      end if;
      if Eq < Item'Last then
         for St of Split (Item (Eq + 1 .. Item'Last), ',') loop
            declare
               X   : constant String := To_String (St);
               Dot : constant Natural :=
                 Ada.Strings.Fixed.Index (X, ".", Going => Ada.Strings.Backward);
            begin
               if Dot = 0 then
                  raise Format_Error with "plan step """ & X & """";
               end if;
               Tour.Append (Step'(To_Unbounded_String (X (X'First .. Dot - 1)),
                             Positive'Value (X (Dot + 1 .. X'Last))));
            end;
         end loop;
      end if;
      return Tour;
   end Decode_Tour;
   --  "ROBOT=TASK.CHOICE,..." (an encoded tour), the tour of robot Robot_Id.

   function Decode (Text : String; S : Snapshot) return Plan is
      Parts  : constant String_Vectors.Vector := Split (Text, '|');
      Result : Plan;
   begin
      if Parts.Length /= 4 then
         raise Format_Error with "plan """ & Text & """: expected 4 parts";
      end if;
      Result.Generation := Natural'Value (To_String (Parts (1)));
      Result.Value := Long_Float'Value (To_String (Parts (2)));
      Result.Proposer := Parts (3);
      declare
         Tours : constant String_Vectors.Vector := Split (To_String (Parts (4)), ';');
      begin
         if Natural (Tours.Length) /= Natural (S.Robots.Length) then
            raise Format_Error with "plan """ & Text & """: not one tour per robot";
         end if;
         for R in 1 .. Natural (Tours.Length) loop
            Result.Tours.Append (Decode_Tour (To_String (Tours (R)), To_String (S.Robots (R).Id)));
         end loop;
      end;
      return Result;
   exception
      when Constraint_Error =>
         raise Format_Error with "plan """ & Text & """: malformed number";
   end Decode;

   --  Costs -------------------------------------------------------------------

   function Tour_Cost
     (S     : Snapshot;
      Start : Point;
      Tour  : Step_Vectors.Vector;
      Leg   : access function (From, To : Point) return Long_Float := null)
      return Long_Float
   is
      Here   : Point := Start;
      Result : Long_Float := 0.0;
   begin
      for St of Tour loop
         declare
            T    : constant Missions.Mission_Task := Task_Of (S, To_String (St.Task_Id));
            To_P : constant Point := Missions.Entry_Point (T, St.Choice);
         begin
            Result := Result
              + (if Leg = null then Long_Float (Distance (Here, To_P)) else Leg (Here, To_P))
              + Missions.Inner_Length (T, St.Choice);
            Here := Missions.Exit_Point (T, St.Choice);
         end;
      end loop;
      return Result;
   end Tour_Cost;

   function Combined_Tour_Costs
     (S       : Snapshot;
      P       : Plan;
      Leg     : access function (From, To : Point) return Long_Float;
      Combine : not null access function (Left, Right : Long_Float) return Long_Float)
      return Long_Float
   is
      --  The robots' tour costs folded with Combine from 0.0, robot by robot.
      Result : Long_Float := 0.0;
   begin
      for R in 1 .. Natural (P.Tours.Length) loop
         Result := Combine (Result, Tour_Cost (S, S.Robots (R).Where, P.Tours (R), Leg));
      end loop;
      return Result;
   end Combined_Tour_Costs;

   function Larger (Left, Right : Long_Float) return Long_Float is (Long_Float'Max (Left, Right));
   function Sum (Left, Right : Long_Float) return Long_Float is (Left + Right);

   function Makespan
     (S   : Snapshot;
      P   : Plan;
      Leg : access function (From, To : Point) return Long_Float := null) return Long_Float
   is (Combined_Tour_Costs (S, P, Leg, Larger'Access));

   function Total
     (S   : Snapshot;
      P   : Plan;
      Leg : access function (From, To : Point) return Long_Float := null) return Long_Float
   is (Combined_Tour_Costs (S, P, Leg, Sum'Access));

   function Evaluate
     (S   : Snapshot;
      P   : in out Plan;
      Leg : access function (From, To : Point) return Long_Float := null) return Long_Float is
   begin
      P.Value := Makespan (S, P, Leg) + Total (S, P, Leg) / 1000.0;
      return P.Value;
   end Evaluate;

   procedure Best_Insertion
     (S         : Snapshot;
      Start     : Point;
      Tour      : Step_Vectors.Vector;
      Task_Id   : String;
      New_Cost  : out Long_Float;
      Position  : out Positive;
      Choice    : out Positive;
      Leg       : access function (From, To : Point) return Long_Float := null)
   is
      function Distance (A, B : Point) return Real is
        (if Leg = null then Sancta.Geometry.Distance (A, B) else Real (Leg (A, B)));
      T     : constant Missions.Mission_Task := Task_Of (S, Task_Id);
      L     : constant Natural := Natural (Tour.Length);
      Entry_P, Exit_P : array (0 .. L) of Point;
      Base  : Long_Float := 0.0;
   begin
      --  Exit point of step K (0: the start) and entry point of step K.
      Exit_P (0) := Start;
      Entry_P (0) := Start;
      for K in 1 .. L loop
         declare
            U : constant Missions.Mission_Task := Task_Of (S, To_String (Tour (K).Task_Id));
         begin
            Entry_P (K) := Missions.Entry_Point (U, Tour (K).Choice);
            Exit_P (K) := Missions.Exit_Point (U, Tour (K).Choice);
            Base := Base + Long_Float (Distance (Exit_P (K - 1), Entry_P (K)))
              + Missions.Inner_Length (U, Tour (K).Choice);
         end;
      end loop;
      New_Cost := Long_Float'Last;
      Position := 1;
      Choice := 1;
      for Pos in 1 .. L + 1 loop
         for C in 1 .. Missions.Alternatives (T) loop
            declare
               In_P  : constant Point := Missions.Entry_Point (T, C);
               Out_P : constant Point := Missions.Exit_Point (T, C);
               Delta_Cost : Long_Float :=
                 Long_Float (Distance (Exit_P (Pos - 1), In_P)) + Missions.Inner_Length (T, C);
            begin
               if Pos <= L then
                  Delta_Cost := Delta_Cost + Long_Float (Distance (Out_P, Entry_P (Pos)))
                    - Long_Float (Distance (Exit_P (Pos - 1), Entry_P (Pos)));
               end if;
               if Base + Delta_Cost < New_Cost - 1.0E-9 then
                  New_Cost := Base + Delta_Cost;
                  Position := Pos;
                  Choice := C;
               end if;
            end;
         end loop;
      end loop;
   end Best_Insertion;

   function Greedy (S : Snapshot; Proposer : String) return Plan is
      Result : Plan := (Generation => S.Generation, Proposer => To_Unbounded_String (Proposer),
                        others => <>);
      Dummy  : Long_Float;
   begin
      for R in 1 .. Natural (S.Robots.Length) loop
         Result.Tours.Append (Step_Vectors.Empty_Vector);
      end loop;
      --  Each task in turn to the robot whose tour stays the shortest.
      for T of S.Tasks loop
         declare
            Best_R   : Positive := 1;
            Best     : Long_Float := Long_Float'Last;
            Best_Pos : Positive := 1;
            Best_C   : Positive := 1;
         begin
            for R in 1 .. Natural (S.Robots.Length) loop
               declare
                  Cost : Long_Float;
                  Pos, C : Positive;
               begin
                  Best_Insertion (S, S.Robots (R).Where, Result.Tours (R), To_String (T.Id),
                                  Cost, Pos, C);
                  if Cost < Best then
                     Best := Cost;
                     Best_R := R;
                     Best_Pos := Pos;
                     Best_C := C;
                  end if;
               end;
            end loop;
            Result.Tours (Best_R).Insert (Best_Pos, Step'(T.Id, Best_C));
         end;
      end loop;
      Dummy := Evaluate (S, Result);
      return Result;
   end Greedy;

   function Auction (S : Snapshot; Proposer : String) return Plan is
      Result : Plan := (Generation => S.Generation, Proposer => To_Unbounded_String (Proposer),
                        others => <>);
      Left   : array (1 .. Natural (S.Tasks.Length)) of Boolean := [others => True];
      Dummy  : Long_Float;
   begin
      for R in 1 .. Natural (S.Robots.Length) loop
         Result.Tours.Append (Step_Vectors.Empty_Vector);
      end loop;
      for Round in 1 .. Natural (S.Tasks.Length) loop
         declare
            Best_R, Best_T, Best_Pos, Best_C : Positive := 1;
            Best : Long_Float := Long_Float'Last;
         begin
            for R in 1 .. Natural (S.Robots.Length) loop
               for T in Left'Range loop
                  if Left (T) then
                     declare
                        Cost   : Long_Float;
                        Pos, C : Positive;
                     begin
                        Best_Insertion (S, S.Robots (R).Where, Result.Tours (R),
                                        To_String (S.Tasks (T).Id), Cost, Pos, C);
                        if Cost < Best then
                           Best := Cost;
                           Best_R := R;
                           Best_T := T;
                           Best_Pos := Pos;
                           Best_C := C;
                        end if;
                     end;
                  end if;
               end loop;
            end loop;
            Result.Tours (Best_R).Insert (Best_Pos, Step'(S.Tasks (Best_T).Id, Best_C));
            Left (Best_T) := False;
         end;
      end loop;
      Dummy := Evaluate (S, Result);
      return Result;
   end Auction;

   function Carried_Over
     (Previous_Round : Snapshot;
      Previous       : Plan;
      S              : Snapshot;
      Proposer       : String;
      Leg            : access function (From, To : Point) return Long_Float := null)
      return Plan
   is
      Result : Plan := (Generation => S.Generation,
                        Proposer   => To_Unbounded_String (Proposer),
                        others     => <>);
      Placed : array (1 .. Natural (S.Tasks.Length)) of Boolean := [others => False];

      Dummy : Long_Float;
   begin
      if S.Robots.Is_Empty or else Previous.Generation = 0
        or else Previous.Generation /= Previous_Round.Generation
        or else Natural (Previous.Tours.Length) /= Natural (Previous_Round.Robots.Length)
      then
         return (others => <>);
      end if;
      for Robot of S.Robots loop
         declare
            Old  : constant Natural := Robot_Index (Previous_Round, Robot.Id);
            Tour : Step_Vectors.Vector;
         begin
            if Old > 0 then
               for St of Previous.Tours (Old) loop
                  declare
                     T : constant Natural := Task_Index (S, St.Task_Id);
                  begin
                     if T > 0 and then not Placed (T)
                       and then St.Choice <= Missions.Alternatives (S.Tasks (T))
                     then
                        Placed (T) := True;
                        Tour.Append (St);
                     end if;
                  end;
               end loop;
            end if;
            Result.Tours.Append (Tour);
         end;
      end loop;
      for T in Placed'Range loop
         if not Placed (T) then
            declare
               Id        : constant String := To_String (S.Tasks (T).Id);
               Best_Cost : Long_Float := Long_Float'Last;
               Best_R    : Positive := 1;
               Best_Pos  : Positive := 1;
               Best_Ch   : Positive := 1;
               Cost      : Long_Float;
               Pos, Ch   : Positive;
            begin
               for R in 1 .. Natural (S.Robots.Length) loop
                  Best_Insertion (S, S.Robots (R).Where, Result.Tours (R), Id,
                                  Cost, Pos, Ch, Leg);
                  if Cost < Best_Cost then
                     Best_Cost := Cost;
                     Best_R := R;
                     Best_Pos := Pos;
                     Best_Ch := Ch;
                  end if;
               end loop;
               Result.Tours (Best_R).Insert (Best_Pos, Step'(S.Tasks (T).Id, Best_Ch));
               Placed (T) := True;
            end;
         end if;
      end loop;
      Dummy := Evaluate (S, Result, Leg);
      return Result;
   end Carried_Over;

   function Anneal
     (S          : Snapshot;
      Seed       : Interfaces.Unsigned_64;
      Budget     : Duration;
      Start_From : Plan;
      Proposer   : String;
      Iterations : Long_Long_Integer := 0;
      Leg        : access function (From, To : Point) return Long_Float := null)
      return Plan
   is
      function Distance (A, B : Point) return Real is
        (if Leg = null then Sancta.Geometry.Distance (A, B) else Real (Leg (A, B)));
      use Sancta.Allocation;
      use Sancta.Allocation.Problems;
      use Sancta.Allocation.Assignments;
      NR     : constant Positive := Positive (S.Robots.Length);
      NT     : constant Natural := Natural (S.Tasks.Length);
      Result : Plan := (Generation => S.Generation, Proposer => To_Unbounded_String (Proposer),
                        others => <>);
      Dummy  : Long_Float;
   begin
      if NT = 0 then
         for R in 1 .. NR loop
            Result.Tours.Append (Step_Vectors.Empty_Vector);
         end loop;
         Dummy := Evaluate (S, Result, Leg);
         return Result;
      end if;
      declare
         NA : Natural := 0;
      begin
         for T of S.Tasks loop
            NA := NA + Missions.Alternatives (T);
         end loop;
         declare
            NL     : constant Positive := NR + NA;
            P      : constant Problem_Access := Create (NL, NT, NR, NA);
            Entry_P, Exit_P : array (1 .. NL) of Point;
            Inner  : array (1 .. NL) of Long_Float := [others => 0.0];
            First  : array (1 .. NT) of Positive;
            L      : Positive := NR;
         begin
            for R in 1 .. NR loop
               Entry_P (R) := S.Robots (R).Where;
               Exit_P (R) := S.Robots (R).Where;
            end loop;
            for T in 1 .. NT loop
               First (T) := L + 1;
               for C in 1 .. Missions.Alternatives (S.Tasks (T)) loop
                  L := L + 1;
                  Entry_P (L) := Missions.Entry_Point (S.Tasks (T), C);
                  Exit_P (L) := Missions.Exit_Point (S.Tasks (T), C);
                  Inner (L) := Missions.Inner_Length (S.Tasks (T), C);
               end loop;
            end loop;
            for A in 1 .. NL loop
               for B in 1 .. NL loop
                  if B > NR and then A /= B then
                     Set_Distance
                       (P.all, A, B,
                        Cost (Long_Float'Rounding
                          (100.0 * (Long_Float (Distance (Exit_P (A), Entry_P (B)))
                                    + Inner (B)))));
                  end if;
               end loop;
            end loop;
            Update_Symmetry (P.all);
            for R in 1 .. NR loop
               Set_Robot (P.all, R, R, Closed => False);
            end loop;
            for T in 1 .. NT loop
               declare
                  Locs : Location_Array (1 .. Missions.Alternatives (S.Tasks (T)));
               begin
                  for K in Locs'Range loop
                     Locs (K) := First (T) + K - 1;
                  end loop;
                  Set_Task_Alternatives (P.all, T, Locs);
               end;
            end loop;
            declare
               Best  : Assignment := Empty (P.all);
               Opts  : Annealers.Options :=
                 (Criterion => Min_Tim, Seed => Seed, Time_Limit => Budget,
                  Iterations => Iterations, Report_Every => 1000.0, others => <>);
               Stats : Annealers.Progress;
            begin
               if Natural (Start_From.Tours.Length) = NR then
                  declare
                     Seen : array (1 .. NT) of Boolean := [others => False];
                     Ok   : Boolean := True;
                  begin
                     for R in 1 .. NR loop
                        for St of Start_From.Tours (R) loop
                           declare
                              T : constant Natural := Task_Index (S, St.Task_Id);
                           begin
                              if T = 0 or else Seen (T)
                                or else St.Choice > Missions.Alternatives (S.Tasks (T))
                              then
                                 Ok := False;
                              else
                                 Seen (T) := True;
                                 Append (Best, R, T);
                                 Best.Choice (T) := St.Choice;
                              end if;
                           end;
                        end loop;
                     end loop;
                     Opts.Initial := Ok and then (for all X of Seen => X);
                     if not Opts.Initial then
                        Best := Empty (P.all);
                     end if;
                  end;
               end if;
               Annealers.Solve (P.all, Opts, Best, Stats);
               for R in 1 .. NR loop
                  declare
                     Tour : Step_Vectors.Vector;
                  begin
                     for K in 1 .. Best.Length (R) loop
                        Tour.Append (Step'(S.Tasks (Best.Tour (R, K)).Id,
                                      Best.Choice (Best.Tour (R, K))));
                     end loop;
                     Result.Tours.Append (Tour);
                  end;
               end loop;
            end;
         end;
      end;
      Dummy := Evaluate (S, Result, Leg);
      return Result;
   end Anneal;

end Sancta.Team.Plans;
