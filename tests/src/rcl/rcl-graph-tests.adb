with AUnit.Assertions; use AUnit.Assertions;
with ROSIDL;
with ROSIDL.Interfaces;
with ROSIDL.Type_Hashes;
with ROSIDL.Typesupport;
with RCL.Clients;
with RCL.DDS.Matching;
with RCL.Graph.Queries;
with RCL.Graph_Announcements;
with RCL.Nodes;
with RCL.Publishers;
with Suite_Support; use Suite_Support;

package body RCL.Graph.Tests is

   use Ada.Strings.Unbounded;

   procedure Type_Names (Unused : in out Fixture) is
   begin
      Assert (ROS_Type_Name ("std_msgs::msg::dds_::String_") = "std_msgs/msg/String",
              ROS_Type_Name ("std_msgs::msg::dds_::String_"));
      Assert (ROS_Type_Name ("example_interfaces::srv::dds_::AddTwoInts_Request_")
              = "example_interfaces/srv/AddTwoInts", "service part: the service type");
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

   --  The readers and writers this process announces for node Name
   --  (counted from the last published ros_discovery_info sample).
   procedure Announced (Name : String; Readers, Writers : out Natural) is
      function Count (Images : Unbounded_String) return Natural is
        (Ada.Strings.Unbounded.Count (Images, ","));
      Info : constant Queries.Participant_Info :=
        Queries.Decode_Participant_Info (RCL.Graph_Announcements.Announcement);
   begin
      for N of Info.Nodes loop
         if To_String (N.Id.Name) = Name then
            Readers := Count (N.Readers);
            Writers := Count (N.Writers);
            return;
         end if;
      end loop;
      raise Assertion_Error with "node " & Name & " not announced";
   end Announced;

   procedure Endpoint_Removal (Unused : in out Fixture) is
      Support : constant ROSIDL.Typesupport.Message_Support :=
        ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");
      Service : constant ROSIDL.Typesupport.Service_Support :=
        ROSIDL.Typesupport.Get_Service_Support ("example_interfaces", "AddTwoInts");
      Node    : RCL.Nodes.Node := RCL.Nodes.Init ("graph_removal_test");
      R0, W0, R, W : Natural;
   begin
      Announced ("graph_removal_test", R0, W0);
      declare
         Client : RCL.Clients.Client;
      begin
         Client.Init (Node, Service, "graph_removal_service");
         Announced ("graph_removal_test", R, W);
         Assert (R = R0 + 1 and W = W0 + 1, "client: one reader and one writer more");
      end;
      Announced ("graph_removal_test", R, W);
      Assert (W = W0, "client gone: its request writer is no longer announced");
      Assert (R = R0, "client gone: its reply reader is no longer announced");
      declare
         Pub : constant RCL.Publishers.Publisher :=
           Node.Publish (Support, "graph_removal_topic");
         pragma Unreferenced (Pub);
      begin
         Announced ("graph_removal_test", R, W);
         Assert (W = W0 + 1, "publisher announced");
      end;
      Announced ("graph_removal_test", R, W);
      Assert (W = W0 and R = R0, "publisher gone: no longer announced");
   end Endpoint_Removal;

   procedure Type_Hashes (Unused : in out Fixture) is
      String_Type : constant String := "std_msgs::msg::dds_::String_";
      String_Hash : constant String :=
        "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18";
      --  As published by ROS 2 Jazzy.
      Sample : constant String :=
        "typehash=RIHS01_00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff;"
        & "clientid=1.f.a.b;";
   begin
      Assert (Type_Hash (Sample)
              = "RIHS01_00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff",
              "typehash read: " & Type_Hash (Sample));
      Assert (RCL.DDS.Matching.User_Data_Value (Sample, "clientid") = "1.f.a.b",
              "the client id still found after a typehash");
      Assert (Type_Hash ("clientid=1.f.a.b;") = Zero_Type_Hash, "missing means zero");
      Assert (Type_Hash ("") = Zero_Type_Hash, "empty USER_DATA");
      Assert (Type_Hash ("typehash") = Zero_Type_Hash, "no '=': ignored");
      Assert (Endpoint_User_Data (Humble_24, String_Type, "clientid=x;") = "clientid=x;",
              "Humble: no hash");
      Assert (Endpoint_User_Data (Jazzy_16, String_Type, "clientid=x;")
              = "clientid=x;typehash=" & String_Hash & ";", "Jazzy: the type's hash");
      Assert (Endpoint_User_Data (Jazzy_16, String_Type) = "typehash=" & String_Hash & ";",
              "Jazzy topic endpoint");
      Assert (Endpoint_User_Data (Jazzy_16, "no_pkg::msg::dds_::Nothing_")
              = "typehash=" & Zero_Type_Hash & ";", "Jazzy, unknown type: zero hash");
      declare
         Request : constant String := ROSIDL.Type_Hashes.Hash
           (ROSIDL.Interfaces.Message_By_DDS_Name
              ("example_interfaces::srv::dds_::AddTwoInts_Request_"));
      begin
         Assert (Request /= Zero_Type_Hash, "a service request has a hash");
         Assert (Endpoint_User_Data
                   (Jazzy_16, "example_interfaces::srv::dds_::AddTwoInts_Request_", "x=1;")
                 = "x=1;typehash=" & Request & ";", "service request: the request's hash");
      end;
      Assert (Zero_Type_Hash'Length = 7 + 64, "RIHS01_ and 64 hex digits");
   end Type_Hashes;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("graph: type names", Type_Names'Access));
      Result.Add_Test (Caller.Create ("graph: topic query", Query'Access));
      Result.Add_Test (Caller.Create ("graph: endpoints removed on destruction",
                                      Endpoint_Removal'Access));
      Result.Add_Test (Caller.Create ("graph: typehash USER_DATA", Type_Hashes'Access));
      return Result;
   end Suite;

end RCL.Graph.Tests;
