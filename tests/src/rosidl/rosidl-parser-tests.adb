with Ada.Containers;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with AUnit.Assertions;
with AUnit.Test_Caller;
with AUnit.Test_Fixtures;
with ROSIDL.Interfaces;
with ROSIDL.Typesupport;

package body ROSIDL.Parser.Tests is

   use AUnit.Assertions;
   use Ada.Strings.Unbounded;
   use type Ada.Containers.Count_Type;

   type Fixture is new AUnit.Test_Fixtures.Test_Fixture with null record;

   package Caller is new AUnit.Test_Caller (Fixture);

   function Bundled return String is
     (ROSIDL.Interfaces.Search_Path.First_Element);

   ---------------------------------------------------------------------------

   procedure Every_Bundled_Interface_Parses (Unused : in out Fixture) is
      use Ada.Directories;
      Found, Parsed, Listed : Natural := 0;
      Packages : Search_Type;
      Package_Entry : Directory_Entry_Type;
   begin
      --  An independent walk of the bundled folder.
      Start_Search (Packages, Bundled, "", [Directory => True, others => False]);
      while More_Entries (Packages) loop
         Get_Next_Entry (Packages, Package_Entry);
         declare
            Pkg : constant String := Simple_Name (Package_Entry);
         begin
            if Pkg /= "." and then Pkg /= ".." then
               for Kind of String_Vectors.Vector'["msg", "srv", "action"] loop
                  declare
                     Folder : constant String := Full_Name (Package_Entry) & "/" & Kind;
                     Files  : Search_Type;
                     File   : Directory_Entry_Type;
                  begin
                     if Exists (Folder) then
                        Start_Search (Files, Folder, "*." & Kind);
                        while More_Entries (Files) loop
                           Get_Next_Entry (Files, File);
                           Found := Found + 1;
                           declare
                              Name : constant String := Base_Name (Simple_Name (File));
                           begin
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
                           end;
                        end loop;
                        End_Search (Files);
                     end if;
                  end;
               end loop;
            end if;
         end;
      end loop;
      End_Search (Packages);
      for Pkg of Interfaces.Packages loop
         Listed := Listed + Natural (Interfaces.Messages (Pkg).Length)
           + Natural (Interfaces.Services (Pkg).Length)
           + Natural (Interfaces.Actions (Pkg).Length);
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
   end Type_Support_Names;

   ---------------------------------------------------------------------------

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test
        (Caller.Create ("rosidl parser: every bundled interface parses",
                        Every_Bundled_Interface_Parses'Access));
      Result.Add_Test
        (Caller.Create ("rosidl typesupport: std_msgs/String, AddTwoInts DDS names",
                        Type_Support_Names'Access));
      return Result;
   end Suite;

end ROSIDL.Parser.Tests;
