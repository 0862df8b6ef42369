with AUnit.Assertions;   use AUnit.Assertions;
with Contract_Test_Support;

package body Sancta.Robot.GPS_Fusion.Contract_Tests is

   procedure Invariant is
      F : Filter;

      procedure Predict_With_Negative_Variance is
      begin
         F.Variance := -1.0;
         F.Predict ((21.0, 0.0, 0.0));
      end Predict_With_Negative_Variance;

      procedure Correct_With_Gain_Above_One is
      begin
         F.Initialize ((0.0, 0.0, 0.0));
         F.Gain := 1.5;
         F.Correct ((Stamp => 1.0, Position => (0.0, 0.0), Std_Dev => 1.0));
      end Correct_With_Gain_Above_One;

      procedure Negative_Variance is new
        Contract_Test_Support.Assert_Caught (Predict_With_Negative_Variance);
      procedure Gain_Above_One is new
        Contract_Test_Support.Assert_Caught (Correct_With_Gain_Above_One);
   begin
      F.Initialize ((0.0, 0.0, 0.0), Variance => 0.5);
      for I in 1 .. 20 loop
         F.Predict ((Real (I), 0.0, 0.0));
         F.Correct ((Stamp => Real (I), Position => (Real (I) + 0.1, 0.05), Std_Dev => 0.3));
      end loop;
      Assert (Variance (F) in 0.0 .. 0.5, "variance kept in 0 .. its start:" & Variance (F)'Image);
      F.Correct ((Stamp => 21.0, Position => (20.0, 0.0), Std_Dev => 0.0));
      Assert (Variance (F) = 0.0, "an exact fix leaves no variance");

      Negative_Variance ("a negative variance");
      Gain_Above_One ("a heading gain above 1");
   end Invariant;

   package Invariant_Test is new Contract_Test_Support.One_Test_Suite
     ("robot: GPS fusion invariant (variance >= 0, gain a share)", Invariant);

   function Suite return AUnit.Test_Suites.Access_Test_Suite renames Invariant_Test.Suite;

end Sancta.Robot.GPS_Fusion.Contract_Tests;
