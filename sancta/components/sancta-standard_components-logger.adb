with Ada.Directories;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Sancta.Logging;
with Sancta.Runtime.Clocks;

package body Sancta.Standard_Components.Logger is

   use Ada.Strings.Unbounded;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;

   type Logger_Component is new Base_Component with record
      File     : Ada.Text_IO.File_Type;
      JSONL    : Boolean := False;
      Period   : Ada.Real_Time.Time_Span;
      Origin   : Clocks.Time;
   end record;

   overriding procedure Start (This : in out Logger_Component);
   overriding procedure Run (This : in out Logger_Component; Next : in out Clocks.Time);
   overriding procedure On_Input
     (This : in out Logger_Component; Data : String; Item : Values.Value'Class);
   overriding procedure Stop (This : in out Logger_Component);

   function Stamp (This : Logger_Component'Class) return String is
     (Values.Real_Image (Long_Float (Ada.Real_Time.To_Duration (This.Now - This.Origin))));

   function CSV_Field (S : String) return String is
      Needs_Quotes : constant Boolean :=
        (for some C of S => C in ',' | '"' | ASCII.LF | ASCII.CR);
      Result : Unbounded_String;
   begin
      if not Needs_Quotes then
         return S;
      end if;
      Append (Result, '"');
      for C of S loop
         if C = '"' then
            Append (Result, """""");
         else
            Append (Result, C);
         end if;
      end loop;
      Append (Result, '"');
      return To_String (Result);
   end CSV_Field;

   overriding procedure Start (This : in out Logger_Component) is
      Name : constant String := This.Option_Text ("file");
   begin
      This.JSONL := This.Option_Text ("format") = "jsonl";
      This.Period := This.Option_Duration ("period");
      This.Origin := This.Now;
      declare
         Folder : constant String := Ada.Directories.Containing_Directory (Name);
      begin
         if not Ada.Directories.Exists (Folder) then
            Ada.Directories.Create_Path (Folder);
         end if;
      end;
      Ada.Text_IO.Create (This.File, Ada.Text_IO.Out_File, Name);
      if This.Period = Ada.Real_Time.Time_Span_Zero then
         if not This.JSONL then
            Ada.Text_IO.Put_Line (This.File, "time,key,value");
         end if;
         for Position in This.Input_Names.Iterate loop
            This.Subscribe (String_Maps.Key (Position));
         end loop;
      elsif not This.JSONL then
         declare
            Header : Unbounded_String := To_Unbounded_String ("time");
         begin
            for Position in This.Input_Names.Iterate loop
               Append (Header, "," & CSV_Field (String_Maps.Key (Position)));
            end loop;
            Ada.Text_IO.Put_Line (This.File, To_String (Header));
         end;
      end if;
      This.Log (Logging.Info, "logging" & This.Input_Names.Length'Image & " input(s) to " & Name);
   end Start;

   overriding procedure Run (This : in out Logger_Component; Next : in out Clocks.Time) is
      Line : Unbounded_String;
   begin
      if This.Period = Ada.Real_Time.Time_Span_Zero then
         Next := Never;
         return;
      end if;
      if This.JSONL then
         Line := To_Unbounded_String ("{""time"": " & This.Stamp);
      else
         Line := To_Unbounded_String (This.Stamp);
      end if;
      for Position in This.Input_Names.Iterate loop
         declare
            Data  : constant String := String_Maps.Key (Position);
            Known : constant Boolean := This.Has_Value (Data);
         begin
            if This.JSONL then
               Append (Line, ", " & Values.JSON_String (Data) & ": "
                       & (if Known then This.Input (Data).JSON else "null"));
            else
               Append (Line, "," & (if Known then CSV_Field (This.Input (Data).Image) else ""));
            end if;
         end;
      end loop;
      if This.JSONL then
         Append (Line, "}");
      end if;
      Ada.Text_IO.Put_Line (This.File, To_String (Line));
      Ada.Text_IO.Flush (This.File);
      Next := Next + This.Period;
   end Run;

   overriding procedure On_Input
     (This : in out Logger_Component; Data : String; Item : Values.Value'Class)
   is
      Key : constant String := This.Input_Key (Data);
   begin
      if This.JSONL then
         Ada.Text_IO.Put_Line
           (This.File, "{""time"": " & This.Stamp & ", ""key"": " & Values.JSON_String (Key)
            & ", ""value"": " & Item.JSON & "}");
      else
         Ada.Text_IO.Put_Line
           (This.File, This.Stamp & "," & CSV_Field (Key) & "," & CSV_Field (Item.Image));
      end if;
      Ada.Text_IO.Flush (This.File);
   end On_Input;

   overriding procedure Stop (This : in out Logger_Component) is
   begin
      Base_Component (This).Stop;
      if Ada.Text_IO.Is_Open (This.File) then
         Ada.Text_IO.Close (This.File);
      end if;
   end Stop;

   function Create is new Factory.Create_Component (Logger_Component);

   Longest_Name_Part : constant := 255;
   --  NAME_MAX of Linux file systems: a longer folder or file name cannot be
   --  created (Use_Error when the logger starts).

   function Check_File (Name : String) return String is
      --  "" when Name can be a log file: not empty, not a folder, and the
      --  nearest existing ancestor is a folder (missing folders are made).
      use Ada.Directories;
   begin
      if Name = "" then
         return "expected a file name";
      elsif Exists (Name) and then Kind (Name) = Directory then
         return "'" & Name & "' is a folder";
      end if;
      --  Each part of the path within the file system's limit (NAME_MAX).
      declare
         Part_First : Positive := Name'First;
      begin
         for I in Name'Range loop
            if I = Name'Last or else Name (I + 1) = '/' then
               if I - Part_First + 1 > Longest_Name_Part then
                  return "a part of the file name has" & Natural'Image (I - Part_First + 1)
                    & " characters, more than" & Longest_Name_Part'Image;
               end if;
               Part_First := I + 2;
            end if;
         end loop;
      end;
      declare
         Folder : Unbounded_String := To_Unbounded_String (Containing_Directory (Name));
      begin
         while not Exists (To_String (Folder)) loop
            Folder := To_Unbounded_String (Containing_Directory (To_String (Folder)));
         end loop;
         if Kind (To_String (Folder)) /= Directory then
            return "cannot create '" & Name & "': '" & To_String (Folder) & "' is not a folder";
         end if;
      end;
      return "";
   exception
      when Name_Error | Use_Error =>
         return "'" & Name & "' is not a valid file name";
   end Check_File;

begin
   Factory.Register
     ((Name       => To_Unbounded_String ("logger"),
       Doc        => To_Unbounded_String ("writes any inputs to a CSV or JSON-lines file"),
       Ports      => Port_Vectors.Empty_Vector,
       Options    => Option_Vectors.Empty_Vector
                       & Make_Option ("file", Text_Option, Required => True,
                                      Doc => "output file (missing folders are made)",
                                      Check => Check_File'Access)
                       & Make_Option ("format", Choice_Option, "csv", Choices => "csv jsonl")
                       & Make_Option ("period", Duration_Option, "0",
                                      Doc => "seconds between lines; 0: a line per update"),
       Any_Inputs => True,
       Refine     => null,
       others     => <>),
      Create'Access);
end Sancta.Standard_Components.Logger;
