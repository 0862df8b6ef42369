--  Tests of services and clients: request/reply pairing (RCL.Pending_Calls),
--  rmw_cyclonedds id printing and USER_DATA parsing (RCL.DDS.Matching), and
--  in-process calls (synchronous, concurrent from several tasks,
--  asynchronous, timeouts) between an RCL.Services server and RCL.Clients.
with AUnit.Test_Suites;

package RCL.Services.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Services.Tests;
