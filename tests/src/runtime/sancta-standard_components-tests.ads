--  Tests of the standard components, wired by configuration files and run
--  on a manual clock: copy, merge, switch, logger (CSV on update, JSON
--  lines periodic), watchdog (alarm and abort), value; and the report of
--  the death of an asynchronous component's task.
with AUnit.Test_Suites;

package Sancta.Standard_Components.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end Sancta.Standard_Components.Tests;
