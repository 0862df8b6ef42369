--  Reading a configuration: the XML files (includes, constants and their
--  substitution, groups), every agent's component instances checked against
--  the factory's descriptors; each agent is then wired (Wiring). Every
--  problem becomes a diagnostic with its file, line and column.
private package Sancta.Runtime.Configurations.Loading is

   procedure Load (File : String; Result : out Configuration; Overrides : String_Map);
   --  As Configurations.Load.

end Sancta.Runtime.Configurations.Loading;
