--  Tests of action clients: in-process, an RCL.Actions.Servers server
--  whose goals the test moves through their states, and clients that
--  follow them on the action's status topic (Clients.Status, On_Status):
--  each change of their own goals in order, nothing of another client's;
--  when a server is available (services, status and feedback topics).
with AUnit.Test_Suites;

package RCL.Actions.Clients.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Actions.Clients.Tests;
