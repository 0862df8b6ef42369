with Ada.Command_Line;
with Ada.Directories;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;    use Ada.Strings.Unbounded;
with Ada.Text_IO;
with GNAT.OS_Lib;

package body Bench_Arguments is

   package CL renames Ada.Command_Line;

   Usage_Text : Unbounded_String;

   function Program return String is (Ada.Directories.Simple_Name (CL.Command_Name));

   function First_Line (Text : String) return String is
     (Text (Text'First .. Ada.Strings.Fixed.Index (Text & ASCII.LF, [ASCII.LF]) - 1));

   function Where (Index : Positive; Name : String) return String is
     (Name & " (argument" & Index'Image & ")");

   function Checked (Usage : String; Min, Max : Natural) return Boolean is
   begin
      Usage_Text := To_Unbounded_String (Usage);
      for I in 1 .. CL.Argument_Count loop
         if CL.Argument (I) in "-h" | "--help" then
            Ada.Text_IO.Put_Line ("usage: " & Usage);
            GNAT.OS_Lib.OS_Exit (0);
         end if;
      end loop;
      if CL.Argument_Count < Min then
         Fail ("expected at least" & Min'Image & " argument(s), found" & CL.Argument_Count'Image);
      elsif CL.Argument_Count > Max then
         Fail ("expected at most" & Max'Image & " argument(s), found" & CL.Argument_Count'Image);
      end if;
      return True;
   end Checked;

   procedure Fail (Message : String) is
      use Ada.Text_IO;
   begin
      Put_Line (Standard_Error, Program & ": " & Message);
      Put_Line (Standard_Error, "usage: " & First_Line (To_String (Usage_Text))
                & "  (" & Program & " --help: more)");
      GNAT.OS_Lib.OS_Exit (2);
   end Fail;

   function Seconds (Index : Positive; Name : String; Default : Duration) return Duration is
   begin
      if CL.Argument_Count < Index then
         return Default;
      end if;
      declare
         Text  : constant String := CL.Argument (Index);
         Value : Duration;
      begin
         begin
            Value := Duration'Value (Text);
         exception
            when Constraint_Error =>
               Fail (Where (Index, Name) & ": """ & Text & """ is not a number of seconds");
         end;
         if Value < 0.0 then
            Fail (Where (Index, Name) & ": """ & Text & """ is negative");
         end if;
         return Value;
      end;
   end Seconds;

   function Count (Index : Positive; Name : String; Minimum : Natural := 0) return Natural is
   begin
      if CL.Argument_Count < Index then
         Fail (Where (Index, Name) & " is missing");
      end if;
      declare
         Text  : constant String := CL.Argument (Index);
         Value : Natural := 0;
      begin
         begin
            Value := Natural'Value (Text);
         exception
            when Constraint_Error =>
               Fail (Where (Index, Name) & ": """ & Text & """ is not a whole number");
         end;
         if Value < Minimum then
            Fail (Where (Index, Name) & ": " & Text & " is below" & Minimum'Image);
         end if;
         return Value;
      end;
   end Count;

   function Number (Index : Positive; Name : String; Default : Long_Float) return Long_Float is
   begin
      if CL.Argument_Count < Index then
         return Default;
      end if;
      declare
         Text  : constant String := CL.Argument (Index);
         Value : Long_Float;
      begin
         begin
            Value := Long_Float'Value (Text);
         exception
            when Constraint_Error =>
               Fail (Where (Index, Name) & ": """ & Text & """ is not a number");
         end;
         if not (Value > 0.0 and then Value <= Long_Float'Last) then
            Fail (Where (Index, Name) & ": """ & Text & """ is not greater than 0");
         end if;
         return Value;
      end;
   end Number;

   function One_Of (Index : Positive; Name, Choices : String) return String is
   begin
      if CL.Argument_Count < Index then
         Fail (Where (Index, Name) & " is missing (" & Choices & ")");
      end if;
      declare
         Text  : constant String := CL.Argument (Index);
         First : Positive := Choices'First;
      begin
         for I in Choices'First .. Choices'Last + 1 loop
            if I > Choices'Last or else Choices (I) = '|' then
               if Choices (First .. I - 1) = Text then
                  return Text;
               end if;
               First := I + 1;
            end if;
         end loop;
         Fail (Where (Index, Name) & ": """ & Text & """ is none of " & Choices);
      end;
   end One_Of;

end Bench_Arguments;
