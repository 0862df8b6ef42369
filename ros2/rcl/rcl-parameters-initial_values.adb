with RCL.Arguments;

package body RCL.Parameters.Initial_Values is

   use type RCL.YAML.Node_Kind;

   procedure Load_File (Path : String) is
      use RCL.YAML;
      D : constant Document := Parse_File (Path);

      procedure Flatten (Pattern : String; Prefix : String; N : Node) is
      begin
         for I in 1 .. D.Length (N) loop
            declare
               K : constant String := D.Key (N, I);
               V : constant Node := D.Item (N, I);
            begin
               if D.Kind (V) = Mapping then
                  Flatten (Pattern, Prefix & K & ".", V);
               else
                  Add_Override (Pattern, Prefix & K, From_YAML (D, V), Origin => D.Where (V));
               end if;
            end;
         end loop;
      end Flatten;

      procedure Walk (Scope : String; N : Node) is
      begin
         if D.Kind (N) /= Mapping then
            raise Parse_Error with D.Where (N) & ": expected 'node_name: ros__parameters: ...'";
         end if;
         for I in 1 .. D.Length (N) loop
            declare
               K : constant String := D.Key (N, I);
               V : constant Node := D.Item (N, I);
            begin
               if K = "ros__parameters" then
                  if Scope = "" then
                     raise Parse_Error with D.Key_Where (N, I)
                       & ": 'ros__parameters' must be under a node name";
                  end if;
                  if D.Kind (V) = Mapping then
                     Flatten (Scope, "", V);
                  elsif D.Kind (V) /= Null_Value then
                     raise Parse_Error with D.Where (V)
                       & ": 'ros__parameters' must hold a mapping of parameters";
                  end if;
               elsif D.Kind (V) = Mapping then
                  Walk ((if Scope = "" then K
                         elsif K (K'First) = '/' then Scope & K
                         else (if Scope (Scope'First) = '/' then Scope else "/" & Scope)
                              & "/" & K), V);
               else
                  raise Parse_Error with D.Key_Where (N, I) & ": expected '" & K
                    & ": ros__parameters: ...' (a node name and its parameters)";
               end if;
            end;
         end loop;
      end Walk;
   begin
      if D.Kind (D.Root) /= Null_Value then
         Walk ("", D.Root);
      end if;
   end Load_File;

   procedure Load_Arguments is
      procedure Load_Argument (Flag, Value : String) is
      begin
         if Flag in "-p" | "--param" then
            --  Checked by RCL.Arguments when it read the command line.
            declare
               Rule  : constant RCL.Arguments.Parameter_Override :=
                 RCL.Arguments.Parameter_Override_Of (Value);
               Where : constant String := "--ros-args " & Flag & " "
                 & (if Rule.Node = "" then "" else Rule.Node & ":") & Rule.Name;
            begin
               Add_Override ((if Rule.Node = "" then "/**" else Rule.Node), Rule.Name,
                             Parse (Rule.Value, Where), Origin => Where);
            end;
         else
            Load_File (Value);
         end if;
      end Load_Argument;
   begin
      RCL.Arguments.For_Each_Parameter_Argument (Load_Argument'Access);
   end Load_Arguments;

end RCL.Parameters.Initial_Values;
