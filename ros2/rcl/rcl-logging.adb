with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Environment_Variables;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;

with RCL.DDS;

package body RCL.Logging is

   use Ada.Strings.Unbounded;

   Default_Format : constant String := "[{severity}] [{time}] [{name}]: {message}";

   package Level_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Severity);

   protected State is
      procedure Init;
      procedure Set_Level (L : Severity);
      function Get_Level return Severity;
      procedure Set_Logger (Name : String);
      function Logger return String;
      function Pattern return String;
      procedure Set_Hook (H : Sink);
      function Hook return Sink;
      procedure Emit (Line : String; Level : Severity);
      procedure Set_Logger_Level (Logger : String; L : Severity);
      function Level_Of (Logger : String) return Severity;
      procedure Set_Console (On : Boolean);
   private
      Levels   : Level_Maps.Map;
      Console  : Boolean := True;
      Done     : Boolean := False;
      Lvl      : Severity := Info;
      Name     : Unbounded_String;
      Fmt      : Unbounded_String := To_Unbounded_String (Default_Format);
      The_Hook : Sink;
   end State;

   protected body State is
      procedure Init is
      begin
         if not Done then
            Done := True;
            if Ada.Environment_Variables.Exists ("RCUTILS_CONSOLE_OUTPUT_FORMAT") then
               Fmt := To_Unbounded_String
                 (Ada.Environment_Variables.Value ("RCUTILS_CONSOLE_OUTPUT_FORMAT"));
            end if;
         end if;
      end Init;
      procedure Set_Level (L : Severity) is
      begin
         Lvl := L;
      end Set_Level;
      function Get_Level return Severity is (Lvl);
      procedure Set_Logger (Name : String) is
      begin
         State.Name := To_Unbounded_String (Name);
      end Set_Logger;
      function Logger return String is (To_String (Name));
      function Pattern return String is (To_String (Fmt));
      procedure Set_Hook (H : Sink) is
      begin
         The_Hook := H;
      end Set_Hook;
      function Hook return Sink is (The_Hook);
      procedure Set_Logger_Level (Logger : String; L : Severity) is
      begin
         Levels.Include (Logger, L);
      end Set_Logger_Level;

      function Level_Of (Logger : String) return Severity is
         Last : Natural := Logger'Last;
      begin
         if not Levels.Is_Empty then
            --  "a.b.c", then "a.b", then "a".
            loop
               if Levels.Contains (Logger (Logger'First .. Last)) then
                  return Levels (Logger (Logger'First .. Last));
               end if;
               loop
                  exit when Last < Logger'First or else Logger (Last) = '.';
                  Last := Last - 1;
               end loop;
               exit when Last < Logger'First;
               Last := Last - 1;
            end loop;
         end if;
         return Lvl;
      end Level_Of;

      procedure Set_Console (On : Boolean) is
      begin
         Console := On;
      end Set_Console;

      procedure Emit (Line : String; Level : Severity) is
         pragma Warnings (Off, "potentially blocking operation");
      begin
         if not Console then
            return;
         end if;
         --  Console output is serialized here so lines never interleave.
         if Level >= Warn then
            Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error, Line);
         else
            Ada.Text_IO.Put_Line (Line);
            Ada.Text_IO.Flush;
         end if;
      end Emit;
   end State;

   procedure Initialize is
   begin
      State.Init;
   end Initialize;

   procedure Set_Level (Level : Severity) is
   begin
      State.Set_Level (Level);
   end Set_Level;

   function Level return Severity is (State.Get_Level);

   procedure Set_Logger_Level (Logger : String; Level : Severity) is
   begin
      State.Set_Logger_Level (Logger, Level);
   end Set_Logger_Level;

   function Effective_Level (Logger : String) return Severity is (State.Level_Of (Logger));

   procedure Set_Console (Enabled : Boolean) is
   begin
      State.Set_Console (Enabled);
   end Set_Console;

   procedure Set_Default_Logger (Name : String) is
   begin
      State.Set_Logger (Name);
   end Set_Default_Logger;

   function Default_Logger return String is (State.Logger);

   function Image (Level : Severity) return String is
     (case Level is
         when Debug => "DEBUG", when Info => "INFO", when Warn => "WARN",
         when Error => "ERROR", when Fatal => "FATAL");

   function Time_Image (Ns : Long_Long_Integer) return String is
      Sec  : constant String := Ada.Strings.Fixed.Trim
        (Long_Long_Integer'Image (Ns / 1_000_000_000), Ada.Strings.Left);
      Frac : constant String := Long_Long_Integer'Image (Ns mod 1_000_000_000 + 1_000_000_000);
   begin
      return Sec & "." & Frac (Frac'Last - 8 .. Frac'Last);
   end Time_Image;

   function Format
     (Pattern : String; Level : Severity; Logger, Message : String;
      Stamp_Ns : Long_Long_Integer) return String
   is
      Result : Unbounded_String;
      I      : Natural := Pattern'First;
   begin
      while I <= Pattern'Last loop
         if Pattern (I) = '{' then
            declare
               Close : constant Natural :=
                 Ada.Strings.Fixed.Index (Pattern (I .. Pattern'Last), "}");
               Key   : constant String :=
                 (if Close = 0 then "" else Pattern (I + 1 .. Close - 1));
            begin
               if Close = 0 then
                  Append (Result, Pattern (I .. Pattern'Last));
                  exit;
               elsif Key = "severity" then
                  Append (Result, Image (Level));
               elsif Key = "name" then
                  Append (Result, Logger);
               elsif Key = "message" then
                  Append (Result, Message);
               elsif Key = "time" then
                  Append (Result, Time_Image (Stamp_Ns));
               elsif Key = "time_as_nanoseconds" then
                  Append (Result, Ada.Strings.Fixed.Trim (Stamp_Ns'Image, Ada.Strings.Left));
               elsif Key in "file_name" | "function_name" | "line_number" then
                  null;
               else
                  Append (Result, Pattern (I .. Close));
               end if;
               I := Close + 1;
            end;
         else
            Append (Result, Pattern (I));
            I := I + 1;
         end if;
      end loop;
      return To_String (Result);
   end Format;

   procedure Log (Level : Severity; Message : String; Logger : String := "") is
      Name : constant String := (if Logger = "" then State.Logger else Logger);
   begin
      if Level < State.Level_Of (Name) then
         return;
      end if;
      State.Init;
      declare
         Stamp : constant Long_Long_Integer := Long_Long_Integer (RCL.DDS.Now);
         Hook  : constant Sink := State.Hook;
      begin
         State.Emit (Format (State.Pattern, Level, Name, Message, Stamp), Level);
         if Hook /= null then
            begin
               Hook (Level, Name, Message, Stamp);
            exception
               when others =>
                  null;
            end;
         end if;
      end;
   end Log;

   procedure Debug (Message : String; Logger : String := "") is
   begin
      Log (Debug, Message, Logger);
   end Debug;

   procedure Info (Message : String; Logger : String := "") is
   begin
      Log (Info, Message, Logger);
   end Info;

   procedure Warn (Message : String; Logger : String := "") is
   begin
      Log (Warn, Message, Logger);
   end Warn;

   procedure Error (Message : String; Logger : String := "") is
   begin
      Log (Error, Message, Logger);
   end Error;

   procedure Fatal (Message : String; Logger : String := "") is
   begin
      Log (Fatal, Message, Logger);
   end Fatal;

   procedure Set_Sink (Hook : Sink) is
   begin
      State.Set_Hook (Hook);
   end Set_Sink;

end RCL.Logging;
