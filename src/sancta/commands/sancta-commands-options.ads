--  Command-line helpers shared by the runtime commands (not for users).
with Sancta.Runtime.Components;

private package Sancta.Commands.Options is

   Usage_Error : exception;

   procedure Parse_Set
     (Text : String; Into : in out Sancta.Runtime.Components.String_Maps.Map);
   --  "name=value" (name with or without "$") into Into; Usage_Error when
   --  malformed.

end Sancta.Commands.Options;
