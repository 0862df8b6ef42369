with Ada.Calendar;
with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Strings.Hash;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Sancta.Mutexes;

package body Sancta.Logging is

   use Ada.Strings.Unbounded;

   package Level_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (Key_Type => String, Element_Type => Level, Hash => Ada.Strings.Hash,
      Equivalent_Keys => "=");

   Start : constant Ada.Calendar.Time := Ada.Calendar.Clock;

   Tags : constant array (Level) of String (1 .. 5) :=
     ["DEBUG", "INFO ", "WARN ", "ERROR"];

   function Stamp return String;
   --  Seconds since start, with milliseconds.

   function Stamp return String is
      Elapsed : constant Duration := Ada.Calendar."-" (Ada.Calendar.Clock, Start);
      Millis  : constant Long_Long_Integer := Long_Long_Integer (Elapsed * 1000);
      Whole   : constant String := Long_Long_Integer'Image (Millis / 1000);
      Frac    : constant String := Long_Long_Integer'Image (1000 + Millis mod 1000);
   begin
      return Whole (Whole'First + 1 .. Whole'Last) & "." & Frac (Frac'Last - 2 .. Frac'Last);
   end Stamp;

   File : Ada.Text_IO.File_Type;
   --  Only touched while Output_Lock is held.

   Output_Lock : Sancta.Mutexes.Mutex;
   --  Serialises the output, which is done outside any protected action.

   protected State is
      procedure Count (Severity : Level; Message : String);
      procedure Set_Default (Threshold : Level);
      procedure Set (Section : String; Threshold : Level);
      function Threshold (Section : String) return Level;
      procedure Set_Console (On : Boolean);
      function Console_On return Boolean;
      function Get_Counts return Counts;
      function Get_Last return String;
      procedure Reset;
   private
      Default : Level := Info;
      Sections : Level_Maps.Map;
      Console : Boolean := True;
      Printed_Counts : Counts := [others => 0];
      Last : Unbounded_String;
   end State;

   protected body State is

      procedure Count (Severity : Level; Message : String) is
      begin
         Printed_Counts (Severity) := Printed_Counts (Severity) + 1;
         Last := To_Unbounded_String (Message);
      end Count;

      procedure Set_Default (Threshold : Level) is
      begin
         Default := Threshold;
      end Set_Default;

      procedure Set (Section : String; Threshold : Level) is
      begin
         Sections.Include (Section, Threshold);
      end Set;

      function Threshold (Section : String) return Level is
         Position : constant Level_Maps.Cursor := Sections.Find (Section);
      begin
         return (if Level_Maps.Has_Element (Position)
                 then Level_Maps.Element (Position) else Default);
      end Threshold;

      procedure Set_Console (On : Boolean) is
      begin
         Console := On;
      end Set_Console;

      function Console_On return Boolean is (Console);

      function Get_Counts return Counts is (Printed_Counts);

      function Get_Last return String is (To_String (Last));

      procedure Reset is
      begin
         Printed_Counts := [others => 0];
         Last := Null_Unbounded_String;
      end Reset;

   end State;

   procedure Log (Section : String; Severity : Level; Message : String) is
   begin
      if Severity < State.Threshold (Section) then
         return;
      end if;
      State.Count (Severity, Message);
      declare
         Line : constant String :=
           Stamp & " " & Tags (Severity) & " [" & Section & "] " & Message;
      begin
         Output_Lock.Seize;
         if State.Console_On then
            Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, Line);
         end if;
         if Ada.Text_IO.Is_Open (File) then
            Ada.Text_IO.Put_Line (File, Line);
            Ada.Text_IO.Flush (File);
         end if;
         Output_Lock.Release;
      exception
         when others =>
            Output_Lock.Release;
            --  A logger never propagates its own output failures.
      end;
   end Log;

   procedure Set_Default_Level (Threshold : Level) is
   begin
      State.Set_Default (Threshold);
   end Set_Default_Level;

   procedure Set_Level (Section : String; Threshold : Level) is
   begin
      State.Set (Section, Threshold);
   end Set_Level;

   function Enabled (Section : String; Severity : Level) return Boolean is
     (Severity >= State.Threshold (Section));

   procedure Set_Console (On : Boolean) is
   begin
      State.Set_Console (On);
   end Set_Console;

   procedure Open_File (Name : String) is
   begin
      Output_Lock.Seize;
      if Ada.Text_IO.Is_Open (File) then
         Ada.Text_IO.Close (File);
      end if;
      begin
         Ada.Text_IO.Open (File, Ada.Text_IO.Append_File, Name);
      exception
         when Ada.Text_IO.Name_Error =>
            Ada.Text_IO.Create (File, Ada.Text_IO.Out_File, Name);
      end;
      Output_Lock.Release;
   exception
      when others =>
         Output_Lock.Release;
         raise;
   end Open_File;

   procedure Close_File is
   begin
      Output_Lock.Seize;
      if Ada.Text_IO.Is_Open (File) then
         Ada.Text_IO.Close (File);
      end if;
      Output_Lock.Release;
   end Close_File;

   function Printed return Counts is (State.Get_Counts);

   function Last_Message return String is (State.Get_Last);

   procedure Reset_Counts is
   begin
      State.Reset;
   end Reset_Counts;

end Sancta.Logging;
