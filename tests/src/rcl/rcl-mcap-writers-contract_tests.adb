with Ada.Directories;
with AUnit.Assertions; use AUnit.Assertions;
with Contract_Test_Support;

package body RCL.MCAP.Writers.Contract_Tests is

   type Stamps is array (Positive range <>) of Time_Stamp;

   function Getpid return Integer with Import, Convention => C, External_Name => "getpid";

   procedure Invariant is
      Pid  : constant String := Integer'Image (Getpid);
      Path : constant String :=
        "/tmp/rclada_mcap_contract_" & Pid (Pid'First + 1 .. Pid'Last) & ".mcap";
      Data : constant Byte_Array (1 .. 8) := [0, 1, 0, 0, 3, 0, 0, 0];
      W    : Writer;
      S    : Schema_Id;
      C    : Channel_Id;

      procedure Add_Channel_With_Chunk_Ending_Before_Start is
      begin
         W.Chunk_End := 5;  --  the open chunk would claim to end before it starts
         C := W.Add_Channel ("/other", S, "cdr", String_Maps.Empty_Map);
      end Add_Channel_With_Chunk_Ending_Before_Start;

      procedure Chunk_Ending_Before_Start is new
        Contract_Test_Support.Assert_Caught (Add_Channel_With_Chunk_Ending_Before_Start);
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

      Chunk_Ending_Before_Start ("a chunk ending before it starts");
      W.Chunk_End := 30;
      W.Close;
      Ada.Directories.Delete_File (Path);
   end Invariant;

   package Invariant_Test is new Contract_Test_Support.One_Test_Suite
     ("mcap: writer invariant (time ranges of chunk and file)", Invariant);

   function Suite return AUnit.Test_Suites.Access_Test_Suite renames Invariant_Test.Suite;

end RCL.MCAP.Writers.Contract_Tests;
