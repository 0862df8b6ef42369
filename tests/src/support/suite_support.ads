--  What the unit-test suites share: a fixture without set-up of its own
--  (each test is a procedure of one Fixture parameter, registered with
--  Caller) and a check on texts such as error messages.
--
--     procedure Rejects_Empty_Name (Unused : in out Fixture) is ...
--     Result.Add_Test (Caller.Create ("rcl: empty name", Rejects_Empty_Name'Access));
--     Assert (Contains (Message, ":1:5:"), Message);
--  Also whole files as bytes (Read_All, Write_All).
with Ada.Streams;
with Ada.Strings.Fixed;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package Suite_Support is

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   package Caller is new AUnit.Test_Caller (Fixture);

   function Contains (Text, Part : String) return Boolean is
     (Ada.Strings.Fixed.Index (Text, Part) > 0);
   --  Whether Part occurs in Text.

   function Read_All (Path : String) return Ada.Streams.Stream_Element_Array;
   --  The file's bytes, indexed from 1.

   procedure Write_All (Path : String; Data : Ada.Streams.Stream_Element_Array);
   --  The file created (or overwritten) with Data.

end Suite_Support;
