with Ada.Command_Line;
with Ada.Directories;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with GNAT.OS_Lib;
with Sancta.Commands.Options;
with Sancta.Standard_Components.All_Standard;
with Sancta.Runtime.Components;
with Sancta.Runtime.Configurations;
with Sancta.Runtime.Configurations.Rendering;

package body Sancta.Commands.Check is

   pragma Warnings (Off, Sancta.Standard_Components.All_Standard);
   --  Withed for its registrations only.

   use Ada.Command_Line;
   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   use type GNAT.OS_Lib.String_Access;
   package Configurations renames Sancta.Runtime.Configurations;

   procedure Write_File (Name, Text : String) is
      F : File_Type;
   begin
      Create (F, Out_File, Name);
      Put (F, Text);
      Close (F);
   end Write_File;

   procedure Run is
      File      : Unbounded_String;
      Output    : Unbounded_String := To_Unbounded_String ("out/check");
      Overrides : Sancta.Runtime.Components.String_Maps.Map;
      Config    : Configurations.Configuration;
      I         : Positive := 2;
   begin
      while I <= Argument_Count loop
         if Argument (I) in "--set" | "--output" and then I = Argument_Count then
            raise Options.Usage_Error with "option " & Argument (I) & " needs a value";
         elsif Argument (I) = "--set" and then I < Argument_Count then
            Options.Parse_Set (Argument (I + 1), Overrides);
            I := I + 1;
         elsif Argument (I) = "--output" and then I < Argument_Count then
            Output := To_Unbounded_String (Argument (I + 1));
            I := I + 1;
         elsif Argument (I) in "-h" | "--help" then
            Put_Line ("usage: sancta check FILE [--set NAME=VALUE]... [--output DIR]");
            Put_Line ("Checks a configuration (share/config/README.md): every diagnostic as");
            Put_Line ("FILE:LINE:COLUMN: error|warning: ...; then each agent's wiring table and");
            Put_Line ("a picture of it. Exit status 1 when there are errors.");
            Put_Line ("  FILE               the configuration (.xml)");
            Put_Line ("  --set NAME=VALUE   give constant $NAME of FILE this value (repeatable)");
            Put_Line ("  --output DIR       where the wiring pictures go (default out/check):");
            Put_Line ("                     DIR/BASE.dot, and DIR/BASE.svg with Graphviz (BASE:");
            Put_Line ("                     FILE's name without folder and extension)");
            return;
         elsif Argument (I)'Length > 0 and then Argument (I) (1) /= '-'
           and then Length (File) = 0
         then
            File := To_Unbounded_String (Argument (I));
         else
            raise Options.Usage_Error with "unexpected argument '" & Argument (I) & "'";
         end if;
         I := I + 1;
      end loop;
      if Length (File) = 0 then
         raise Options.Usage_Error with "missing configuration FILE";
      end if;

      Options.Load_Reporting (To_String (File), Config, Overrides);
      if Configurations.Error_Count (Config) > 0 then
         Put_Line (Standard_Error,
                   To_String (File) & ":" & Configurations.Error_Count (Config)'Image
                   & " error(s)," & Configurations.Warning_Count (Config)'Image
                   & " warning(s)");
         Set_Exit_Status (Failure);
         return;
      end if;
      Put_Line ("configuration " & To_String (Config.Name) & " (" & To_String (File) & "): "
                & "agents " & Configurations.Agent_Ids (Config) & ";"
                & Configurations.Warning_Count (Config)'Image & " warning(s)");
      Put (Configurations.Rendering.Wiring_Table (Config));

      declare
         Dir  : constant String := To_String (Output);
         Base : constant String := Ada.Directories.Base_Name (To_String (File));
         Dot  : constant String := Dir & "/" & Base & ".dot";
         Svg  : constant String := Dir & "/" & Base & ".svg";
         Tool : GNAT.OS_Lib.String_Access := GNAT.OS_Lib.Locate_Exec_On_Path ("dot");
      begin
         Ada.Directories.Create_Path (Dir);
         Write_File (Dot, Configurations.Rendering.To_Dot (Config));
         Put_Line ("wiring picture: " & Dot);
         if Tool /= null then
            declare
               Args : GNAT.OS_Lib.Argument_List :=
                 [new String'("-Tsvg"), new String'("-o"), new String'(Svg), new String'(Dot)];
               Ok   : Boolean;
            begin
               GNAT.OS_Lib.Spawn (Tool.all, Args, Ok);
               for A of Args loop
                  GNAT.OS_Lib.Free (A);
               end loop;
               Put_Line (if Ok then "wiring picture: " & Svg
                         else "dot failed; no SVG written");
            end;
            GNAT.OS_Lib.Free (Tool);
         end if;
      exception
         when E : Ada.IO_Exceptions.Name_Error | Ada.IO_Exceptions.Use_Error =>
            GNAT.OS_Lib.Free (Tool);
            Put_Line (Standard_Error, "sancta check: --output " & Dir
                      & ": cannot write the wiring picture: "
                      & Ada.Exceptions.Exception_Message (E));
            Set_Exit_Status (Failure);
      end;
   exception
      when E : Options.Usage_Error =>
         Put_Line (Standard_Error, "sancta check: " & Ada.Exceptions.Exception_Message (E));
         Put_Line (Standard_Error, "usage: sancta check FILE [--set NAME=VALUE]... [--output DIR]");
         Set_Exit_Status (2);
   end Run;

end Sancta.Commands.Check;
