--  The component runtime of SANCTA: components wired by an XML
--  configuration (Sancta.Runtime.Configurations), the local database they
--  share (Sancta.Runtime.Local_Databases), the factory that creates them by name
--  (Sancta.Runtime.Factory), the scheduler that runs them
--  (Sancta.Runtime.Schedulers) and the node that holds one agent's
--  components together (Sancta.Runtime.Component_Hosts).
--
--  Standard components live in Sancta.Standard_Components.*; a program that wants
--  them all must "with Sancta.Standard_Components.All_Standard;" (see there why).
package Sancta.Runtime
  with Preelaborate
is

   Unknown_Key : exception;
   --  Get or Update of a database key that holds no value.

   Listener_Recursion : exception;
   --  A listener stored into a key whose listeners are already running in
   --  the same task; the message names the chain of keys.

   Type_Error : exception;
   --  A value of an unexpected type was found under a key.

end Sancta.Runtime;
