with Ada.Directories;
with Ada.Exceptions;
with Ada.Text_IO;
with AUnit.Assertions; use AUnit.Assertions;
with RCL.Nodes;
with Suite_Support; use Suite_Support;

package body RCL.Parameters.Tests is

   procedure Values (Unused : in out Fixture) is
   begin
      Assert (Parse ("20").Kind = Integer_Type and then Parse ("20").Int = 20, "integer");
      Assert (Parse ("2.5").Kind = Double_Type and then Parse ("2.5").Double = 2.5, "double");
      Assert (Parse ("true").Kind = Bool_Type and then Parse ("true").Bool, "bool");
      Assert (Parse ("'20'").Kind = String_Type and then Image (Parse ("'20'")) = "20",
              "quoted number is a string");
      Assert (Parse ("[1, 2]").Kind = Integer_Array_Type, "integer array");
      Assert (Parse ("[1, 2.5]").Kind = Double_Array_Type
              and then Image (Parse ("[1, 2.5]")) = "[1.0, 2.5]", "mixed numbers -> doubles");
      Assert (Image (Parse ("[a, 'b c']")) = "['a', 'b c']", "string array");
      Assert (Image (Parse ("[true, false]")) = "[True, False]", "bool array");
      Assert (Image (To_Value (Long_Float'(0.1))) = "0.1", "shortest double image");
      Assert (Image (To_Value (Long_Float'(3.0))) = "3.0", "whole double");
      Assert (YAML_Image (To_Value ("it's")) = "'it''s'", "YAML string single-quoted");
      declare
         Two_Lines : constant String := "two" & ASCII.LF & "lines";
      begin
         Assert (YAML_Image (To_Value (Two_Lines)) = """two\nlines""",
                 "YAML string with a line break: " & YAML_Image (To_Value (Two_Lines)));
         Assert (Image (Parse (YAML_Image (To_Value (Two_Lines)))) = Two_Lines,
                 "YAML string with a line break read back");
      end;
      declare
         Msg : Unbounded_String;
      begin
         begin
            Msg := To_Unbounded_String (Image (Parse ("[1, x]", "cli")));
         exception
            when E : RCL.YAML.Parse_Error =>
               Msg := To_Unbounded_String (Ada.Exceptions.Exception_Message (E));
         end;
         Assert (Contains (To_String (Msg), "cli:1:5: a parameter array holds values of one"),
                 To_String (Msg));
         begin
            Msg := To_Unbounded_String (Image (Parse ("{a: 1}", "cli")));
         exception
            when E : RCL.YAML.Parse_Error =>
               Msg := To_Unbounded_String (Ada.Exceptions.Exception_Message (E));
         end;
         Assert (Contains (To_String (Msg), "cli:1:1: a parameter value must be a scalar"),
                 To_String (Msg));
      end;
   end Values;

   Limit : constant Long_Long_Integer := 100;

   function Check (Name : String; New_Value : Value) return String is
     (if Name = "rate" and then New_Value.Int > Limit then "rate too high" else "");

   procedure Setting (Unused : in out Fixture) is
      Node : constant RCL.Nodes.Node := RCL.Nodes.Init ("param_unit", "/tests");
      FQN  : constant String := "/tests/param_unit";
   begin
      Add_Override ("/**", "gain", To_Value (Long_Long_Integer'(4)));
      Add_Override ("/tests/param_unit", "label", To_Value ("override"));
      Add_Override ("/other/node", "rate", To_Value (Long_Long_Integer'(99)));
      Add_Override ("param_unit", "rate", To_Value (Long_Long_Integer'(98)));
      --  (a name without '/' is absolute, as in rclcpp: "/param_unit")
      Declare_Parameter (Node, "rate", To_Value (Long_Long_Integer'(10)));
      Declare_Parameter (Node, "gain", To_Value (Long_Float'(1.0)));
      Declare_Parameter (Node, "label", To_Value ("default"), "a label");
      Declare_Parameter (Node, "fixed", To_Value (True), Read_Only => True);
      Clear_Overrides;
      Assert (Get (Node, "rate").Int = 10, "overrides for other nodes are ignored");
      Assert (Get (Node, "gain").Double = 4.0, "wildcard override, integer made double");
      Assert (To_String (Get (Node, "label").Text) = "override", "override by full node name");
      Assert (Has_Parameter (Node, "rate") and not Has_Parameter (Node, "nope"), "has");
      On_Set (Node, Check'Access);
      Assert (Try_Set (FQN, "rate", To_Value (Long_Long_Integer'(50))) = "", "accepted");
      Assert (Get (Node, "rate").Int = 50, "set");
      Assert (Try_Set (FQN, "rate", To_Value (Long_Long_Integer'(500))) = "rate too high",
              "validator reason");
      Assert (Get (Node, "rate").Int = 50, "rejected value not applied");
      Assert (Contains (Try_Set (FQN, "rate", To_Value ("x")), "is integer, not string"),
              "type check");
      Assert (Contains (Try_Set (FQN, "fixed", To_Value (False)), "read-only"), "read-only");
      Assert (Contains (Try_Set (FQN, "nope", To_Value (False)), "not declared"), "undeclared");
      Assert (Try_Set_Atomically
                (FQN, Assignment_Array'
                   (1 => (To_Unbounded_String ("rate"), To_Value (Long_Long_Integer'(60))),
                    2 => (To_Unbounded_String ("fixed"), To_Value (False)))) /= "",
              "atomic set rejected as a whole");
      Assert (Get (Node, "rate").Int = 50, "nothing applied");
      Assert (Try_Set_Atomically
                (FQN, Assignment_Array'
                   (1 => (To_Unbounded_String ("rate"), To_Value (Long_Long_Integer'(60))),
                    2 => (To_Unbounded_String ("label"), To_Value ("both")))) = "",
              "atomic set accepted");
      Assert (Get (Node, "rate").Int = 60
              and then To_String (Get (Node, "label").Text) = "both", "both applied");
      Assert (Natural (Names (FQN).Length) = 5
              and then To_String (Names (FQN).First_Element) = "fixed"
              and then To_String (Names (FQN).Last_Element) = "use_sim_time",
              "sorted names (with use_sim_time, as every node has)");
      Assert (Describe (FQN, "label").Kind = String_Type
              and then To_String (Describe (FQN, "label").Description) = "a label", "describe");
      Assert (Describe (FQN, "nope").Kind = Not_Set, "describe undeclared");
      begin
         Declare_Parameter (Node, "rate", To_Value (Long_Long_Integer'(1)));
         Assert (False, "declaring twice raises");
      exception
         when Parameter_Error =>
            null;
      end;
      Assert (Has_Parameter (Node, "rate"), "still declared");
      begin
         Set (Node, "rate", To_Value (Long_Long_Integer'(1000)));
         Assert (False, "Set of a rejected value raises");
      exception
         when E : Parameter_Error =>
            Assert (Ada.Exceptions.Exception_Message (E) = "rate too high", "reason raised");
      end;
   end Setting;

   procedure Files (Unused : in out Fixture) is
      use Ada.Text_IO;
      Path : constant String := "obj/param_unit_test.yaml";
      F    : File_Type;

      function Load_Error (Text : String) return String is
      begin
         Create (F, Out_File, Path);
         Put (F, Text);
         Close (F);
         Clear_Overrides;
         Load_File (Path);
         return "";
      exception
         when E : RCL.YAML.Parse_Error | Parameter_Error =>
            return Ada.Exceptions.Exception_Message (E);
      end Load_Error;
   begin
      Assert (Load_Error ("/**:" & ASCII.LF & "  ros__parameters:" & ASCII.LF
                          & "    a:" & ASCII.LF & "      b: 1" & ASCII.LF
                          & "ns:" & ASCII.LF & "  n:" & ASCII.LF & "    ros__parameters:"
                          & ASCII.LF & "      c: [x, y]" & ASCII.LF) = "", "a good file");
      declare
         Node : constant RCL.Nodes.Node := RCL.Nodes.Init ("n", "/ns");
      begin
         Declare_Parameter (Node, "a.b", To_Value (Long_Long_Integer'(0)));
         Declare_Parameter (Node, "c", Parse ("[z]"));
         Assert (Get (Node, "a.b").Int = 1, "nested names flattened with '.'");
         Assert (Image (Get (Node, "c")) = "['x', 'y']", "namespace nesting /ns/n");
      end;
      Assert (Contains (Load_Error ("ros__parameters:" & ASCII.LF & "  a: 1" & ASCII.LF),
                        ":1:1: 'ros__parameters' must be under a node name"),
              Load_Error ("ros__parameters:" & ASCII.LF & "  a: 1" & ASCII.LF));
      Assert (Contains (Load_Error ("node: 5" & ASCII.LF), ":1:1: expected 'node: ros__"),
              Load_Error ("node: 5" & ASCII.LF));
      Assert (Contains (Load_Error ("n:" & ASCII.LF & "  ros__parameters:" & ASCII.LF
                                    & "    a: [1" & ASCII.LF), ":3:8: '[' is never closed"),
              "YAML error position");
      Assert (Contains (Load_Error ("n:" & ASCII.LF & "  ros__parameters:" & ASCII.LF
                                    & "    a: ~" & ASCII.LF), ":3:8: a parameter value cannot"),
              "null value");
      Clear_Overrides;
      Ada.Directories.Delete_File (Path);
   end Files;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("parameters: values from YAML", Values'Access));
      Result.Add_Test (Caller.Create ("parameters: declare, overrides, validation",
                                      Setting'Access));
      Result.Add_Test (Caller.Create ("parameters: parameter files", Files'Access));
      return Result;
   end Suite;

end RCL.Parameters.Tests;
