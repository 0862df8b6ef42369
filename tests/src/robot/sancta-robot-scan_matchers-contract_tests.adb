with Ada.Assertions;
with AUnit.Assertions;   use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body Sancta.Robot.Scan_Matchers.Contract_Tests is

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   package Caller is new AUnit.Test_Caller (Fixture);

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

   procedure Invariant (Unused : in out Fixture) is
      P : constant Scan_Points := To_Points (Scan);
      C : Corrector;
   begin
      Assert (Is_Indexed (P) and then Natural (P.Points.Length) = 5
              and then P.By_Beam (2) = 0 and then P.By_Beam (3) = 2,
              "8 beams, 5 valid points, indexed by beam");
      C.Update ((others => <>), (0.0, 0.0, 0.0), Scan);
      C.Update ((others => <>), (0.0, 0.0, 0.0), Scan);
      Assert (Is_Indexed (C.Key), "the corrector's key scan is indexed");

      C.Key.By_Beam (3) := 1;  --  Beam 3's entry now names beam 1's point.
      begin
         C.Update ((others => <>), (0.0, 0.0, 0.0), Scan);
         Assert (False, "an index naming another beam's point went unnoticed");
      exception
         when Ada.Assertions.Assertion_Error =>
            null;
      end;
   end Invariant;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("robot: scan points invariant (index by beam)",
                                      Invariant'Access));
      return Result;
   end Suite;

end Sancta.Robot.Scan_Matchers.Contract_Tests;
