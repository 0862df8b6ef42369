with Ada.Command_Line;

package body Command_Line_Options is

   function Next_Value (Index : in out Positive) return String is
      use Ada.Command_Line;
   begin
      if Index + 1 > Argument_Count then
         raise Usage_Error with "option " & Argument (Index) & " needs a value";
      end if;
      Index := Index + 1;
      return Argument (Index);
   end Next_Value;

   function Number (Option, Text : String) return Long_Float is
   begin
      return Long_Float'Value (Text);
   exception
      when Constraint_Error =>
         raise Usage_Error with "option " & Option & ": """ & Text & """ is not a number";
   end Number;

end Command_Line_Options;
