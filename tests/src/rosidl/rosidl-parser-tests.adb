with Ada.Containers;
with Ada.Directories;
with Ada.Environment_Variables;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;
with ROSIDL.Definitions.Rendering;
with ROSIDL.Interfaces;
with ROSIDL.Parser.Literals;
with ROSIDL.Typesupport;
with Suite_Support;

package body ROSIDL.Parser.Tests is

   use AUnit.Assertions;
   use Ada.Strings.Unbounded;
   use type Ada.Containers.Count_Type;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   overriding procedure Tear_Down (Unused : in out Fixture);
   --  Takes the test folders off the search path, so that suites run later
   --  (which may walk every package on the path) see the bundled ones only.

   package Caller is new AUnit.Test_Caller (Fixture);

   function Contains (Text, Part : String) return Boolean renames Suite_Support.Contains;

   type Message_Access_List is array (Positive range <>) of Message_Access;

   function Bundled return String is
     (ROSIDL.Interfaces.Search_Path.First_Element);
   --  The bundled folder comes first on the path.

   function Test_Data return String is
     (Ada.Directories.Full_Name (Bundled & "/../../tests/data"));
   --  tests/data of the repository (the bundled folder is share/ros2_interfaces).

   function User_Folder return String is (Test_Data & "/user_interfaces");

   procedure Add_User_Folder is
   begin
      ROSIDL.Interfaces.Add_Folder (User_Folder);
   end Add_User_Folder;

   Had_Path_Variable : constant Boolean :=
     Ada.Environment_Variables.Exists (ROSIDL.Interfaces.Path_Variable);
   Saved_Path_Variable : constant String :=
     (if Had_Path_Variable
      then Ada.Environment_Variables.Value (ROSIDL.Interfaces.Path_Variable) else "");
   --  The variable as the run started; tests that change it restore it.

   procedure Restore_Path_Variable is
   begin
      if Had_Path_Variable then
         Ada.Environment_Variables.Set (ROSIDL.Interfaces.Path_Variable, Saved_Path_Variable);
      else
         Ada.Environment_Variables.Clear (ROSIDL.Interfaces.Path_Variable);
      end if;
   end Restore_Path_Variable;

   overriding procedure Tear_Down (Unused : in out Fixture) is
   begin
      ROSIDL.Interfaces.Remove_Folder (User_Folder);
      ROSIDL.Interfaces.Remove_Folder (Test_Data & "/bad_interfaces");
      Restore_Path_Variable;
   end Tear_Down;

   function Error_Of (Action : not null access procedure) return String is
      --  The message of the Definition_Error Action raises, "" when none.
   begin
      Action.all;
      return "";
   exception
      when E : Definition_Error =>
         return Ada.Exceptions.Exception_Message (E);
   end Error_Of;

   function Field_Of (M : Message_Access; Name : String) return Field is
      I : constant Natural := Field_Index (M.all, Name);
   begin
      Assert (I > 0, "no field " & Name & " in " & Full_Name (M.all));
      return M.Fields (I);
   end Field_Of;

   function Constant_Of (M : Message_Access; Name : String) return Constant_Definition is
   begin
      for C of M.Constants loop
         if C.Name = Name then
            return C;
         end if;
      end loop;
      Assert (False, "no constant " & Name & " in " & Full_Name (M.all));
      return M.Constants.First_Element;
   end Constant_Of;

   function Defaults (F : Field) return String is
      --  "a|b|c"
      Result : Unbounded_String;
   begin
      for D of F.Default loop
         Append (Result, (if Length (Result) = 0 then "" else "|") & D);
      end loop;
      return To_String (Result);
   end Defaults;

   ---------------------------------------------------------------------------

   procedure Every_Bundled_Interface_Parses (Unused : in out Fixture) is
      use Ada.Directories;
      Found, Parsed, Listed : Natural := 0;

      procedure Check_Definition (Pkg, Kind : String; File : Directory_Entry_Type) is
         Name : constant String := Base_Name (Simple_Name (File));
      begin
         Found := Found + 1;
         if Kind = "msg" then
            Assert (Interfaces.Message (Pkg, Name) /= null, Name);
         elsif Kind = "srv" then
            Assert (Interfaces.Service (Pkg, Name) /= null, Name);
         else
            Assert (Interfaces.Action (Pkg, Name) /= null, Name);
         end if;
         Parsed := Parsed + 1;
      exception
         when E : Definition_Error =>
            Assert (False, Pkg & "/" & Kind & "/" & Name & ": "
                    & Ada.Exceptions.Exception_Message (E));
      end Check_Definition;

      procedure Check_Package (Package_Entry : Directory_Entry_Type) is
         Pkg : constant String := Simple_Name (Package_Entry);

         procedure Check_Folder (Kind : String) is
            Folder : constant String := Full_Name (Package_Entry) & "/" & Kind;

            procedure Check (File : Directory_Entry_Type) is
            begin
               Check_Definition (Pkg, Kind, File);
            end Check;
         begin
            if Exists (Folder) then
               Search (Folder, "*." & Kind, Process => Check'Access);
            end if;
         end Check_Folder;
      begin
         if Pkg /= "." and then Pkg /= ".." then
            for Kind of String_Vectors.Vector'["msg", "srv", "action"] loop
               Check_Folder (Kind);
            end loop;
         end if;
      end Check_Package;
   begin
      --  An independent walk of the bundled folder.
      Search (Bundled, "", [Directory => True, others => False], Check_Package'Access);
      for Pkg of Interfaces.Packages loop
         --  Only the packages of this folder (share/interfaces follows it).
         if Exists (Bundled & "/" & Pkg) then
            Listed := Listed + Natural (Interfaces.Messages (Pkg).Length)
              + Natural (Interfaces.Services (Pkg).Length)
              + Natural (Interfaces.Actions (Pkg).Length);
         end if;
      end loop;
      Assert (Found >= 200, "expected the bundled interfaces, found" & Found'Image & " files");
      Assert (Parsed = Found, "parsed" & Parsed'Image & " of" & Found'Image);
      Assert (Listed = Found, "listed" & Listed'Image & " of" & Found'Image);
   end Every_Bundled_Interface_Parses;

   ---------------------------------------------------------------------------

   procedure Type_Support_Names (Unused : in out Fixture) is
      use ROSIDL.Typesupport;
      S   : constant Message_Support := Get_Message_Support ("std_msgs", "String");
      Srv : constant Service_Support :=
        Get_Service_Support ("example_interfaces", "AddTwoInts");
   begin
      Assert (DDS_Type_Name (S) = "std_msgs::msg::dds_::String_", DDS_Type_Name (S));
      Assert (Full_Name (S) = "std_msgs/msg/String", Full_Name (S));
      Assert (Definition (S).Fields.Length = 1, "String has one field");
      Assert (Definition (S).Fields (1).Name = "data", "String.data");
      Assert (Definition (S).Fields (1).Of_Type.Kind = String_Kind, "data is a string");
      Assert (DDS_Type_Name (Request_Support (Srv))
              = "example_interfaces::srv::dds_::AddTwoInts_Request_",
              DDS_Type_Name (Request_Support (Srv)));
      Assert (DDS_Type_Name (Response_Support (Srv))
              = "example_interfaces::srv::dds_::AddTwoInts_Response_",
              DDS_Type_Name (Response_Support (Srv)));
      Assert (Field_Names (Definition (Request_Support (Srv)).all) = "a, b",
              Field_Names (Definition (Request_Support (Srv)).all));
      Assert (Field_Names (Definition (Response_Support (Srv)).all) = "sum",
              Field_Names (Definition (Response_Support (Srv)).all));
      Assert (Full_Name (Srv) = "example_interfaces/srv/AddTwoInts", Full_Name (Srv));
      declare
         Fib       : constant Action_Access :=
           Interfaces.Action ("example_interfaces", "Fibonacci");
         Send_Goal : constant Service_Support := To_Support (Fib.Send_Goal);
      begin
         Assert (Full_Name (Send_Goal) = "example_interfaces/action/Fibonacci_SendGoal",
                 Full_Name (Send_Goal));
         Assert (DDS_Type_Name (Request_Support (Send_Goal))
                 = "example_interfaces::action::dds_::Fibonacci_SendGoal_Request_",
                 DDS_Type_Name (Request_Support (Send_Goal)));
      end;
      --  From DDS type names back to definitions.
      Assert (Interfaces.Message_By_DDS_Name ("std_msgs::msg::dds_::String_")
              = Definition (S), "String by DDS name");
      Assert (Interfaces.Message_By_DDS_Name
                ("example_interfaces::srv::dds_::AddTwoInts_Response_")
              = Definition (Response_Support (Srv)), "AddTwoInts_Response by DDS name");
      Assert (Interfaces.Message_By_DDS_Name
                ("example_interfaces::action::dds_::Fibonacci_GetResult_Response_")
              = Interfaces.Action ("example_interfaces", "Fibonacci").Get_Result.Response,
              "Fibonacci_GetResult_Response by DDS name");
      for Bad of String_Vectors.Vector'
        ["std_msgs::msg::dds_::String", "std_msgs::msg::String_", "::dds_::X_",
         "std_msgs::msg::dds_::_", "std_msgs::msg::dds_::Nope_"]
      loop
         begin
            Assert (Interfaces.Message_By_DDS_Name (Bad) = null,
                    Bad & " must raise Unknown_Type");
         exception
            when Unknown_Type =>
               null;
         end;
      end loop;
   end Type_Support_Names;

   ---------------------------------------------------------------------------

   procedure Header_And_Nested_Resolution (Unused : in out Fixture) is
   begin
      Add_User_Folder;
      declare
         Stamped : constant Message_Access := Parse_Message
           ("sancta_test_msgs", "Stamped",
            "Header header" & ASCII.LF & "Point2 p # same package" & ASCII.LF
            & "geometry_msgs/Point q" & ASCII.LF);
         Header : constant Field := Field_Of (Stamped, "header");
      begin
         Assert (Header.Of_Type.Kind = Message_Kind, "header is a message");
         Assert (Header.Of_Type.Nested = Interfaces.Message ("std_msgs", "Header"),
                 "Header is resolved to std_msgs/Header");
         Assert (Image (Header.Of_Type) = "std_msgs/Header", Image (Header.Of_Type));
         Assert (Image (Field_Of (Stamped, "p").Of_Type) = "sancta_test_msgs/Point2",
                 "Point2 is resolved in the message's own package");
         Assert (Field_Of (Stamped, "q").Of_Type.Nested
                 = Interfaces.Message ("geometry_msgs", "Point"), "geometry_msgs/Point");
         Assert (Field_Of (Stamped, "q").Position.Line = 3
                 and then Field_Of (Stamped, "q").Position.Column = 21,
                 "field position " & Image (Field_Of (Stamped, "q").Position));
         --  Definitions are cached: the same access value on each look-up.
         Assert (Interfaces.Message ("std_msgs", "Header")
                 = Interfaces.Message ("std_msgs/msg/Header"), "cached");
         Assert (Interfaces.Message ("std_msgs/Header")
                 = Interfaces.Message ("std_msgs", "Header"), "pkg/Name form");
      end;
   end Header_And_Nested_Resolution;

   ---------------------------------------------------------------------------

   procedure Every_Construct (Unused : in out Fixture) is
      M : Message_Access;

      procedure Check_Type (Name, Expected_Image : String) is
         T : constant String := Image (Field_Of (M, Name).Of_Type);
      begin
         Assert (T = Expected_Image, Name & ": " & T & " /= " & Expected_Image);
      end Check_Type;

      procedure Check_Default (Name, Expected : String) is
         D : constant String := Defaults (Field_Of (M, Name));
      begin
         Assert (D = Expected, Name & " default: " & D & " /= " & Expected);
      end Check_Default;

      procedure Check_Constant (Name : String; Kind : Element_Kind; Value : String) is
         C : constant Constant_Definition := Constant_Of (M, Name);
      begin
         Assert (C.Kind = Kind, Name & " kind " & C.Kind'Image);
         Assert (C.Value = Value, Name & " = " & To_String (C.Value) & " /= " & Value);
      end Check_Constant;

   begin
      Add_User_Folder;
      M := Interfaces.Message ("sancta_test_msgs", "Everything");
      Assert (M.Constants.Length = 10, "constants:" & M.Constants.Length'Image);
      Check_Constant ("ANSWER", Int32_Kind, "42");
      Check_Constant ("NEGATIVE", Int8_Kind, "-5");
      Check_Constant ("MASK", UInt8_Kind, "255");
      Check_Constant ("BIG", UInt64_Kind, "18446744073709551615");
      Check_Constant ("SMALL", Int64_Kind, "-9223372036854775808");
      Check_Constant ("PI", Float64_Kind, "3.14159");
      Check_Constant ("ON", Bool_Kind, "true");
      Check_Constant ("GREETING", String_Kind, "hello # not a comment");
      Check_Constant ("UNQUOTED", String_Kind, "plain text");
      Check_Constant ("LETTER", Char_Kind, "65");
      Assert (Field_Names (M.all) =
                "header, flag, b, c, f32, f64, i8, u8, i16, u16, i32, u32, i64, u64, "
              & "text, short_text, wide, wide_short, fixed, unbounded, bounded, names, "
              & "tiny, local_point, local_points, other_point, other_points, some_points",
              Field_Names (M.all));
      Check_Type ("header", "std_msgs/Header");
      Check_Type ("flag", "bool");
      Check_Type ("b", "byte");
      Check_Type ("c", "char");
      Check_Type ("f32", "float32");
      Check_Type ("u64", "uint64");
      Check_Type ("short_text", "string<=5");
      Check_Type ("wide", "wstring");
      Check_Type ("wide_short", "wstring<=3");
      Check_Type ("fixed", "float64[3]");
      Check_Type ("unbounded", "int32[]");
      Check_Type ("bounded", "int32[<=4]");
      Check_Type ("names", "string[]");
      Check_Type ("tiny", "string<=2[<=3]");
      Check_Type ("local_point", "sancta_test_msgs/Point2");
      Check_Type ("local_points", "sancta_test_msgs/Point2[2]");
      Check_Type ("other_point", "geometry_msgs/Point");
      Check_Type ("other_points", "geometry_msgs/Point[]");
      Check_Type ("some_points", "geometry_msgs/Point[<=2]");
      Assert (Field_Of (M, "tiny").Of_Type.String_Bound = 2
              and then Field_Of (M, "tiny").Of_Type.Size = 3
              and then Field_Of (M, "tiny").Of_Type.Collection = Bounded_Sequence,
              "string<=2[<=3]");
      Check_Default ("flag", "true");
      Check_Default ("b", "255");
      Check_Default ("c", "0");
      Check_Default ("f32", "0.5");
      Check_Default ("f64", "-1.0e3");
      Check_Default ("i8", "-128");
      Check_Default ("u8", "5");
      Check_Default ("i16", "-32768");
      Check_Default ("u16", "65535");
      Check_Default ("i32", "");
      Check_Default ("u32", "4294967295");
      Check_Default ("u64", "15");
      Check_Default ("text", "it's");
      Check_Default ("short_text", "abc");
      Check_Default ("wide", "wide");
      Check_Default ("fixed", "1.0|2.5|-3.0");
      Check_Default ("unbounded", "1|2|3");
      Check_Default ("bounded", "7");
      Check_Default ("names", "a,b|c|d""e");
      Check_Default ("tiny", "ab|c");
      Assert (not Has_Default (Field_Of (M, "local_point")), "no default for a message");
   end Every_Construct;

   ---------------------------------------------------------------------------

   procedure Empty_Message_Member (Unused : in out Fixture) is
      Empty   : constant Message_Access := Interfaces.Message ("std_msgs", "Empty");
      Nothing : Message_Access;
   begin
      Add_User_Folder;
      Nothing := Interfaces.Message ("sancta_test_msgs", "Nothing");
      for M of Message_Access_List'[Empty, Nothing] loop
         Assert (M.Fields.Length = 1, Full_Name (M.all) & " has one field");
         Assert (M.Fields (1).Name = Empty_Member_Name, Field_Names (M.all));
         Assert (M.Fields (1).Of_Type.Kind = UInt8_Kind
                 and then M.Fields (1).Of_Type.Collection = Single, "uint8");
      end loop;
      Assert (Nothing.Constants.Length = 1, "the constant stays");
   end Empty_Message_Member;

   ---------------------------------------------------------------------------

   procedure Service_And_Action_Parts (Unused : in out Fixture) is
      S : constant Service_Access := Interfaces.Service ("example_interfaces", "AddTwoInts");
      A : constant Action_Access := Interfaces.Action ("example_interfaces", "Fibonacci");

      procedure Check (M : Message_Access; DDS_Name, Fields, Types : String) is
         Images : Unbounded_String;
      begin
         Assert (DDS_Type_Name (M.all) = DDS_Name, DDS_Type_Name (M.all) & " /= " & DDS_Name);
         Assert (Field_Names (M.all) = Fields, DDS_Name & ": " & Field_Names (M.all));
         for F of M.Fields loop
            Append (Images, (if Length (Images) = 0 then "" else ", ") & Image (F.Of_Type));
         end loop;
         Assert (To_String (Images) = Types, DDS_Name & ": " & To_String (Images));
      end Check;

   begin
      Check (S.Request, "example_interfaces::srv::dds_::AddTwoInts_Request_", "a, b",
             "int64, int64");
      Check (S.Response, "example_interfaces::srv::dds_::AddTwoInts_Response_", "sum",
             "int64");
      Assert (S.Request.Namespace = Srv, "service parts are in srv");
      Check (A.Goal, "example_interfaces::action::dds_::Fibonacci_Goal_", "order", "int32");
      Check (A.Result, "example_interfaces::action::dds_::Fibonacci_Result_", "sequence",
             "int32[]");
      Check (A.Feedback, "example_interfaces::action::dds_::Fibonacci_Feedback_",
             "sequence", "int32[]");
      Check (A.Send_Goal.Request,
             "example_interfaces::action::dds_::Fibonacci_SendGoal_Request_",
             "goal_id, goal", "unique_identifier_msgs/UUID, example_interfaces/Fibonacci_Goal");
      Check (A.Send_Goal.Response,
             "example_interfaces::action::dds_::Fibonacci_SendGoal_Response_",
             "accepted, stamp", "bool, builtin_interfaces/Time");
      Check (A.Get_Result.Request,
             "example_interfaces::action::dds_::Fibonacci_GetResult_Request_",
             "goal_id", "unique_identifier_msgs/UUID");
      Check (A.Get_Result.Response,
             "example_interfaces::action::dds_::Fibonacci_GetResult_Response_",
             "status, result", "int8, example_interfaces/Fibonacci_Result");
      Check (A.Feedback_Message,
             "example_interfaces::action::dds_::Fibonacci_FeedbackMessage_",
             "goal_id, feedback",
             "unique_identifier_msgs/UUID, example_interfaces/Fibonacci_Feedback");
      Assert (Full_Name (A.Feedback_Message.all)
              = "example_interfaces/action/Fibonacci_FeedbackMessage",
              Full_Name (A.Feedback_Message.all));
      --  The parts are found by their full names too.
      Assert (Interfaces.Message ("example_interfaces/srv/AddTwoInts_Request") = S.Request,
              "srv part by full name");
      Assert (Interfaces.Message ("example_interfaces/action/Fibonacci_SendGoal_Response")
              = A.Send_Goal.Response, "action part by full name");
      Assert (Interfaces.Message ("example_interfaces/action/Fibonacci_Feedback")
              = A.Feedback, "action feedback by full name");
      --  A user service and action nest a message of their own package.
      Add_User_Folder;
      Check (Interfaces.Service ("sancta_test_msgs", "Compute").Request,
             "sancta_test_msgs::srv::dds_::Compute_Request_", "from_point, factor",
             "sancta_test_msgs/Point2, float64");
      Check (Interfaces.Action ("sancta_test_msgs", "Walk").Feedback_Message,
             "sancta_test_msgs::action::dds_::Walk_FeedbackMessage_", "goal_id, feedback",
             "unique_identifier_msgs/UUID, sancta_test_msgs/Walk_Feedback");
   end Service_And_Action_Parts;

   ---------------------------------------------------------------------------

   procedure Malformed_Corpus (Unused : in out Fixture) is
      --  Every file of tests/data/bad_interfaces/bad_msgs starts with a line
      --  "# expect: <message>"; loading it must raise Definition_Error with
      --  "<folder>/<message>" (the message names file:line:column), where
      --  "$DIR/" in <message> stands for <folder>/.
      use Ada.Directories;
      Folder   : constant String := Full_Name (Test_Data & "/bad_interfaces");
      Problems : Unbounded_String;
      Checked  : Natural := 0;
   begin
      Interfaces.Add_Folder (Folder);
      for Kind of String_Vectors.Vector'["msg", "srv", "action"] loop
         declare
            Files : Search_Type;
            File  : Directory_Entry_Type;
         begin
            Start_Search (Files, Folder & "/bad_msgs/" & Kind, "*." & Kind);
            while More_Entries (Files) loop
               Get_Next_Entry (Files, File);
               declare
                  Name     : constant String := Base_Name (Simple_Name (File));
                  Input    : Ada.Text_IO.File_Type;
                  Prefix   : constant String := "# expect: ";
                  Expected : Unbounded_String;

                  procedure Load is
                  begin
                     if Kind = "msg" then
                        Assert (Interfaces.Message ("bad_msgs", Name) /= null, Name);
                     elsif Kind = "srv" then
                        Assert (Interfaces.Service ("bad_msgs", Name) /= null, Name);
                     else
                        Assert (Interfaces.Action ("bad_msgs", Name) /= null, Name);
                     end if;
                  end Load;

               begin
                  Ada.Text_IO.Open (Input, Ada.Text_IO.In_File, Full_Name (File));
                  declare
                     First_Line : constant String := Ada.Text_IO.Get_Line (Input);
                  begin
                     Assert (First_Line'Length > Prefix'Length
                             and then First_Line (1 .. Prefix'Length) = Prefix,
                             Name & ": no expectation line");
                     Expected := To_Unbounded_String
                       (Folder & "/bad_msgs/" & Kind & "/"
                        & First_Line (Prefix'Length + 1 .. First_Line'Last));
                     --  "$DIR/" stands for the file's folder in the text.
                     loop
                        declare
                           At_Dir : constant Natural := Index (Expected, "$DIR/");
                        begin
                           exit when At_Dir = 0;
                           Replace_Slice (Expected, At_Dir, At_Dir + 4,
                                          Folder & "/bad_msgs/" & Kind & "/");
                        end;
                     end loop;
                  end;
                  Ada.Text_IO.Close (Input);
                  declare
                     Got : constant String := Error_Of (Load'Access);
                  begin
                     Checked := Checked + 1;
                     if Got /= Expected then
                        --  The whole text on standard error (AUnit shortens
                        --  assertion messages).
                        Ada.Text_IO.Put_Line
                          (Ada.Text_IO.Standard_Error,
                           "corpus " & Kind & "/" & Name & ASCII.LF & "  got      " & Got
                           & ASCII.LF & "  expected " & To_String (Expected));
                        Append (Problems, " " & Name);
                     end if;
                  end;
               end;
            end loop;
            End_Search (Files);
         end;
      end loop;
      Assert (Checked >= 50, "corpus of" & Checked'Image & " files");
      Assert (Length (Problems) = 0, "wrong errors for" & To_String (Problems));
   end Malformed_Corpus;

   ---------------------------------------------------------------------------

   procedure Inline_Errors (Unused : in out Fixture) is
      --  Errors in text given directly to the parser (default file name).

      procedure Duplicate is
         M : constant Message_Access := Parse_Message
           ("my_msgs", "Dup", "int32 x" & ASCII.LF & "  int32   x" & ASCII.LF);
      begin
         Assert (M = null, "not reached");
      end Duplicate;

      procedure Bad_Type is
         M : constant Message_Access := Parse_Message
           ("my_msgs", "Bad", "# c" & ASCII.LF & ASCII.HT & "flaot64 x" & ASCII.LF);
      begin
         Assert (M = null, "not reached");
      end Bad_Type;

      procedure Bad_Name is
         M : constant Message_Access := Parse_Message ("My_Msgs", "Bad", "int32 x");
      begin
         Assert (M = null, "not reached");
      end Bad_Name;

      procedure Bad_UTF_8 is
         --  A wstring default whose text is not UTF-8 (a lone Latin-1 byte).
         M : constant Message_Access := Parse_Message
           ("my_msgs", "Wide", "wstring w ""caf" & Character'Val (16#E9#) & """");
      begin
         Assert (M = null, "not reached");
      end Bad_UTF_8;

      procedure Bad_UTF_8_Constant is
         M : constant Message_Access := Parse_Message
           ("my_msgs", "Wide", "int8 x" & ASCII.LF & "wstring W=" & Character'Val (16#C3#));
      begin
         Assert (M = null, "not reached");
      end Bad_UTF_8_Constant;

      Got : Unbounded_String;
   begin
      Got := To_Unbounded_String (Error_Of (Bad_UTF_8'Access));
      Assert (Contains (To_String (Got), "my_msgs/msg/Wide.msg:1:")
              and then Contains (To_String (Got), "valid UTF-8"), To_String (Got));
      Got := To_Unbounded_String (Error_Of (Bad_UTF_8_Constant'Access));
      Assert (Contains (To_String (Got), "my_msgs/msg/Wide.msg:2:")
              and then Contains (To_String (Got), "valid UTF-8"), To_String (Got));
      declare
         M : constant Message_Access := Parse_Message
           ("my_msgs", "Wide", "wstring w ""caf" & Character'Val (16#C3#)
            & Character'Val (16#A9#) & """");
      begin
         Assert (Defaults (Field_Of (M, "w")) = "caf" & Character'Val (16#C3#)
                 & Character'Val (16#A9#), "valid UTF-8 accepted: " & Defaults (Field_Of (M, "w")));
      end;
      Got := To_Unbounded_String (Error_Of (Duplicate'Access));
      Assert (Got = "my_msgs/msg/Dup.msg:2:11: expected a new field name, found 'x'"
              & " (already defined at line 1)", To_String (Got));
      Got := To_Unbounded_String (Error_Of (Bad_Type'Access));
      Assert (Got = "my_msgs/msg/Bad.msg:2:2: expected a primitive type or a type name"
              & " ([A-Z][A-Za-z0-9]*), found 'flaot64'", To_String (Got));
      Got := To_Unbounded_String (Error_Of (Bad_Name'Access));
      Assert (Contains (To_String (Got), "expected a package name"), To_String (Got));
   end Inline_Errors;

   ---------------------------------------------------------------------------

   procedure Search_Path_And_Unknown_Types (Unused : in out Fixture) is
      Env_Folder : constant String := Test_Data & "/env_interfaces";
      Raised     : Boolean := False;
   begin
      --  The environment variable, read at each look-up of the path.
      begin
         Assert (Interfaces.Message ("sancta_env_msgs", "Ping") = null, "not reached");
      exception
         when E : Unknown_Type =>
            Raised := True;
            Assert (Contains (Ada.Exceptions.Exception_Message (E),
                              "no package sancta_env_msgs"),
                    Ada.Exceptions.Exception_Message (E));
      end;
      Assert (Raised, "sancta_env_msgs must be unknown before the variable is set");
      Ada.Environment_Variables.Set
        (Interfaces.Path_Variable, "/nonexistent/folder:" & Env_Folder);
      declare
         Path : constant String_Vectors.Vector := Interfaces.Search_Path;
      begin
         Assert (Path.First_Element = Bundled, "bundled first");
         Assert (Path.Contains (Ada.Directories.Full_Name (Env_Folder)),
                 "the variable's folder is on the path");
         Assert (Interfaces.Message ("sancta_env_msgs", "Ping").Fields.Length = 1, "Ping");
         Assert (Interfaces.Packages.Contains ("sancta_env_msgs"), "listed package");
      end;
      Restore_Path_Variable;

      --  Without RCLADA_ROOT the bundled folder is found from the program's
      --  own folder (bin/../share/ros2_interfaces).
      declare
         Root_Variable : constant String := Interfaces.Root_Variable;
         Saved : constant String :=
           (if Ada.Environment_Variables.Exists (Root_Variable)
            then Ada.Environment_Variables.Value (Root_Variable) else "");
         Via_Root : constant String := Bundled;
      begin
         Ada.Environment_Variables.Clear (Root_Variable);
         declare
            Via_Program : constant String := Bundled;
         begin
            if Saved /= "" then
               Ada.Environment_Variables.Set (Root_Variable, Saved);
            end if;
            Assert (Via_Program = Via_Root, Via_Program & " /= " & Via_Root);
         end;
         Ada.Environment_Variables.Set (Root_Variable, "/nonexistent/root");
         declare
            Path : constant String_Vectors.Vector := Interfaces.Search_Path;
         begin
            if Saved /= "" then
               Ada.Environment_Variables.Set (Root_Variable, Saved);
            else
               Ada.Environment_Variables.Clear (Root_Variable);
            end if;
            Assert (Path.Is_Empty or else Path.First_Element /= Via_Root,
                    "RCLADA_ROOT names the bundled folder");
         end;
      end;

      --  Add_Folder.
      Add_User_Folder;
      Assert (Interfaces.Search_Path.Contains (User_Folder), "Add_Folder");
      Assert (Interfaces.Messages ("sancta_test_msgs").Contains ("Everything"), "listing");
      Assert (Interfaces.Services ("sancta_test_msgs").First_Element = "Compute", "srv");
      Assert (Interfaces.Actions ("sancta_test_msgs").First_Element = "Walk", "action");
      Raised := False;
      begin
         Interfaces.Add_Folder (Test_Data & "/no_such_folder");
      exception
         when Definition_Error =>
            Raised := True;
      end;
      Assert (Raised, "Add_Folder of a missing folder raises Definition_Error");
      Interfaces.Remove_Folder (User_Folder);
      Assert (not Interfaces.Search_Path.Contains (User_Folder), "Remove_Folder");
      Assert (not Interfaces.Packages.Contains ("sancta_test_msgs"), "removed package");
      Add_User_Folder;

      --  Listings of the bundled packages, sorted.
      declare
         Packages : constant String_Vectors.Vector := Interfaces.Packages;
      begin
         for Name of String_Vectors.Vector'
           ["builtin_interfaces", "std_msgs", "geometry_msgs", "sensor_msgs", "nav_msgs",
            "rcl_interfaces", "rmw_dds_common", "action_msgs", "unique_identifier_msgs",
            "example_interfaces", "std_srvs", "visualization_msgs", "rosgraph_msgs"]
         loop
            Assert (Packages.Contains (Name), "package " & Name);
         end loop;
         for I in Packages.First_Index + 1 .. Packages.Last_Index loop
            Assert (Packages (I - 1) < Packages (I), "sorted packages");
         end loop;
      end;

      --  Unknown types.
      for Full of String_Vectors.Vector'
        ["std_msgs/msg/NoSuchType", "no_such_pkg/msg/Thing", "std_msgs/srv/X_Request",
         "example_interfaces/action/Fibonacci_Nope", "NoSlash", "std_msgs/msg/../../x"]
      loop
         Raised := False;
         begin
            Assert (Interfaces.Message (Full) = null, "not reached");
         exception
            when Unknown_Type =>
               Raised := True;
         end;
         Assert (Raised, Full & " must raise Unknown_Type");
      end loop;
      Raised := False;
      begin
         Assert (Interfaces.Service ("std_srvs", "Nope") = null, "not reached");
      exception
         when E : Unknown_Type =>
            Raised := Contains (Ada.Exceptions.Exception_Message (E), "std_srvs/srv/Nope");
      end;
      Assert (Raised, "unknown service");
      Raised := False;
      begin
         Assert (Interfaces.Messages ("no_such_pkg").Is_Empty, "not reached");
      exception
         when Unknown_Type =>
            Raised := True;
      end;
      Assert (Raised, "listing an unknown package");
   end Search_Path_And_Unknown_Types;

   ---------------------------------------------------------------------------

   procedure Value_Rules (Unused : in out Fixture) is
      use ROSIDL.Parser.Literals;

      procedure Good (Kind : Element_Kind; Text, Normal : String; Bound : Natural := 0) is
         R : constant Check_Result := Check_Scalar (Kind, Bound, Text);
      begin
         Assert (R.OK, Kind'Image & " " & Text & ": " & To_String (R.Expected));
         Assert (R.Value = Normal, Kind'Image & " " & Text & " gave " & To_String (R.Value)
                 & ", expected " & Normal);
      end Good;

      procedure Bad (Kind : Element_Kind; Text : String; Bound : Natural := 0) is
         R : constant Check_Result := Check_Scalar (Kind, Bound, Text);
      begin
         Assert (not R.OK, Kind'Image & " " & Text & " must be refused, gave "
                 & To_String (R.Value));
      end Bad;

   begin
      Good (Bool_Kind, "TRUE", "true");
      Good (Bool_Kind, "0", "false");
      Bad (Bool_Kind, "2");
      Good (Int8_Kind, "-0", "0");
      Good (Int8_Kind, "+7", "7");
      Good (Int16_Kind, "0x7FFF", "32767");
      Bad (Int16_Kind, "0x8000");
      Good (Int32_Kind, "-0b1000", "-8");
      Good (Int32_Kind, "1_000", "1000");
      Bad (Int32_Kind, "1__000");
      Bad (Int32_Kind, "_1");
      Bad (Int32_Kind, "1.0");
      Bad (Int32_Kind, "");
      Good (UInt32_Kind, "0o777", "511");
      Bad (UInt32_Kind, "4294967296");
      Good (Int64_Kind, "9223372036854775807", "9223372036854775807");
      Bad (Int64_Kind, "9223372036854775808");
      Bad (UInt64_Kind, "99999999999999999999999");
      Good (Byte_Kind, "0xff", "255");
      Bad (Byte_Kind, "-1");
      Good (Float64_Kind, "5", "5.0");
      Good (Float64_Kind, "5.", "5.0");
      Good (Float64_Kind, "-.25E+2", "-0.25e2");
      Good (Float64_Kind, "Infinity", "inf");
      Good (Float64_Kind, "-inf", "-inf");
      Good (Float64_Kind, "NaN", "nan");
      Good (Float64_Kind, "1e308", "1.0e308");
      Bad (Float64_Kind, "1e309");
      Good (Float32_Kind, "3.4e38", "3.4e38");
      Bad (Float32_Kind, "3.5e38");
      Bad (Float64_Kind, ".");
      Bad (Float64_Kind, "1e");
      Bad (Float64_Kind, "0x10");
      Bad (Float64_Kind, "1,5");
      Good (String_Kind, "plain words", "plain words");
      Good (String_Kind, """a\""b""", "a""b");
      Good (String_Kind, "'tab\there'", "tab" & ASCII.HT & "here");
      Good (String_Kind, "''", "");
      Good (WString_Kind, """h" & Character'Val (16#C3#) & Character'Val (16#A9#) & """",
            "h" & Character'Val (16#C3#) & Character'Val (16#A9#), Bound => 2);
      Bad (String_Kind, """abc""", Bound => 2);
      Bad (String_Kind, """abc");
      Bad (String_Kind, "'a'b'");
   end Value_Rules;

   ---------------------------------------------------------------------------

   function Only_Point
     (Package_Name, Name : String; Where : Source_Position) return Message_Access;
   --  A resolver that knows a single type, my_msgs/Point.

   Point : constant Message_Access := Parse_Message
     ("my_msgs", "Point", "float64 x" & ASCII.LF & "float64 y" & ASCII.LF,
      Resolve => Only_Point'Access);

   function Only_Point
     (Package_Name, Name : String; Where : Source_Position) return Message_Access
   is
      pragma Unreferenced (Where);
   begin
      return (if Package_Name = "my_msgs" and then Name = "Point" then Point else null);
   end Only_Point;

   procedure Custom_Resolver (Unused : in out Fixture) is
      BOM  : constant String :=
        Character'Val (16#EF#) & Character'Val (16#BB#) & Character'Val (16#BF#);
      Path : constant Message_Access := Parse_Message
        ("my_msgs", "Path",
         BOM & "Point[] points" & ASCII.CR & ASCII.LF & "Point start",
         File => "mem:Path", Resolve => Only_Point'Access);

      procedure Unknown is
         M : constant Message_Access := Parse_Message
           ("my_msgs", "Other", "int32 a" & ASCII.LF & "  geometry_msgs/Point p",
            File => "mem:Other", Resolve => Only_Point'Access);
      begin
         Assert (M = null, "not reached");
      end Unknown;

   begin
      Assert (Path.Fields (1).Of_Type.Nested = Point, "resolved by the given function");
      Assert (Path.Fields (2).Position.Line = 2, "CR LF line ends");
      Assert (Path.Fields (1).Position.Column = 9, "columns after the byte order mark");
      Assert (Image (Path.Position) = "mem:Path:1:1", Image (Path.Position));
      Assert (Error_Of (Unknown'Access) = "mem:Other:2:3: expected a message type on the"
              & " search path, found 'geometry_msgs/Point'", Error_Of (Unknown'Access));
   end Custom_Resolver;

   ---------------------------------------------------------------------------

   procedure Rendering (Unused : in out Fixture) is
      use ROSIDL.Definitions.Rendering;
      HT : constant Character := ASCII.HT;
      LF : constant Character := ASCII.LF;
      Pose : constant String :=
        Show (Interfaces.Message ("geometry_msgs", "PoseStamped").all);
      Expected_Pose : constant String :=
        "std_msgs/Header header" & LF
        & HT & "builtin_interfaces/Time stamp" & LF
        & HT & HT & "int32 sec" & LF
        & HT & HT & "uint32 nanosec" & LF
        & HT & "string frame_id" & LF
        & "Pose pose" & LF
        & HT & "Point position" & LF
        & HT & HT & "float64 x" & LF
        & HT & HT & "float64 y" & LF
        & HT & HT & "float64 z" & LF
        & HT & "Quaternion orientation" & LF
        & HT & HT & "float64 x 0.0" & LF
        & HT & HT & "float64 y 0.0" & LF
        & HT & HT & "float64 z 0.0" & LF
        & HT & HT & "float64 w 1.0" & LF;
      Service : constant String :=
        Show (Interfaces.Service ("example_interfaces", "AddTwoInts").all);
      Action : constant String :=
        Show (Interfaces.Action ("example_interfaces", "Fibonacci").all);
   begin
      Assert (Pose = Expected_Pose, "PoseStamped:" & LF & Pose);
      Assert (Service = "int64 a" & LF & "int64 b" & LF & "---" & LF & "int64 sum" & LF,
              Service);
      Assert (Action = "int32 order" & LF & "---" & LF & "int32[] sequence" & LF & "---" & LF
              & "int32[] sequence" & LF, Action);
      Assert (Show (Interfaces.Message ("std_msgs", "Empty").all) = "", "Empty shows nothing");
      Add_User_Folder;
      declare
         Text : constant String :=
           Show (Interfaces.Message ("sancta_test_msgs", "Everything").all, Expand => False);

         procedure Has (Line : String) is
         begin
            Assert (Contains (LF & Text, LF & Line & LF), "no line '" & Line & "' in" & LF
                    & Text);
         end Has;

      begin
         Has ("int32 ANSWER=42");
         Has ("string GREETING=""hello # not a comment""");
         Has ("bool flag true");
         Has ("string<=5 short_text ""abc""");
         Has ("float64[3] fixed [1.0, 2.5, -3.0]");
         Has ("string[] names [""a,b"", ""c"", ""d\""e""]");
         Has ("Point2[2] local_points");
         Has ("geometry_msgs/Point[<=2] some_points");
         Assert (Index (To_Unbounded_String (Text), "ANSWER")
                 < Index (To_Unbounded_String (Text), "header"), "file order");
         Assert (not Contains (Text, HT & ""), "not expanded");
      end;
   end Rendering;

   ---------------------------------------------------------------------------

   procedure Concurrent_Look_Ups (Unused : in out Fixture) is
      --  Tasks load the same (not yet cached) types at once: each type is
      --  parsed once and every task gets the same definition.
      subtype Name_Index is Positive range 1 .. 4;

      function Name (I : Name_Index) return String is
        (case I is
            when 1 => "MultiDOFJointState",
            when 2 => "JointState",
            when 3 => "Imu",
            when 4 => "PointCloud2");

      type Result_Array is array (Name_Index) of Message_Access;

      task type Loader is
         entry Start (Offset : Natural);
         entry Done (Result : out Result_Array);
      end Loader;

      task body Loader is
         Mine  : Result_Array := [others => null];
         First : Natural;
      begin
         accept Start (Offset : Natural) do
            First := Offset;
         end Start;
         for K in Name_Index loop
            declare
               I : constant Positive := (K + First - 1) mod Name_Index'Last + 1;
            begin
               Mine (I) := Interfaces.Message ("sensor_msgs", Name (I));
            end;
         end loop;
         accept Done (Result : out Result_Array) do
            Result := Mine;
         end Done;
      exception
         when others =>
            accept Done (Result : out Result_Array) do
               Result := [others => null];
            end Done;
      end Loader;

      Loaders : array (1 .. 4) of Loader;
      Results : array (Loaders'Range) of Result_Array;
   begin
      for L in Loaders'Range loop
         Loaders (L).Start (L);
      end loop;
      for L in Loaders'Range loop
         Loaders (L).Done (Results (L));
      end loop;
      for I in Name_Index loop
         for L in Loaders'Range loop
            Assert (Results (L) (I) /= null, Name (I) & " loaded by task" & L'Image);
            Assert (Results (L) (I) = Results (1) (I), Name (I) & " parsed once");
         end loop;
         Assert (Results (1) (I) = Interfaces.Message ("sensor_msgs", Name (I)),
                 "cached");
      end loop;
   end Concurrent_Look_Ups;

   ---------------------------------------------------------------------------

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;

      procedure Add (Name : String; Test : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("rosidl parser: " & Name, Test));
      end Add;

   begin
      Add ("every bundled interface parses", Every_Bundled_Interface_Parses'Access);
      Add ("type support of std_msgs/String and AddTwoInts", Type_Support_Names'Access);
      Add ("search path (variable, Add_Folder), listings, unknown types",
           Search_Path_And_Unknown_Types'Access);
      Add ("Header shorthand and nested resolution", Header_And_Nested_Resolution'Access);
      Add ("every construct: types, bounds, constants, defaults", Every_Construct'Access);
      Add ("empty messages get their one member", Empty_Message_Member'Access);
      Add ("service and action parts, DDS names", Service_And_Action_Parts'Access);
      Add ("malformed corpus: error text and line:column", Malformed_Corpus'Access);
      Add ("errors in inline text", Inline_Errors'Access);
      Add ("value rules: integers, floats, booleans, strings", Value_Rules'Access);
      Add ("a resolver given by the caller", Custom_Resolver'Access);
      Add ("text rendering as ros2 interface show", Rendering'Access);
      Add ("concurrent look-ups parse each type once", Concurrent_Look_Ups'Access);
      return Result;
   end Suite;

end ROSIDL.Parser.Tests;
