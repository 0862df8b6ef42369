with AUnit.Assertions;
with ROSIDL.Definitions;
with ROSIDL.Interfaces;
with ROSIDL.Parser;
with Suite_Support; use Suite_Support;

package body ROSIDL.Type_Hashes.Tests is

   use AUnit.Assertions;

   procedure Check (Full_Name, Expected_Hex : String) is
      Got : constant String := Hash (ROSIDL.Interfaces.Message (Full_Name));
   begin
      Assert (Got = Prefix & Expected_Hex, Full_Name & ": " & Got);
   end Check;

   procedure Published_Hashes (Unused : in out Fixture) is
   begin
      --  Values published by ROS 2 Jazzy (ros2 topic info -v, type
      --  description files): flat, nested, sequences, arrays, several
      --  referenced types.
      Check ("std_msgs/msg/String",
             "df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18");
      Check ("builtin_interfaces/msg/Time",
             "b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197");
      Check ("geometry_msgs/msg/Point",
             "6963084842a9b04494d6b2941d11444708d892da2f4b09843b9c43f42a7f6881");
      Check ("std_msgs/msg/Header",
             "f49fb3ae2cf070f793645ff749683ac6b06203e41c891e17701b1cb597ce6a01");
      Check ("std_msgs/msg/Float32MultiArray",
             "0599f6f85b4bfca379873a0b4375a0aca022156bd2d7021275d116ed1fa8bfe0");
      Check ("geometry_msgs/msg/Twist",
             "9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a");
      Check ("nav_msgs/msg/Odometry",
             "3cc97dc7fb7502f8714462c526d369e35b603cfc34d946e3f2eda2766dfec6e0");
      Check ("sensor_msgs/msg/Image",
             "d31d41a9a4c4bc8eae9be757b0beed306564f7526c88ea6a4588fb9582527d47");
      Check ("sensor_msgs/msg/Imu",
             "7d9a00ff131080897a5ec7e26e315954b8eae3353c3f995c55faf71574000b5b");
      Check ("sensor_msgs/msg/NavSatFix",
             "62223ab3fe210a15976021da7afddc9e200dc9ec75231c1b6a557fc598a65404");
      Check ("sensor_msgs/msg/PointCloud2",
             "9198cabf7da3796ae6fe19c4cb3bdd3525492988c70522628af5daa124bae2b5");
      Check ("rosgraph_msgs/msg/Clock",
             "692f7a66e93a3c83e71765d033b60349ba68023a8c689a79e48078bcb5c58564");
      Check ("action_msgs/msg/GoalStatusArray",
             "6c1684b00f177d37438febe6e709fc4e2b0d4248dca4854946f9ed8b30cda83e");
      Check ("unique_identifier_msgs/msg/UUID",
             "1b8e8aca958cbea28fe6ef60bf6c19b683c97a9ef60bb34752067d0f2f7ab437");
   end Published_Hashes;

   function Jazzy_Gids
     (Package_Name, Name : String; Where : ROSIDL.Definitions.Source_Position)
      return ROSIDL.Definitions.Message_Access is
     (if Package_Name = "rmw_dds_common" and then Name = "Gid"
      then ROSIDL.Parser.Parse_Message ("rmw_dds_common", "Gid", "char[16] data")
      else ROSIDL.Parser.Search_Path_Resolver (Package_Name, Name, Where));
   --  Jazzy's rmw_dds_common: 16-byte Gid (the bundled files are Humble's).

   procedure Same_Name_Other_Definition (Unused : in out Fixture) is
      use type ROSIDL.Definitions.Message_Access;
      Humble : constant Type_Hash :=
        Hash (ROSIDL.Interfaces.Message ("rmw_dds_common/msg/ParticipantEntitiesInfo"));
      Jazzy  : constant ROSIDL.Definitions.Message_Access :=
        ROSIDL.Parser.Parse_Message
          ("rmw_dds_common", "ParticipantEntitiesInfo",
           "Gid gid" & ASCII.LF & "NodeEntitiesInfo[] node_entities_info_seq",
           Resolve => Jazzy_Gids'Access);
   begin
      --  ros_discovery_info's type as Jazzy publishes it.
      Assert (Hash (Jazzy) = Prefix
              & "91a0593bacdcc50ea9bdcf849a938b128412cc1ea821245c663bcd26f83c295e",
              "Jazzy ParticipantEntitiesInfo: " & Hash (Jazzy));
      Assert (Humble /= Hash (Jazzy), "two definitions of one name: two hashes");
   end Same_Name_Other_Definition;

   procedure Description_Text (Unused : in out Fixture) is
      Text : constant String := Description (ROSIDL.Interfaces.Message ("std_msgs/msg/String"));
   begin
      Assert (Text = "{""type_description"": {""type_name"": ""std_msgs/msg/String"", "
              & """fields"": [{""name"": ""data"", ""type"": {""type_id"": 17, "
              & """capacity"": 0, ""string_capacity"": 0, ""nested_type_name"": """"}}]}, "
              & """referenced_type_descriptions"": []}", Text);
      Assert (Hash_Of_DDS_Type ("std_msgs::msg::dds_::String_")
              = Hash (ROSIDL.Interfaces.Message ("std_msgs/msg/String")), "by DDS name");
      Assert (Hash_Of_DDS_Type ("no_such::msg::dds_::Thing_") = Zero, "unknown: zero");
      Assert (Hash_Of_DDS_Type ("garbage") = Zero, "not a DDS type name: zero");
   end Description_Text;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("type hashes: the values ROS 2 Jazzy publishes",
                                      Published_Hashes'Access));
      Result.Add_Test (Caller.Create ("type hashes: description text, look-up by DDS name",
                                      Description_Text'Access));
      Result.Add_Test
        (Caller.Create ("type hashes: Jazzy's ros_discovery_info type, one name with two"
                        & " definitions", Same_Name_Other_Definition'Access));
      return Result;
   end Suite;

end ROSIDL.Type_Hashes.Tests;
