--  SANCTA: a multi-robot architecture of black-box components wired by an
--  XML configuration, with local and replicated databases, periodic /
--  event-driven / asynchronous execution, task allocation by simulated
--  annealing and auctions, a 2D multi-robot simulator and team missions over
--  DDS.
--
--  This root package holds the exceptions shared by the whole hierarchy.
package Sancta
  with Pure
is

   Configuration_Error : exception;
   --  A configuration or mission file is wrong; the message starts with
   --  "file:line:column: ".

end Sancta;
