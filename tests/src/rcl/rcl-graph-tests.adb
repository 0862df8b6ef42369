with AUnit.Assertions; use AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;
with ROSIDL;
with ROSIDL.Typesupport;
with RCL.Nodes;
with RCL.Publishers;

package body RCL.Graph.Tests is

   use Ada.Strings.Unbounded;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;
   package Caller is new AUnit.Test_Caller (Fixture);

   procedure Type_Names (Unused : in out Fixture) is
   begin
      Assert (ROS_Type_Name ("std_msgs::msg::dds_::String_") = "std_msgs/msg/String",
              ROS_Type_Name ("std_msgs::msg::dds_::String_"));
      Assert (ROS_Type_Name ("example_interfaces::srv::dds_::AddTwoInts_Request_")
              = "example_interfaces/srv/AddTwoInts_Request", "service part");
      Assert (ROS_Type_Name ("Plain") = "Plain", "non-ROS names unchanged");
   end Type_Names;

   procedure Ignore (Node : in out RCL.Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
                     Info : ROSIDL.Message_Info) is null;

   procedure Query (Unused : in out Fixture) is
      Support : constant ROSIDL.Typesupport.Message_Support :=
        ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");
      Node    : RCL.Nodes.Node := RCL.Nodes.Init ("graph_query_test");
      Pub     : constant RCL.Publishers.Publisher := Node.Publish (Support, "graph_query");
      Found   : Boolean := False;
      pragma Unreferenced (Pub);
   begin
      Node.Subscribe_Raw ("std_msgs::msg::dds_::String_", "graph_query", Ignore'Access);
      for Attempt in 1 .. 100 loop
         for T of Topics loop
            if T.Name = "/graph_query" then
               Assert (T.Type_Name = "std_msgs/msg/String", To_String (T.Type_Name));
               Found := T.Publishers >= 1 and then T.Subscribers >= 1;
            end if;
         end loop;
         exit when Found;
         delay 0.02;
      end loop;
      Assert (Found, "our topic listed with a publisher and a subscriber");
      Assert (Count_Publishers ("/graph_query") >= 1, "Count_Publishers");
      Assert (Count_Subscribers ("/graph_query") >= 1, "Count_Subscribers");
      Assert (Count_Publishers ("/no_such_topic") = 0, "unknown topic");
   end Query;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("graph: type names", Type_Names'Access));
      Result.Add_Test (Caller.Create ("graph: topic query", Query'Access));
      return Result;
   end Suite;

end RCL.Graph.Tests;
