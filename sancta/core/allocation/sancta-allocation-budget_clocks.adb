with Ada.Execution_Time;

package body Sancta.Allocation.Budget_Clocks is

   function Clock (Kind : Clock_Kind) return Ada.Real_Time.Time is
      use type Ada.Execution_Time.CPU_Time;
   begin
      case Kind is
         when Wall_Time =>
            return Ada.Real_Time.Clock;
         when CPU_Time =>
            return Ada.Real_Time.Time_Of
              (0, Ada.Execution_Time.Clock - Ada.Execution_Time.Time_Of (0));
      end case;
   end Clock;

end Sancta.Allocation.Budget_Clocks;
