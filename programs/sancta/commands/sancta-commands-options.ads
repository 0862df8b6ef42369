--  Command-line helpers shared by the runtime commands (a private child).
with Command_Line_Options;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;

private package Sancta.Commands.Options is

   Usage_Error : exception renames Command_Line_Options.Usage_Error;

   procedure Parse_Set
     (Text : String; Into : in out Sancta.Runtime.Components.String_Maps.Map);
   --  "name=value" (name with or without "$") into Into; Usage_Error when
   --  malformed.

   function Next_Value (Index : in out Positive) return String
     renames Command_Line_Options.Next_Value;

   function Number (Option, Text : String) return Long_Float
     renames Command_Line_Options.Number;

   function Number_Value (Index : in out Positive) return Long_Float;
   --  Number (Argument (Index), Next_Value (Index)): the number following
   --  the option at Index.

   generic
      with procedure Usage;
      with procedure Take (Option : String; Index : in out Positive);
   function Parse_Arguments return Boolean;
   --  Take (Argument (I), I) for each command-line argument from the second
   --  on (the first names the command); Take reads an option's value with
   --  Next_Value (I). "--help" or "-h": Usage, and False (the command then
   --  does nothing more); True when every argument has been taken.

   procedure Load_Reporting
     (File      : String;
      Result    : out Sancta.Runtime.Configurations.Configuration;
      Overrides : Sancta.Runtime.Components.String_Maps.Map);
   --  Configurations.Load, then each diagnostic on standard error.

end Sancta.Commands.Options;
