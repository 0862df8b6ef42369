--  Command-line helpers shared by the runtime commands (a private child).
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;

private package Sancta.Commands.Options is

   Usage_Error : exception;

   procedure Parse_Set
     (Text : String; Into : in out Sancta.Runtime.Components.String_Maps.Map);
   --  "name=value" (name with or without "$") into Into; Usage_Error when
   --  malformed.

   function Next_Value (Index : in out Positive) return String;
   --  The value following the option at Ada.Command_Line.Argument (Index);
   --  Index then designates that value. Usage_Error "option X needs a value"
   --  when the command line ends there.

   function Number (Option, Text : String) return Long_Float;
   --  Text as a number; Usage_Error "option X: "T" is not a number".

   procedure Load_Reporting
     (File      : String;
      Result    : out Sancta.Runtime.Configurations.Configuration;
      Overrides : Sancta.Runtime.Components.String_Maps.Map);
   --  Configurations.Load, then each diagnostic on standard error.

end Sancta.Commands.Options;
