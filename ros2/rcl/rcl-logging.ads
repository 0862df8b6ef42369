--  ROS 2 style logging: severities, a console format like rcutils'
--  ("[INFO] [1700000000.123456789] [talker]: Hello"), honouring
--  RCUTILS_CONSOLE_OUTPUT_FORMAT ({severity}, {time}, {time_as_nanoseconds},
--  {name}, {message}; {file_name}, {function_name}, {line_number} print
--  empty), and a hook through which RCL republishes records on /rosout.
--  Example:
--     Logging.Info ("Got chatter");              --  logger of the last node
--     Logging.Warn ("low battery", Logger => "robot1.power");
package RCL.Logging is

   type Severity is (Debug, Info, Warn, Error, Fatal);

   function ROS_Level (Level : Severity) return Natural is
     (case Level is
         when Debug => 10, when Info => 20, when Warn => 30,
         when Error => 40, when Fatal => 50);
   --  rcl_interfaces/msg/Log levels.

   procedure Initialize;
   --  Reads RCUTILS_CONSOLE_OUTPUT_FORMAT; called implicitly by the first log.

   procedure Set_Level (Level : Severity);
   --  Messages below Level are dropped (default Info).

   function Level return Severity;

   procedure Set_Logger_Level (Logger : String; Level : Severity);
   --  The level of Logger and of its descendants ("robot1" covers
   --  "robot1.talker"), overriding Set_Level for them; the most specific
   --  setting wins (--ros-args --log-level robot1.talker:=debug).

   function Effective_Level (Logger : String) return Severity;
   --  The level that applies to Logger.

   procedure Set_Console (Enabled : Boolean);
   --  Console output on (default) or off (--disable-stdout-logs); /rosout
   --  still gets the records.

   procedure Set_Default_Logger (Name : String);
   --  The logger name used when none is given (RCL sets it to the name of
   --  the first node created in the process).

   function Default_Logger return String;

   procedure Log (Level : Severity; Message : String; Logger : String := "");

   procedure Debug (Message : String; Logger : String := "");
   procedure Info (Message : String; Logger : String := "");
   procedure Warn (Message : String; Logger : String := "");
   procedure Error (Message : String; Logger : String := "");
   procedure Fatal (Message : String; Logger : String := "");

   function Format
     (Pattern : String; Level : Severity; Logger, Message : String;
      Stamp_Ns : Long_Long_Integer) return String;
   --  Expands a RCUTILS_CONSOLE_OUTPUT_FORMAT pattern (exposed for tests).

   type Sink is access procedure
     (Level : Severity; Logger, Message : String; Stamp_Ns : Long_Long_Integer);
   procedure Set_Sink (Hook : Sink);
   --  Called for each record that passes the level (used for /rosout);
   --  exceptions in the sink are swallowed.

end RCL.Logging;
