with AUnit.Assertions;        use AUnit.Assertions;
with Interfaces;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Branch_And_Cut.Separation;
with Sancta.Allocation.Exact;
with Sancta.Allocation.Local_Search;
with Sancta.Allocation.Random;
with Sancta.Allocation.TSPLIB;
with Sancta.Geometry;
with Suite_Support; use Suite_Support;

package body Sancta.Allocation.Branch_And_Cut.Tests is

   use type Interfaces.Unsigned_64;

   type Shape is (Closed_Tour, Asymmetric_Tour, Open_Tour, Shared_Depot, Open_Starts);
   --  One robot: a closed symmetric tour, an asymmetric one, an open one;
   --  several robots (MinSum): closed tours from one depot, open tours
   --  from their own starts.

   function Instance (S : Shape; Tasks, Robots : Positive; Seed : Interfaces.Unsigned_64)
     return Problem_Access
   is
      G : Random.Generator := Random.Seeded (Seed);
      Places : constant Positive := Tasks + Robots;
      P : constant Problem_Access := Create (Places, Tasks, Robots);
      Points : constant Point_Array (1 .. Places) :=
        [for I in 1 .. Places => (Sancta.Geometry.Real (Random.Below (G, 500)),
                                  Sancta.Geometry.Real (Random.Below (G, 500)))];
   begin
      Set_Euclidean (P.all, Points, 1.0);
      if S = Asymmetric_Tour then
         for A in 1 .. Places loop
            for B in 1 .. Places loop
               if A /= B then
                  Set_Distance (P.all, A, B, Distance (P.all, A, B) + Cost (Random.Below (G, 200)));
               end if;
            end loop;
         end loop;
         Update_Symmetry (P.all);
      end if;
      for T in 1 .. Tasks loop
         Set_Task (P.all, T, Robots + T);
      end loop;
      for R in 1 .. Robots loop
         Set_Robot (P.all, R, (if S = Open_Starts then R else 1),
                    Closed => S not in Open_Tour | Open_Starts);
      end loop;
      return P;
   end Instance;

   function Solved (P : Problem; Limit : Duration := 60.0) return Result is
      Start : Assignment := Annealers.Greedy_Start (P, Min_Sum, 3);
      Search : Local_Search.Statistics;
   begin
      if Local_Search.Applies (P) then
         --  A good first tour, as sancta plan has from its anneal.
         Local_Search.Improve (P, Start, (Time_Limit => 0.5, others => <>), Search);
      end if;
      return R : Result (P.Robots, P.Tasks) do
         Solve (P, Start, R, (Time_Limit => Limit, others => <>));
      end return;
   end Solved;

   procedure Equals_Held_Karp (Unused : in out Fixture) is
   begin
      for S in Shape loop
         for Seed in Interfaces.Unsigned_64 range 1 .. 4 loop
            for Min_Tasks in 0 .. (if S in Shared_Depot | Open_Starts then 1 else 0) loop
               declare
                  Robots : constant Positive :=
                    (if S in Shared_Depot | Open_Starts then 2 + Natural (Seed mod 2) else 1);
                  P : constant Problem_Access := Instance (S, 9, Robots, Seed);
                  Name : constant String := S'Image & " seed" & Seed'Image
                    & " min" & Min_Tasks'Image;
               begin
                  P.Min_Tasks := Min_Tasks;
                  Assert (Supports (P.all) = "", Name & ": " & Supports (P.all));
                  declare
                     R : constant Result := Solved (P.all);
                     Optimum : constant Cost :=
                       Evaluate (P.all, Exact.Solve (P.all, Min_Sum), Min_Sum).Sum;
                     Found : constant Evaluation := Evaluate (P.all, R.Best, Min_Sum);
                  begin
                     Assert (Validate (P.all, R.Best) = "",
                             Name & ": " & Validate (P.all, R.Best));
                     Assert (R.Proven and then R.Lower = R.Upper, Name & ": not proven");
                     Assert (Found.Sum = R.Upper, Name & ": reported" & R.Upper'Image
                             & ", evaluated" & Found.Sum'Image);
                     Assert (R.Upper = Optimum, Name & ":" & R.Upper'Image
                             & " /= Held-Karp" & Optimum'Image);
                  end;
               end;
            end loop;
         end loop;
      end loop;
   end Equals_Held_Karp;

   procedure Proves_TSPLIB (Unused : in out Fixture) is
      procedure Check (File : String; Optimum : Cost) is
         P : constant Problem_Access :=
           TSPLIB.To_MTSP (TSPLIB.Read ("share/tsplib/" & File).all, Robots => 1);
         R : constant Result := Solved (P.all);
      begin
         Assert (R.Proven, File & ": no proof (lower bound" & R.Lower'Image & ")");
         Assert (R.Upper = Optimum, File & ":" & R.Upper'Image & " /=" & Optimum'Image);
         Assert (Evaluate (P.all, R.Best, Min_Sum).Sum = Optimum, File & ": tour cost");
      end Check;
   begin
      Check ("eil51.tsp", 426);
      Check ("kroA100.tsp", 21_282);
      Check ("br17.atsp", 39);
   end Proves_TSPLIB;

   procedure Refuses (Unused : in out Fixture) is
      P : constant Problem_Access := Instance (Shared_Depot, 6, 2, 5);
   begin
      Set_Robot (P.all, 2, 1, Closed => True, Multiplier => 2);
      Assert (Supports (P.all) /= "", "different multipliers accepted");
      Set_Robot (P.all, 2, 1, Closed => False);
      Assert (Supports (P.all) /= "", "different ends accepted");
      Set_Robot (P.all, 2, 1, Closed => True);
      Assert (Supports (P.all) = "", Supports (P.all));
      Freeze (P.all, 1, [1 => 3]);
      Assert (Supports (P.all) /= "", "frozen prefix accepted");
   end Refuses;

   procedure Gap_At_Time_Limit (Unused : in out Fixture) is
      P : constant Problem_Access := Instance (Closed_Tour, 60, 1, 11);
      R : constant Result := Solved (P.all, Limit => 0.001);
   begin
      Assert (Validate (P.all, R.Best) = "", "tour not valid at the time limit");
      Assert (R.Lower <= R.Upper, "lower bound above the tour");
      Assert (R.Proven = (R.Lower = R.Upper), "proof flag");
      Assert (Evaluate (P.all, R.Best, Min_Sum).Sum = R.Upper, "reported cost");
   end Gap_At_Time_Limit;

   ---------------------------------------------------------------------------
   --  Separators on points of 8 nodes: every cut found is violated by the
   --  point and valid for every tour (all 2520 enumerated); the exact
   --  separators find a cut whenever brute force over every handle finds
   --  a violated subtour or blossom inequality.

   package Sep renames Separation;
   Small : constant := 8;
   type Point is array (1 .. Small, 1 .. Small) of Long_Float;
   type Order is array (1 .. Small) of Positive;

   function To_Support (X : Point) return Sep.Support is
      Count : Natural := 0;
      S : Sep.Support (1 .. Small * (Small - 1) / 2);
   begin
      for U in 1 .. Small loop
         for V in U + 1 .. Small loop
            if X (U, V) > 0.0 then
               Count := Count + 1;
               S (Count) := (U, V, X (U, V));
            end if;
         end loop;
      end loop;
      return S (1 .. Count);
   end To_Support;

   procedure Add (X : in out Point; U, V : Positive; Amount : Long_Float) is
   begin
      X (U, V) := X (U, V) + Amount;
      X (V, U) := X (V, U) + Amount;
   end Add;

   function Shuffled (G : in out Random.Generator) return Order is
      O : Order := [for I in 1 .. Small => I];
   begin
      for I in reverse 2 .. Small loop
         declare
            J : constant Positive := 1 + Random.Below (G, I);
            T : constant Positive := O (I);
         begin
            O (I) := O (J);
            O (J) := T;
         end;
      end loop;
      return O;
   end Shuffled;

   --  A half-integral point: two odd cycles of edges at 1/2 (3 + 3 or
   --  3 + 5 nodes, the rest free), their nodes paired at random by paths
   --  of edges at 1 through the free nodes (drawn again until no edge is
   --  above 1).
   function Half_Integral_Draw (G : in out Random.Generator) return Point;

   function Half_Integral (G : in out Random.Generator) return Point is
   begin
      loop
         declare
            X : constant Point := Half_Integral_Draw (G);
         begin
            if (for all U in 1 .. Small => (for all V in 1 .. Small => X (U, V) <= 1.0)) then
               return X;
            end if;
         end;
      end loop;
   end Half_Integral;

   function Half_Integral_Draw (G : in out Random.Generator) return Point is
      O : constant Order := Shuffled (G);
      X : Point := [others => [others => 0.0]];
      Second : constant Positive := (if Random.Below (G, 2) = 0 then 3 else 5);
      Ends : Order := O;
      Cycle_Nodes : constant Positive := 3 + Second;
      Free_Next : Positive := Cycle_Nodes + 1;
   begin
      for I in 1 .. 3 loop
         Add (X, O (I), O (if I = 3 then 1 else I + 1), 0.5);
      end loop;
      for I in 1 .. Second loop
         Add (X, O (3 + I), O (if I = Second then 4 else 3 + I + 1), 0.5);
      end loop;
      --  Pair the cycle nodes at random.
      for I in reverse 2 .. Cycle_Nodes loop
         declare
            J : constant Positive := 1 + Random.Below (G, I);
            T : constant Positive := Ends (I);
         begin
            Ends (I) := Ends (J);
            Ends (J) := T;
         end;
      end loop;
      for K in 1 .. Cycle_Nodes / 2 loop
         declare
            Here : Positive := Ends (2 * K - 1);
         begin
            while Free_Next <= Small and then Random.Below (G, 2) = 0 loop
               Add (X, Here, O (Free_Next), 1.0);
               Here := O (Free_Next);
               Free_Next := Free_Next + 1;
            end loop;
            if K = Cycle_Nodes / 2 then
               while Free_Next <= Small loop
                  Add (X, Here, O (Free_Next), 1.0);
                  Here := O (Free_Next);
                  Free_Next := Free_Next + 1;
               end loop;
            end if;
            Add (X, Here, Ends (2 * K), 1.0);
         end;
      end loop;
      return X;
   end Half_Integral_Draw;

   function Tour_Point (O : Order) return Point is
      X : Point := [others => [others => 0.0]];
   begin
      for I in 1 .. Small loop
         Add (X, O (I), O (if I = Small then 1 else I + 1), 1.0);
      end loop;
      return X;
   end Tour_Point;

   function Mix (A, B : Point; Share : Long_Float) return Point is
     ([for U in 1 .. Small =>
         [for V in 1 .. Small => Share * A (U, V) + (1.0 - Share) * B (U, V)]]);

   --  Calls Check for every tour of 1 .. Small (node 1 first).
   procedure For_Each_Tour (Check : not null access procedure (T : Point)) is
      O : Order := [for I in 1 .. Small => I];
      procedure Permute (K : Positive) is
      begin
         if K = Small then
            if O (2) < O (Small) then   --  each cycle once
               Check (Tour_Point (O));
            end if;
            return;
         end if;
         for I in K .. Small loop
            declare
               T : Positive := O (K);
            begin
               O (K) := O (I);
               O (I) := T;
               Permute (K + 1);
               T := O (K);
               O (K) := O (I);
               O (I) := T;
            end;
         end loop;
      end Permute;
   begin
      Permute (2);
   end For_Each_Tour;

   procedure Check_Cuts (Name : String; X : Point; Found : Sep.Cut_Lists.Vector) is
      S : constant Sep.Support := To_Support (X);
      procedure Valid_For (T : Point) is
         Tour : constant Sep.Support := To_Support (T);
      begin
         for C of Found loop
            Assert (Sep.Left_Side (C, Tour) >= Sep.Right_Side (C) - 1.0E-9,
                    Name & ": a " & C.Kind'Image & " cut cuts off a tour");
         end loop;
      end Valid_For;
   begin
      for C of Found loop
         Assert (Sep.Violation (C, S) > Sep.Tolerance,
                 Name & ": a " & C.Kind'Image & " cut is not violated");
         if C.Kind = Comb then
            Assert (C.Teeth >= 3 and then C.Teeth mod 2 = 1, Name & ": comb teeth");
         elsif C.Kind = Blossom then
            Assert (C.Tooth_Edges >= 3 and then C.Tooth_Edges mod 2 = 1, Name & ": blossom teeth");
         end if;
      end loop;
      For_Each_Tour (Valid_For'Access);
   end Check_Cuts;

   --  Brute force over every handle: the least x (delta (H)) and the least
   --  blossom left side minus right side (teeth chosen best, parity fixed).
   procedure Brute_Force (X : Point; Least_Cut, Least_Blossom : out Long_Float) is
   begin
      Least_Cut := Long_Float'Last;
      Least_Blossom := Long_Float'Last;
      for Mask in 1 .. 2 ** Small - 2 loop
         declare
            In_H : constant array (1 .. Small) of Boolean :=
              [for V in 1 .. Small => (Mask / 2 ** (V - 1)) mod 2 = 1];
            Crossing, Best_Side : Long_Float := 0.0;
            Teeth : Natural := 0;
            Flip : Long_Float := Long_Float'Last;
         begin
            for U in 1 .. Small loop
               for V in U + 1 .. Small loop
                  if In_H (U) /= In_H (V) then
                     Crossing := Crossing + X (U, V);
                     --  Tooth when 1 - x < x.
                     if 1.0 - X (U, V) < X (U, V) then
                        Teeth := Teeth + 1;
                        Best_Side := Best_Side + 1.0 - X (U, V);
                     else
                        Best_Side := Best_Side + X (U, V);
                     end if;
                     Flip := Long_Float'Min (Flip, abs (1.0 - 2.0 * X (U, V)));
                  end if;
               end loop;
            end loop;
            if Teeth mod 2 = 0 then
               Best_Side := Best_Side + Flip;
            end if;
            Least_Cut := Long_Float'Min (Least_Cut, Crossing - 2.0);
            Least_Blossom := Long_Float'Min (Least_Blossom, Best_Side - 1.0);
         end;
      end loop;
   end Brute_Force;

   procedure Separators_On_Small_Points (Unused : in out Fixture) is
      G : Random.Generator := Random.Seeded (17);
      Exact_Found, Subtour_Found, Heuristic_Found, Combs_Found : Natural := 0;
   begin
      for Trial in 1 .. 60 loop
         declare
            Base_Point : constant Point := Half_Integral (G);
            X : constant Point :=
              (case Trial mod 3 is
                  when 0 => Base_Point,
                  when 1 => Mix (Base_Point, Tour_Point (Shuffled (G)), 0.7),
                  when others => Mix (Tour_Point (Shuffled (G)), Tour_Point (Shuffled (G)), 0.5));
            --  The last kind is in the tour polytope: nothing may be found.
            S : constant Sep.Support := To_Support (X);
            Name : constant String := "point" & Trial'Image;
            Least_Cut, Least_Blossom : Long_Float;
            Subtours : constant Sep.Cut_Lists.Vector := Sep.Subtours (Small, S);
            Heuristic : constant Sep.Cut_Lists.Vector := Sep.Blossoms_Heuristic (Small, S);
            Exact_Blossoms : constant Sep.Cut_Lists.Vector := Sep.Blossoms_Exact (Small, S);
            Found_Combs : constant Sep.Cut_Lists.Vector := Sep.Combs (Small, S);
         begin
            for U in 1 .. Small loop
               declare
                  Degree : Long_Float := 0.0;
               begin
                  for V in 1 .. Small loop
                     Degree := Degree + X (U, V);
                  end loop;
                  Assert (abs (Degree - 2.0) < 1.0E-9, Name & ": degree (test generator)");
               end;
            end loop;
            Check_Cuts (Name & " subtours", X, Subtours);
            Check_Cuts (Name & " odd components", X, Heuristic);
            Check_Cuts (Name & " Padberg-Rao", X, Exact_Blossoms);
            Check_Cuts (Name & " combs", X, Found_Combs);
            Brute_Force (X, Least_Cut, Least_Blossom);
            Assert ((Least_Cut < -Sep.Tolerance) = not Subtours.Is_Empty,
                    Name & ": subtour separation is not exact (least cut - 2 ="
                    & Least_Cut'Image & ")");
            if Least_Blossom < -Sep.Tolerance then
               Assert (not Exact_Blossoms.Is_Empty,
                       Name & ": Padberg-Rao missed a violated blossom ("
                       & Least_Blossom'Image & ")");
            end if;
            if Trial mod 3 = 2 then
               Assert (Subtours.Is_Empty and then Heuristic.Is_Empty
                       and then Exact_Blossoms.Is_Empty and then Found_Combs.Is_Empty,
                       Name & ": a cut found for a mix of tours");
            end if;
            Subtour_Found := Subtour_Found + Natural (Subtours.Length);
            Exact_Found := Exact_Found + Natural (Exact_Blossoms.Length);
            Heuristic_Found := Heuristic_Found + Natural (Heuristic.Length);
            Combs_Found := Combs_Found + Natural (Found_Combs.Length);
         end;
      end loop;
      --  The points are meant to exercise every separator.
      Assert (Subtour_Found > 0 and then Exact_Found > 0 and then Heuristic_Found > 0
              and then Combs_Found > 0,
              "separators found too little:" & Subtour_Found'Image & Heuristic_Found'Image
              & Exact_Found'Image & Combs_Found'Image);
   end Separators_On_Small_Points;

   --  The prism point (two triangles at 1/2 matched by three edges at 1)
   --  satisfies every subtour cut and violates the blossom on a triangle.
   procedure Blossom_Of_The_Prism (Unused : in out Fixture) is
      X : Point := [others => [others => 0.0]];
   begin
      Add (X, 1, 2, 0.5);
      Add (X, 2, 3, 0.5);
      Add (X, 3, 1, 0.5);
      Add (X, 4, 5, 0.5);
      Add (X, 5, 6, 0.5);
      Add (X, 6, 4, 0.5);
      Add (X, 1, 4, 1.0);
      Add (X, 2, 7, 1.0);
      Add (X, 7, 8, 1.0);
      Add (X, 8, 5, 1.0);
      Add (X, 3, 6, 1.0);
      declare
         S : constant Sep.Support := To_Support (X);
      begin
         Assert (Sep.Subtours (Small, S).Is_Empty, "prism: a subtour cut found");
         for Which in 1 .. 3 loop
            declare
               Found : constant Sep.Cut_Lists.Vector :=
                 (case Which is
                     when 1 => Sep.Blossoms_Heuristic (Small, S),
                     when 2 => Sep.Blossoms_Exact (Small, S),
                     when others => Sep.Combs (Small, S));
            begin
               Assert (not Found.Is_Empty, "prism: no blossom found by separator" & Which'Image);
               Check_Cuts ("prism", X, Found);
               Assert ((for some C of Found => abs (Sep.Violation (C, S) - 1.0) < 1.0E-9),
                       "prism: no cut violated by 1 (separator" & Which'Image & ")");
            end;
         end loop;
      end;
   end Blossom_Of_The_Prism;

   --  Every technique switched off in turn still proves the optimum.
   procedure Settings_Prove_The_Same (Unused : in out Fixture) is
      P : constant Problem_Access :=
        TSPLIB.To_MTSP (TSPLIB.Read ("share/tsplib/kroA100.tsp").all, Robots => 1);
      Start : Assignment := Annealers.Greedy_Start (P.all, Min_Sum, 3);
      Search : Local_Search.Statistics;
      Variants : constant array (1 .. 9) of Settings :=
        [Default_Settings,
         (Heuristic_Blossoms => False, others => <>),
         (Exact_Blossoms => False, others => <>),
         (Heuristic_Blossoms => False, Exact_Blossoms => False, Combs => False, others => <>),
         (Pricing => False, others => <>),
         (Node_Fixing => False, others => <>),
         (Strong_Branching => 0, others => <>),
         (Best_Bound => False, Purge => False, others => <>),
         (CPU_Time_Limit => True, others => <>)];
   begin
      Local_Search.Improve (P.all, Start, (Time_Limit => 0.5, others => <>), Search);
      for I in Variants'Range loop
         declare
            R : Result (P.Robots, P.Tasks);
         begin
            Solve (P.all, Start, R, (Variants (I) with delta Time_Limit => 120.0));
            Assert (R.Proven and then R.Upper = 21_282,
                    "variant" & I'Image & ": proven " & R.Proven'Image & R.Upper'Image);
            Assert (R.Root_Bound <= 21_282.0 + 1.0E-6, "variant" & I'Image & ": root bound");
            Assert (R.Cuts >= R.By_Class (Subtour), "variant" & I'Image & ": cut counts");
            Assert (Evaluate (P.all, R.Best, Min_Sum).Sum = 21_282, "variant" & I'Image);
         end;
      end loop;
   end Settings_Prove_The_Same;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
      procedure Add (Name : String; Proc : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("branch and cut: " & Name, Proc));
      end Add;
   begin
      Add ("equals Held-Karp: TSP, ATSP, open, multi-robot MinSum", Equals_Held_Karp'Access);
      Add ("proves eil51, kroA100 and br17 optimal", Proves_TSPLIB'Access);
      Add ("refuses what it cannot transform", Refuses'Access);
      Add ("best tour and lower bound at a time limit", Gap_At_Time_Limit'Access);
      Add ("separators: cuts violated, valid for all tours, exact ones exact",
           Separators_On_Small_Points'Access);
      Add ("separators: the prism point's blossom", Blossom_Of_The_Prism'Access);
      Add ("every technique off in turn still proves kroA100", Settings_Prove_The_Same'Access);
      return Result;
   end Suite;

end Sancta.Allocation.Branch_And_Cut.Tests;
