with Ada.Directories;
with Ada.Exceptions;
with Ada.Numerics.Discrete_Random;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with AUnit.Assertions;
with Sancta.Standard_Components.All_Standard;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Factory;
with Sancta.Edit_Distances;
with Sancta.Runtime.Component_Hosts;
with Sancta.Runtime.Values;
with Sancta.Geometry;
with Suite_Support; use Suite_Support;

package body Sancta.Runtime.Configurations.Tests is

   pragma Warnings (Off, Sancta.Standard_Components.All_Standard);

   use AUnit.Assertions;
   use type Sancta.Geometry.Pose;

   Data_Dir : constant String := "tests/data/config";

   function Diagnostics_Text (C : Configuration) return String is
      Result : Unbounded_String;
   begin
      for D of C.Diagnostics loop
         Append (Result, "  " & Image (D) & ASCII.LF);
      end loop;
      return To_String (Result);
   end Diagnostics_Text;

   --  Every tests/data/config/bad-*.xml starts with
   --  "<!-- expect: [FILE:]LINE:COLUMN: SEVERITY: MESSAGE -->"; the
   --  diagnostic "DIR/FILE:LINE:COLUMN: SEVERITY: MESSAGE..." must be among
   --  those of its load (FILE defaults to the file itself), and the load
   --  must have errors.
   procedure Broken_Corpus (Unused : in out Fixture) is
      Search : Ada.Directories.Search_Type;
      Item   : Ada.Directories.Directory_Entry_Type;
      Count  : Natural := 0;
   begin
      Ada.Directories.Start_Search (Search, Data_Dir, "bad-*.xml");
      while Ada.Directories.More_Entries (Search) loop
         Ada.Directories.Get_Next_Entry (Search, Item);
         declare
            Name   : constant String := Data_Dir & "/" & Ada.Directories.Simple_Name (Item);
            F      : Ada.Text_IO.File_Type;
            Config : Configuration;
         begin
            Ada.Text_IO.Open (F, Ada.Text_IO.In_File, Name);
            declare
               Line   : constant String := Ada.Text_IO.Get_Line (F);
               Open   : constant String := "<!-- expect: ";
               First  : constant Natural := Ada.Strings.Fixed.Index (Line, Open);
               Last   : constant Natural := Ada.Strings.Fixed.Index (Line, " -->");
            begin
               Ada.Text_IO.Close (F);
               Assert (First > 0 and then Last > First, Name & ": no expectation line");
               declare
                  Expect : constant String := Line (First + Open'Length .. Last - 1);
                  Full   : constant String :=
                    (if Expect (Expect'First) in '0' .. '9' then Name & ":" & Expect
                     else Data_Dir & "/" & Expect);
                  Found  : Boolean := False;
               begin
                  Load (Name, Config);
                  Assert (Error_Count (Config) > 0, Name & ": no error reported");
                  for D of Config.Diagnostics loop
                     declare
                        Text : constant String := Image (D);
                     begin
                        if Text'Length >= Full'Length
                          and then Text (Text'First .. Text'First + Full'Length - 1) = Full
                        then
                           Found := True;
                        end if;
                     end;
                  end loop;
                  Assert (Found, Name & ": expected" & ASCII.LF & "  " & Full & ASCII.LF
                          & "got" & ASCII.LF & Diagnostics_Text (Config));
               end;
            end;
            Count := Count + 1;
         end;
      end loop;
      Ada.Directories.End_Search (Search);
      Assert (Count >= 20, "the corpus has only" & Count'Image & " files");
   end Broken_Corpus;

   function Find_Instance (A : Agent; Name : String) return Instance is
   begin
      for I of A.Instances loop
         if I.Name = Name then
            return I;
         end if;
      end loop;
      raise Program_Error with "no instance " & Name;
   end Find_Instance;

   function Key_Of
     (I : Instance; Direction : Components.Port_Direction; Data : String) return String is
      use type Components.Port_Direction;
   begin
      for B of I.Bindings loop
         if B.Direction = Direction and then B.Data = Data then
            return To_String (B.Key) & ":" & To_String (B.Type_Name);
         end if;
      end loop;
      return "";
   end Key_Of;

   --  Listing 1.1: Ari, a robot, whose odometry provides odometric_pose to
   --  the scan matcher, which provides corrected_pose (nobody uses it yet:
   --  a warning). Then the node runs one round on a manual clock.
   procedure Listing_1_1 (Unused : in out Fixture) is
      Config : Configuration;
      Clock  : aliased Clocks.Manual_Clock;
      Host   : Component_Hosts.Component_Host;
   begin
      Load ("share/config/listing-1.1.xml", Config);
      Assert (Error_Count (Config) = 0, "errors:" & ASCII.LF & Diagnostics_Text (Config));
      Assert (Warning_Count (Config) = 1, "one warning expected:" & Diagnostics_Text (Config));
      Assert (Contains
                (Image (Config.Diagnostics.First_Element),
                 "listing-1.1.xml:14:7: warning: output 'corrected_pose' of scan_matching#2"
                 & " is not used"),
              Diagnostics_Text (Config));
      Assert (Config.Name = "config_example", "root name");
      Assert (Natural (Config.Agents.Length) = 1, "one agent");
      declare
         A  : constant Agent := Config.Agents.First_Element;
         O  : constant Instance := Find_Instance (A, "odometry#1");
         SM : constant Instance := Find_Instance (A, "scan_matching#2");
      begin
         Assert (A.Id = "Ari" and then A.Kind = "robot", "agent Ari, robot");
         Assert (A.Instances.First_Element.Name = "odometry#1", "odometry starts first");
         Assert (Key_Of (O, Components.Output, "pose") = "odometric_pose:types.pose",
                 "odometry provides odometric_pose");
         Assert (Key_Of (SM, Components.Input, "pose") = "odometric_pose:types.pose",
                 "scan matching requires odometric_pose");
         Assert (Key_Of (SM, Components.Output, "pose") = "corrected_pose:types.pose",
                 "scan matching provides corrected_pose");
      end;
      Host.Create (Config, 1, Clock'Unchecked_Access);
      Host.Start (Run_Scheduler_Task => False);
      Host.Scheduler.Step;
      Assert (Host.Database.Contains ("odometric_pose"), "odometry ran");
      Assert (Host.Database.Contains ("corrected_pose"), "scan matching reacted");
      Assert (Values.Pose_Value (Host.Database.Get ("corrected_pose")).Data
              = Values.Pose_Value (Host.Database.Get ("odometric_pose")).Data,
              "identity correction by default");
      Host.Stop;
   end Listing_1_1;

   --  Constants (with an override), groups shared by two agents, an
   --  include, $id and ${id}, order, a disabled component.
   procedure Extensions (Unused : in out Fixture) is
      Config    : Configuration;
      Overrides : String_Map;
   begin
      Overrides.Include ("speed", "2.5");
      Load (Data_Dir & "/good-team.xml", Config, Overrides);
      Assert (Error_Count (Config) = 0, "errors:" & ASCII.LF & Diagnostics_Text (Config));
      Assert (Agent_Ids (Config) = "Ari, Ben", "agents: " & Agent_Ids (Config));
      Assert (Config.Constants ("$period") = "0.05", "constant from the include");
      Assert (Config.Constants ("$speed") = "2.5", "override wins");
      for A of Config.Agents loop
         declare
            Id : constant String := To_String (A.Id);
            O  : constant Instance := Find_Instance (A, "odometry#1");
            SM : constant Instance := Find_Instance (A, "scan_matching#3");
         begin
            Assert (O.Options ("period") = "0.05", Id & ": period from constant");
            Assert (O.Options ("v") = "2.5", Id & ": v from the overridden constant");
            Assert (Key_Of (O, Components.Output, "pose") = Id & "_odometric_pose:types.pose",
                    Id & ": ${id} in as: " & Key_Of (O, Components.Output, "pose"));
            Assert (Key_Of (SM, Components.Input, "pose") = Id & "_odometric_pose:types.pose",
                    Id & ": scan matching input");
            Assert (A.Instances.First_Element.Name = "scan_matching#3",
                    Id & ": order -1 starts first");
            Assert (not Find_Instance (A, "watchdog#2").Enabled, Id & ": watchdog disabled");
         end;
      end loop;
   end Extensions;

   --  Every example under share/config loads without error.
   procedure Examples (Unused : in out Fixture) is
      Search : Ada.Directories.Search_Type;
      Item   : Ada.Directories.Directory_Entry_Type;
      Count  : Natural := 0;
   begin
      Ada.Directories.Start_Search (Search, "share/config", "*.xml",
                                    [Ada.Directories.Ordinary_File => True, others => False]);
      while Ada.Directories.More_Entries (Search) loop
         Ada.Directories.Get_Next_Entry (Search, Item);
         declare
            Name   : constant String := Ada.Directories.Full_Name (Item);
            Config : Configuration;
         begin
            Load (Name, Config);
            Assert (Error_Count (Config) = 0, Name & ":" & ASCII.LF & Diagnostics_Text (Config));
            Count := Count + 1;
         end;
      end loop;
      Ada.Directories.End_Search (Search);
      Assert (Count >= 3, "examples:" & Count'Image);
   end Examples;

   --  Random corruptions of a good file (bytes replaced, deleted or
   --  duplicated; a fixed seed) never make Load raise: every outcome is a
   --  list of diagnostics, each with a position.
   procedure Corruptions (Unused : in out Fixture) is
      package Random_Positions is new Ada.Numerics.Discrete_Random (Positive);
      Gen      : Random_Positions.Generator;
      Original : Unbounded_String;
      F        : Ada.Text_IO.File_Type;
      Name     : constant String := "out/test/corrupted.xml";
      Noise    : constant String := "<>/=""'$ {}&;#x-!?azAZ09" & ASCII.LF;
   begin
      Ada.Directories.Create_Path ("out/test");
      Ada.Text_IO.Open (F, Ada.Text_IO.In_File, Data_Dir & "/good-plumbing.xml");
      while not Ada.Text_IO.End_Of_File (F) loop
         Append (Original, Ada.Text_IO.Get_Line (F) & ASCII.LF);
      end loop;
      Ada.Text_IO.Close (F);
      Random_Positions.Reset (Gen, 20261121);
      for Round in 1 .. 300 loop
         declare
            Text : Unbounded_String := Original;
            Config : Configuration;
         begin
            for Change in 1 .. 1 + Round mod 4 loop
               declare
                  At_Char : constant Positive :=
                    1 + Random_Positions.Random (Gen) mod Length (Text);
                  Pick    : constant Positive :=
                    1 + Random_Positions.Random (Gen) mod Noise'Length;
               begin
                  case Random_Positions.Random (Gen) mod 3 is
                     when 0 => Replace_Element (Text, At_Char, Noise (Pick));
                     when 1 => Delete (Text, At_Char, At_Char);
                     when others => Insert (Text, At_Char, Noise (Pick) & Noise (Pick));
                  end case;
               end;
            end loop;
            Ada.Text_IO.Create (F, Ada.Text_IO.Out_File, Name);
            Ada.Text_IO.Put (F, To_String (Text));
            Ada.Text_IO.Close (F);
            begin
               Load (Name, Config);
            exception
               when E : others =>
                  Assert (False, "round" & Round'Image & ": Load raised "
                          & Ada.Exceptions.Exception_Information (E));
            end;
            for D of Config.Diagnostics loop
               Assert (D.Where.Line >= 1 and then D.Where.Column >= 1,
                       "round" & Round'Image & ": no position in " & Image (D));
            end loop;
         end;
      end loop;
   end Corruptions;

   procedure Distances (Unused : in out Fixture) is
   begin
      Assert (Edit_Distances.Distance ("odometri", "odometry") = 1, "one substitution");
      Assert (Edit_Distances.Distance ("", "abc") = 3, "insertions");
      Assert (Edit_Distances.Distance ("abc", "") = 3, "deletions");
      Assert (Edit_Distances.Distance ("kitten", "sitting") = 3, "kitten/sitting");
      Assert (Edit_Distances.Distance ("Logger", "logger") = 1, "case counts by default");
      Assert (Edit_Distances.Distance ("Logger", "logger", Ignore_Case => True) = 0,
              "case ignored");
      Assert (Edit_Distances.Distance (String'("xxabc") (3 .. 5), "abd") = 1,
              "slices not starting at 1");
      Assert (Factory.Closest ("odometri", Factory.Names) = "'odometry'",
              "closest component: " & Factory.Closest ("odometri", Factory.Names));
   end Distances;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("configuration: broken-file corpus (message and position)",
                                      Broken_Corpus'Access));
      Result.Add_Test (Caller.Create ("configuration: Listing 1.1 loads, wires and runs",
                                      Listing_1_1'Access));
      Result.Add_Test (Caller.Create ("configuration: constants, groups, includes, --set",
                                      Extensions'Access));
      Result.Add_Test (Caller.Create ("configuration: the examples of share/config check clean",
                                      Examples'Access));
      Result.Add_Test (Caller.Create ("configuration: random corruptions never raise",
                                      Corruptions'Access));
      Result.Add_Test (Caller.Create ("configuration: edit distance of suggestions",
                                      Distances'Access));
      return Result;
   end Suite;

end Sancta.Runtime.Configurations.Tests;
