with AUnit.Assertions;   use AUnit.Assertions;
with Contract_Test_Support;

package body Sancta.Robot.Scan_Matchers.Contract_Tests is

   function Scan return Laser_Scan is
      S : Laser_Scan (8);
   begin
      S.Angle_Min := -0.4;
      S.Angle_Increment := 0.1;
      S.Angle_Max := 0.3;
      S.Range_Min := 0.1;
      S.Range_Max := 5.0;
      S.Ranges := [1.0, 5.0, 1.2, 1.3, 0.0, 1.5, 1.6, 5.0];
      --  Beams 2 and 8 hit nothing, beam 5 is below Range_Min.
      return S;
   end Scan;

   procedure Invariant is
      P : constant Scan_Points := To_Points (Scan);
      C : Corrector;

      procedure Update_With_Index_Naming_Another_Beam is
      begin
         C.Key.By_Beam (3) := 1;  --  Beam 3's entry now names beam 1's point.
         C.Update ((others => <>), (0.0, 0.0, 0.0), Scan);
      end Update_With_Index_Naming_Another_Beam;

      procedure Index_Naming_Another_Beam is new
        Contract_Test_Support.Assert_Caught (Update_With_Index_Naming_Another_Beam);
   begin
      Assert (Is_Indexed (P) and then Natural (P.Points.Length) = 5
              and then P.By_Beam (2) = 0 and then P.By_Beam (3) = 2,
              "8 beams, 5 valid points, indexed by beam");
      C.Update ((others => <>), (0.0, 0.0, 0.0), Scan);
      C.Update ((others => <>), (0.0, 0.0, 0.0), Scan);
      Assert (Is_Indexed (C.Key), "the corrector's key scan is indexed");

      Index_Naming_Another_Beam ("an index naming another beam's point");
   end Invariant;

   package Invariant_Test is new Contract_Test_Support.One_Test_Suite
     ("robot: scan points invariant (index by beam)", Invariant);

   function Suite return AUnit.Test_Suites.Access_Test_Suite renames Invariant_Test.Suite;

end Sancta.Robot.Scan_Matchers.Contract_Tests;
