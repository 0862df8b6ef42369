with Ada.Command_Line;
with Ada.Directories;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;    use Ada.Strings.Unbounded;
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

   generic
      type Value_Type is private;
      with function Value (Text : String) return Value_Type;
      Kind : String;
   function Parsed (Index : Positive; Name : String) return Value_Type;
   --  Argument Index (there is one) read by Value; Fail "is not KIND".

   function Parsed (Index : Positive; Name : String) return Value_Type is
      Text : constant String := CL.Argument (Index);
   begin
      return Value (Text);
   exception
      when Constraint_Error =>
         Fail (Where (Index, Name) & ": """ & Text & """ is not " & Kind);
   end Parsed;

   function Parsed_Seconds is new Parsed (Duration, Duration'Value, "a number of seconds");
   function Parsed_Count is new Parsed (Natural, Natural'Value, "a whole number");
   function Parsed_Number is new Parsed (Long_Float, Long_Float'Value, "a number");

   function Seconds (Index : Positive; Name : String; Default : Duration) return Duration is
   begin
      if CL.Argument_Count < Index then
         return Default;
      end if;
      return Value : constant Duration := Parsed_Seconds (Index, Name) do
         if Value < 0.0 then
            Fail (Where (Index, Name) & ": """ & CL.Argument (Index) & """ is negative");
         end if;
      end return;
   end Seconds;

   function Count (Index : Positive; Name : String; Minimum : Natural := 0) return Natural is
   begin
      if CL.Argument_Count < Index then
         Fail (Where (Index, Name) & " is missing");
      end if;
      return Value : constant Natural := Parsed_Count (Index, Name) do
         if Value < Minimum then
            Fail (Where (Index, Name) & ": " & CL.Argument (Index) & " is below" & Minimum'Image);
         end if;
      end return;
   end Count;

   function Number (Index : Positive; Name : String; Default : Long_Float) return Long_Float is
   begin
      if CL.Argument_Count < Index then
         return Default;
      end if;
      return Value : constant Long_Float := Parsed_Number (Index, Name) do
         if not (Value > 0.0 and then Value <= Long_Float'Last) then
            Fail (Where (Index, Name) & ": """ & CL.Argument (Index)
                  & """ is not greater than 0");
         end if;
      end return;
   end Number;

   procedure Create_Output (File : in out Ada.Text_IO.File_Type; Name, What : String) is
   begin
      Ada.Text_IO.Create (File, Ada.Text_IO.Out_File, Name);
   exception
      when Ada.Text_IO.Name_Error | Ada.Text_IO.Use_Error =>
         Fail (What & ": """ & Name & """ cannot be created");
   end Create_Output;

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
