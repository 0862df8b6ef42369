--  A small logging facility: messages with a section name (the component or
--  subsystem that speaks) and a level, printed on the console (standard
--  error) and optionally appended to a file. Each section may have its own
--  threshold; the default threshold applies to the rest.
--
--     Sancta.Logging.Log ("scheduler", Sancta.Logging.Warning,
--                         "cannot keep up: 12 ms late");
--     --  prints "12.345 WARN  [scheduler] cannot keep up: 12 ms late"
--
--  Task-safe: one protected object serialises the output. The ROS 2 layer
--  has its own RCL.Logging; a bridge may forward one to the other later.
package Sancta.Logging is

   type Level is (Debug, Info, Warning, Error);

   procedure Log (Section : String; Severity : Level; Message : String);
   --  Print Message when Severity reaches the section's threshold.

   procedure Set_Default_Level (Threshold : Level);
   --  The threshold of sections without one of their own (Info at start).

   procedure Set_Level (Section : String; Threshold : Level);
   --  A threshold for one section.

   function Enabled (Section : String; Severity : Level) return Boolean;
   --  Whether Log (Section, Severity, ...) would print: lets callers skip
   --  building expensive messages.

   procedure Set_Console (On : Boolean);
   --  Console output on or off (on at start).

   procedure Open_File (Name : String);
   --  Also append every printed message to the file Name (created if needed).
   --  Raises Ada.IO_Exceptions.Name_Error / Use_Error when it cannot.

   procedure Close_File;

   type Counts is array (Level) of Natural;

   function Printed return Counts;
   --  How many messages of each level were printed so far (for tests and
   --  the exit status of commands).

   function Last_Message return String;
   --  The text of the last message printed, "" if none (for tests).

   procedure Reset_Counts;

end Sancta.Logging;
