--  Wiring one agent: the types of untyped outputs that follow their inputs
--  are propagated along the chains, then every input is matched with the
--  output providing its key (missing, duplicated and incompatible ends and
--  unused outputs are diagnosed).
private package Sancta.Runtime.Configurations.Wiring is

   procedure Propagate_Types (Result : in out Configuration; A : in out Agent);
   --  Untyped outputs of components that follow their inputs take the type
   --  of what feeds them, repeatedly (chains of copies).

   procedure Wire (Result : in out Configuration; A : Agent);
   --  Checks the connections of A's enabled instances; reports into Result.

end Sancta.Runtime.Configurations.Wiring;
