with Ada.Streams;
with AUnit.Assertions; use AUnit.Assertions;
with RCL.DDS;
with RCL.Process_Context;
with Suite_Support; use Suite_Support;

package body RCL.QoS.Tests is

   procedure Profiles (Unused : in out Fixture) is
   begin
      Assert (Default.History = Keep_Last and then Default.Depth = 10
              and then Default.Reliability = Reliable and then Default.Durability = Volatile,
              "default: KEEP_LAST 10, RELIABLE, VOLATILE");
      Assert (Sensor_Data.Depth = 5 and then Sensor_Data.Reliability = Best_Effort,
              "sensor_data: KEEP_LAST 5, BEST_EFFORT");
      Assert (Parameters.Depth = 1000 and then Parameter_Events.Depth = 1000, "parameters");
      Assert (Rosout.Depth = 1000 and then Rosout.Durability = Transient_Local
              and then Rosout.Lifespan = 10.0, "rosout: 1000, transient local, lifespan 10 s");
      Assert (Clock.Depth = 1 and then Clock.Reliability = Best_Effort, "clock");
      Assert (Services_Default = Default, "services_default");
      Assert (System_Default.Reliability = Middleware_Default, "system_default");
      Assert (Image (Default) = "KEEP_LAST 10, RELIABLE, VOLATILE", Image (Default));
      Assert (Image ((Default with delta Deadline => 0.5)) =
                "KEEP_LAST 10, RELIABLE, VOLATILE, deadline 0.500000000",
              Image ((Default with delta Deadline => 0.5)));
   end Profiles;

   procedure Custom_On_DDS (Unused : in out Fixture) is
      Custom : constant Profile :=
        (History => Keep_All, Depth => 1, Reliability => Reliable,
         Durability => Transient_Local, Deadline => 5.0, Lifespan => 30.0,
         Liveliness => Manual_By_Topic, Lease => 10.0, Destination_Order => By_Source_Timestamp);
      W    : RCL.DDS.Writer;
      R    : RCL.DDS.Reader;
      Late : RCL.DDS.Reader;
      Info : RCL.DDS.Sample_Info;
      use type Ada.Streams.Stream_Element_Array;
      Data : constant Ada.Streams.Stream_Element_Array := [0, 1, 0, 0, 7, 0, 0, 0];
   begin
      RCL.DDS.Create (W, RCL.Process_Context.Participant.all, "rt/qos_custom", "t::msg::dds_::T_",
                      Custom);
      RCL.DDS.Create (R, RCL.Process_Context.Participant.all, "rt/qos_custom", "t::msg::dds_::T_",
                      Custom);
      for I in 1 .. 200 loop
         exit when RCL.DDS.Matched_Readers (W) > 0;
         delay 0.01;
      end loop;
      Assert (RCL.DDS.Matched_Readers (W) = 1, "custom QoS endpoints match");
      RCL.DDS.Write (W, Data);
      --  A transient-local reader created after the write still gets it.
      RCL.DDS.Create (Late, RCL.Process_Context.Participant.all,
                      "rt/qos_custom", "t::msg::dds_::T_",
                      Custom);
      for I in 1 .. 200 loop
         declare
            Got : constant Ada.Streams.Stream_Element_Array := RCL.DDS.Take (Late, Info);
         begin
            if Got'Length > 0 then
               Assert (Got = Data, "late joiner gets the historical sample");
               return;
            end if;
         end;
         delay 0.01;
      end loop;
      Assert (False, "transient local: nothing for a late joiner");
   end Custom_On_DDS;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("qos: ROS 2 profiles", Profiles'Access));
      Result.Add_Test (Caller.Create ("qos: custom settings on DDS", Custom_On_DDS'Access));
      return Result;
   end Suite;

end RCL.QoS.Tests;
