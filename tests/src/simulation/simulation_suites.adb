with Sancta.Standard_Components.Navigation.Tests;
with Sancta.Robot.Tests;
with Sancta.Simulation.Map_Files.Tests;
with Sancta.Simulation.Rendering.Tests;
with Sancta.Simulation.Tests;

package body Simulation_Suites is

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Sancta.Simulation.Tests.Suite);
      Result.Add_Test (Sancta.Simulation.Map_Files.Tests.Suite);
      Result.Add_Test (Sancta.Simulation.Rendering.Tests.Suite);
      Result.Add_Test (Sancta.Robot.Tests.Suite);
      Result.Add_Test (Sancta.Standard_Components.Navigation.Tests.Suite);
      return Result;
   end Suite;

end Simulation_Suites;
