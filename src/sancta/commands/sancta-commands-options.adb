with Ada.Strings.Fixed;

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

end Sancta.Commands.Options;
