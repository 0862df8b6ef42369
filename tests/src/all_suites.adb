with Simulation_Suites;
with Harness_Tests;
with Sancta.Standard_Components.Tests;
with Sancta.Standard_Components.ROS2.Tests;
with Sancta.Logging.Tests;
with Sancta.Runtime.Configurations.Tests;
with Sancta.Runtime.Local_Databases.Tests;
with Sancta.Runtime.Schedulers.Tests;
with Sancta.Standard_Components.ROS_Clocks.Tests;
with RCL.Clocks.Tests;
with RCL.Graph.Tests;
with RCL.Logging.Tests;
with RCL.MCAP.Tests;
with RCL.MCAP.Writers.Contract_Tests;
with RCL.Zstd.Tests;
with RCL.Names.Tests;
with RCL.Nodes.Tests;
with RCL.Parameters.Tests;
with RCL.QoS.Tests;
with RCL.Services.Tests;
with RCL.Actions.Clients.Tests;
with RCL.YAML.Tests;
with RCL.Timers.Tests;
with ROSIDL.Parser.Tests;
with ROSIDL.CDR_Tests;
with ROSIDL.Static.Sequence_Contract_Tests;
with ROSIDL.Static.Tests;
with ROSIDL.Type_Hashes.Tests;
with Sancta.Allocation.Branch_And_Cut.Tests;
with Sancta.Allocation.Local_Search.Tests;
with Sancta.Allocation.Replanning.Tests;
with Sancta.Allocation.Test_Support.Plan_Tests;
with Sancta.Allocation.Tests;
with Sancta.Team.Tests;

package body All_Suites is

   use AUnit.Test_Suites;

   Result : aliased Test_Suite;

   function Suite return Access_Test_Suite is
   begin
      Result.Add_Test (Harness_Tests.Suite);
      Result.Add_Test (Sancta.Runtime.Configurations.Tests.Suite);
      Result.Add_Test (Sancta.Runtime.Local_Databases.Tests.Suite);
      Result.Add_Test (Sancta.Runtime.Schedulers.Tests.Suite);
      Result.Add_Test (Sancta.Standard_Components.Tests.Suite);
      Result.Add_Test (Sancta.Standard_Components.ROS2.Tests.Suite);
      Result.Add_Test (Sancta.Logging.Tests.Suite);
      Result.Add_Test (RCL.Names.Tests.Suite);
      Result.Add_Test (RCL.Logging.Tests.Suite);
      Result.Add_Test (RCL.Timers.Tests.Suite);
      Result.Add_Test (RCL.Nodes.Tests.Suite);
      Result.Add_Test (RCL.Clocks.Tests.Suite);
      Result.Add_Test (Sancta.Standard_Components.ROS_Clocks.Tests.Suite);
      Result.Add_Test (RCL.QoS.Tests.Suite);
      Result.Add_Test (RCL.Graph.Tests.Suite);
      Result.Add_Test (ROSIDL.Parser.Tests.Suite);
      Result.Add_Test (ROSIDL.CDR_Tests.Suite);
      Result.Add_Test (ROSIDL.Type_Hashes.Tests.Suite);
      Result.Add_Test (ROSIDL.Static.Tests.Suite);
      Result.Add_Test (ROSIDL.Static.Sequence_Contract_Tests.Suite);
      Result.Add_Test (RCL.Services.Tests.Suite);
      Result.Add_Test (RCL.Actions.Clients.Tests.Suite);
      Result.Add_Test (RCL.YAML.Tests.Suite);
      Result.Add_Test (RCL.MCAP.Tests.Suite);
      Result.Add_Test (RCL.MCAP.Writers.Contract_Tests.Suite);
      Result.Add_Test (RCL.Zstd.Tests.Suite);
      Result.Add_Test (RCL.Parameters.Tests.Suite);
      Result.Add_Test (Sancta.Allocation.Tests.Suite);
      Result.Add_Test (Sancta.Allocation.Test_Support.Plan_Tests.Suite);
      Result.Add_Test (Sancta.Allocation.Branch_And_Cut.Tests.Suite);
      Result.Add_Test (Sancta.Allocation.Local_Search.Tests.Suite);
      Result.Add_Test (Sancta.Allocation.Replanning.Tests.Suite);
      Result.Add_Test (Sancta.Team.Tests.Suite);
      --  Each area adds its suite here, e.g.
      --  Result.Add_Test (ROSIDL.CDR_Tests.Suite);
      Result.Add_Test (Simulation_Suites.Suite);
      return Result'Access;
   end Suite;

end All_Suites;
