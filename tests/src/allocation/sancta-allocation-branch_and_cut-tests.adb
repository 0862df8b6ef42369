with AUnit.Assertions;        use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;
with Interfaces;
with Sancta.Allocation.Annealers;
with Sancta.Allocation.Exact;
with Sancta.Allocation.Local_Search;
with Sancta.Allocation.Random;
with Sancta.Allocation.TSPLIB;
with Sancta.Geometry;

package body Sancta.Allocation.Branch_And_Cut.Tests is

   use type Interfaces.Unsigned_64;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;
   package Caller is new AUnit.Test_Caller (Fixture);

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
         Local_Search.Improve (P, Start, 0.5, 1, Search);
      end if;
      return R : Result (P.Robots, P.Tasks) do
         Solve (P, Start, Limit, R);
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
      return Result;
   end Suite;

end Sancta.Allocation.Branch_And_Cut.Tests;
