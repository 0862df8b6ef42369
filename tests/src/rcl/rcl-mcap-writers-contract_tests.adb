with Ada.Assertions;
with Ada.Directories;
with AUnit.Assertions; use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;

package body RCL.MCAP.Writers.Contract_Tests is

   type Stamps is array (Positive range <>) of Time_Stamp;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;
   package Caller is new AUnit.Test_Caller (Fixture);

   function Getpid return Integer with Import, Convention => C, External_Name => "getpid";

   procedure Invariant (Unused : in out Fixture) is
      Pid  : constant String := Integer'Image (Getpid);
      Path : constant String :=
        "/tmp/rclada_mcap_contract_" & Pid (Pid'First + 1 .. Pid'Last) & ".mcap";
      Data : constant Byte_Array (1 .. 8) := [0, 1, 0, 0, 3, 0, 0, 0];
      W    : Writer;
      S    : Schema_Id;
      C    : Channel_Id;
   begin
      W.Create (Path, Compression => None);
      S := W.Add_Schema ("std_msgs/msg/String", "ros2msg", "string data");
      C := W.Add_Channel ("/chatter", S, "cdr", String_Maps.Empty_Map);
      for T of Stamps'[30, 10, 20] loop
         W.Write (C, T, Data);
      end loop;
      Assert (W.Chunk_Start = 10 and then W.Chunk_End = 30 and then W.First_Time = 10
              and then W.Last_Time = 30 and then W.Chunk_Messages = 3,
              "the time ranges follow the messages (out of order too)");

      W.Chunk_End := 5;  --  the open chunk would claim to end before it starts
      begin
         C := W.Add_Channel ("/other", S, "cdr", String_Maps.Empty_Map);
         Assert (False, "a chunk ending before it starts went unnoticed");
      exception
         when Ada.Assertions.Assertion_Error =>
            null;
      end;
      W.Chunk_End := 30;
      W.Close;
      Ada.Directories.Delete_File (Path);
   end Invariant;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("mcap: writer invariant (time ranges of chunk and file)",
                                      Invariant'Access));
      return Result;
   end Suite;

end RCL.MCAP.Writers.Contract_Tests;
