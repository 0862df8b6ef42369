with AUnit.Assertions; use AUnit.Assertions;
with Suite_Support; use Suite_Support;

package body RCL.Logging.Tests is

   procedure Formats (Unused : in out Fixture) is
      Stamp : constant Long_Long_Integer := 1_700_000_000_012_345_678;
   begin
      Assert (Format ("[{severity}] [{time}] [{name}]: {message}", Info, "talker", "Hi",
                      Stamp) = "[INFO] [1700000000.012345678] [talker]: Hi",
              "default ROS 2 format: "
              & Format ("[{severity}] [{time}] [{name}]: {message}", Info, "talker", "Hi",
                        Stamp));
      Assert (Format ("{severity}|{time_as_nanoseconds}|{file_name}{line_number}|{x}", Warn,
                      "n", "m", Stamp) = "WARN|1700000000012345678||{x}",
              "other tokens");
      Assert (Format ("{message", Error, "n", "m", 0) = "{message", "unterminated token");
      Assert (ROS_Level (Fatal) = 50 and then ROS_Level (Debug) = 10, "rosout levels");
   end Formats;

   Captured : Natural := 0;
   procedure Capture (Level : Severity; Logger, Message : String; Stamp_Ns : Long_Long_Integer)
   is
      pragma Unreferenced (Logger, Stamp_Ns);
   begin
      if Level = Warn and then Message = "captured" then
         Captured := Captured + 1;
      end if;
   end Capture;

   procedure Levels (Unused : in out Fixture) is
      Old : constant Severity := Level;
   begin
      Set_Sink (Capture'Access);
      Set_Level (Error);
      Warn ("captured");
      Assert (Captured = 0, "below the level: dropped");
      Set_Level (Debug);
      Warn ("captured", Logger => "test");
      Assert (Captured = 1, "at or above the level: sent to the sink");
      Set_Sink (null);
      Set_Level (Old);
   end Levels;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("logging: console format", Formats'Access));
      Result.Add_Test (Caller.Create ("logging: levels and sink", Levels'Access));
      return Result;
   end Suite;

end RCL.Logging.Tests;
