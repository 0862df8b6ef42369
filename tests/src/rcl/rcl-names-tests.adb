with Ada.Exceptions;
with AUnit.Assertions; use AUnit.Assertions;
with Suite_Support; use Suite_Support;

package body RCL.Names.Tests is

   procedure Node_Names (Unused : in out Fixture) is
   begin
      Assert (Node_Name_Problem ("talker") = "", "talker is valid");
      Assert (Node_Name_Problem ("my_node_2") = "", "my_node_2 is valid");
      Assert (Contains (Node_Name_Problem ("my-node"), "'-' at position 3"),
              "names '-': " & Node_Name_Problem ("my-node"));
      Assert (Contains (Node_Name_Problem ("2node"), "digit"), "leading digit");
      Assert (Node_Name_Problem ("") /= "", "empty");
      declare
         Raised : Boolean := False;
      begin
         begin
            Validate_Node_Name ("a b");
         exception
            when E : Name_Error =>
               Raised := Contains (Ada.Exceptions.Exception_Message (E), "' ' at position 2");
         end;
         Assert (Raised, "Validate_Node_Name raises Name_Error naming ' '");
      end;
   end Node_Names;

   procedure Namespaces (Unused : in out Fixture) is
   begin
      Assert (Normalize_Namespace ("") = "/", "empty -> /");
      Assert (Normalize_Namespace ("ns") = "/ns", "relative -> absolute");
      Assert (Normalize_Namespace ("/a/b/") = "/a/b", "trailing / removed");
      Assert (Contains (Namespace_Problem ("/a//b"), "repeated '/'"), "//");
      Assert (Contains (Namespace_Problem ("/a/1b"), "digit"), "token starts with digit");
      Assert (Contains (Namespace_Problem ("/a.b"), "'.' at position 3"),
              Namespace_Problem ("/a.b"));
   end Namespaces;

   procedure Expansion (Unused : in out Fixture) is
   begin
      Assert (Expand_Topic_Name ("chatter", "talker", "/") = "/chatter", "relative, root");
      Assert (Expand_Topic_Name ("chatter", "talker", "/ns") = "/ns/chatter", "relative");
      Assert (Expand_Topic_Name ("/chatter", "talker", "/ns") = "/chatter", "absolute");
      Assert (Expand_Topic_Name ("~", "talker", "/ns") = "/ns/talker", "~");
      Assert (Expand_Topic_Name ("~/status", "talker", "/") = "/talker/status", "~/x");
      Assert (Expand_Topic_Name ("{node}/x", "talker", "/ns") = "/ns/talker/x", "{node}");
      Assert (Expand_Topic_Name ("{ns}/x", "talker", "/ns") = "/ns/x", "{ns}");
      Assert (DDS_Topic_Name ("/ns/chatter") = "rt/ns/chatter", "rt/ prefix");
      declare
         type String_Access is access String;
         Message : String_Access;
      begin
         begin
            declare
               Ignored : constant String := Expand_Topic_Name ("chat ter", "n", "/");
            begin
               null;
            end;
         exception
            when E : Name_Error =>
               Message := new String'(Ada.Exceptions.Exception_Message (E));
         end;
         Assert (Message /= null and then Contains (Message.all, "' '"),
                 "invalid character named");
      end;
   end Expansion;

   procedure Bad_Topics (Unused : in out Fixture) is
      function Fails (Name : String) return Boolean is
      begin
         declare
            Ignored : constant String := Expand_Topic_Name (Name, "n", "/");
         begin
            return False;
         end;
      exception
         when Name_Error =>
            return True;
      end Fails;
   begin
      Assert (Fails (""), "empty");
      Assert (Fails ("a//b"), "//");
      Assert (Fails ("a/"), "trailing /");
      Assert (Fails ("~x"), "~ not followed by /");
      Assert (Fails ("{bad}"), "unknown substitution");
      Assert (Fails ("{node"), "unmatched {");
      Assert (Fails ("1abc"), "leading digit");
      Assert (not Fails ("a/b_c/d1"), "valid nested name");
   end Bad_Topics;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("names: node names", Node_Names'Access));
      Result.Add_Test (Caller.Create ("names: namespaces", Namespaces'Access));
      Result.Add_Test (Caller.Create ("names: topic expansion", Expansion'Access));
      Result.Add_Test (Caller.Create ("names: invalid topics", Bad_Topics'Access));
      return Result;
   end Suite;

end RCL.Names.Tests;
