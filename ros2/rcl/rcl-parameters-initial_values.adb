with Ada.Strings.Fixed;
with RCL.Arguments;
with RCL.Names;

package body RCL.Parameters.Initial_Values is

   use type RCL.YAML.Node_Kind;

   function Node_Pattern_Problem (Pattern : String) return String is
      --  "" when the node names of a parameter file's scope are valid by
      --  rcl's rules: "/**", or [NAMESPACE/]NODE where NODE is "*" or a node
      --  name and NAMESPACE (made absolute) "/**" or a namespace; else what
      --  is wrong (a scope no node can match would silently never apply).
      Slash : constant Natural := Ada.Strings.Fixed.Index (Pattern, "/", Ada.Strings.Backward);
      Node  : constant String := Pattern (Slash + 1 .. Pattern'Last);
   begin
      if Pattern = "/**" then
         return "";
      end if;
      if Slash > 0 then
         declare
            Given     : constant String := Pattern (Pattern'First .. Slash - 1);
            Namespace : constant String :=
              (if Given'Length > 0 and then Given (Given'First) = '/' then Given
               else "/" & Given);
            Problem   : constant String :=
              (if Namespace = "/**" then "" else RCL.Names.Namespace_Problem (Namespace));
         begin
            if Problem /= "" then
               return Problem;
            end if;
         end;
      end if;
      return (if Node = "*" then "" else RCL.Names.Node_Name_Problem (Node));
   end Node_Pattern_Problem;

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
               if K = "" then
                  --  (rcl refuses an empty key; other names are the node's
                  --  business, as in rcl: no rule for names in files.)
                  raise Parse_Error with D.Key_Where (N, I) & ": empty parameter name";
               elsif D.Kind (V) = Mapping then
                  Flatten (Pattern, Prefix & K & ".", V);
               else
                  Add_Override (Pattern, Prefix & K, From_YAML (D, V), Origin => D.Where (V));
               end if;
            end;
         end loop;
      end Flatten;

      procedure Walk (Scope : String; Scope_Where : String; N : Node) is
      --  Scope: the node names of the keys above N ("" at the root, then
      --  "/ns/node", "/**"...), the last of them at Scope_Where.
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
                  declare
                     Problem : constant String := Node_Pattern_Problem (Scope);
                  begin
                     if Problem /= "" then
                        raise Parse_Error with Scope_Where & ": " & Problem;
                     end if;
                  end;
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
                              & "/" & K), D.Key_Where (N, I), V);
               else
                  raise Parse_Error with D.Key_Where (N, I) & ": expected '" & K
                    & ": ros__parameters: ...' (a node name and its parameters)";
               end if;
            end;
         end loop;
      end Walk;
   begin
      if D.Kind (D.Root) /= Null_Value then
         Walk ("", "", D.Root);
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
