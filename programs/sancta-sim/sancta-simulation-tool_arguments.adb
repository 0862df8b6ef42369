with Ada.Command_Line;
with Ada.Strings.Fixed;

package body Sancta.Simulation.Tool_Arguments is

   use Ada.Command_Line;

   function Next_Value (Index : in out Positive) return String is
   begin
      if Index + 1 > Argument_Count then
         raise Usage_Error with Argument (Index) & ": missing value";
      end if;
      Index := Index + 1;
      return Argument (Index);
   end Next_Value;

   function To_Real (Option, Text : String) return Sancta.Geometry.Real is
      use Sancta.Geometry;
      Value : Real;
   begin
      Value := Real'Value
        (if Ada.Strings.Fixed.Index (Text, ".") = 0 then Text & ".0" else Text);
      if not Value'Valid then
         raise Constraint_Error;
      end if;
      return Value;
   exception
      when Constraint_Error =>
         raise Usage_Error with Option & ": expected a number, found """ & Text & """";
   end To_Real;

   function Parse_Arguments (World : out Ada.Strings.Unbounded.Unbounded_String)
     return Boolean
   is
      use Ada.Strings.Unbounded;
      K : Positive := 1;
   begin
      World := Null_Unbounded_String;
      if Argument_Count = 0 then
         Usage;
         Set_Exit_Status (Failure);
         return False;
      end if;
      while K <= Argument_Count loop
         declare
            A : constant String := Argument (K);
         begin
            if A in "--help" | "-h" then
               Usage;
               return False;
            elsif A'Length > 0 and then A (A'First) = '-' then
               Take (A, K);
            elsif Length (World) = 0 then
               World := To_Unbounded_String (A);
            else
               raise Usage_Error with Second_World (A);
            end if;
         end;
         K := K + 1;
      end loop;
      if Length (World) = 0 then
         raise Usage_Error with No_World;
      end if;
      return True;
   end Parse_Arguments;

end Sancta.Simulation.Tool_Arguments;
