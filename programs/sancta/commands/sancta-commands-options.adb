with Ada.Command_Line;
with Ada.Strings.Fixed;
with Ada.Text_IO;

package body Sancta.Commands.Options is

   procedure Parse_Set
     (Text : String; Into : in out Sancta.Runtime.Components.String_Maps.Map)
   is
      Equal : constant Natural := Ada.Strings.Fixed.Index (Text, "=");
   begin
      if Equal <= Text'First then
         raise Usage_Error with "--set expects NAME=VALUE, found '" & Text & "'";
      end if;
      Into.Include (Text (Text'First .. Equal - 1), Text (Equal + 1 .. Text'Last));
   end Parse_Set;

   function Number_Value (Index : in out Positive) return Long_Float is
      Option : constant String := Ada.Command_Line.Argument (Index);
   begin
      return Number (Option, Next_Value (Index));
   end Number_Value;

   function Parse_Arguments return Boolean is
      use Ada.Command_Line;
      I : Positive := 2;
   begin
      while I <= Argument_Count loop
         if Argument (I) in "--help" | "-h" then
            Usage;
            return False;
         end if;
         Take (Argument (I), I);
         I := I + 1;
      end loop;
      return True;
   end Parse_Arguments;

   procedure Load_Reporting
     (File      : String;
      Result    : out Sancta.Runtime.Configurations.Configuration;
      Overrides : Sancta.Runtime.Components.String_Maps.Map) is
      package Configurations renames Sancta.Runtime.Configurations;
   begin
      Configurations.Load (File, Result, Overrides);
      for D of Result.Diagnostics loop
         Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, Configurations.Image (D));
      end loop;
   end Load_Reporting;

end Sancta.Commands.Options;
