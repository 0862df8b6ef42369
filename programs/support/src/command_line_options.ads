--  The options of a program's command line, as the sancta and sancta-view
--  commands read them: an option, then its value in the next argument.
--
--     Option : constant String := Ada.Command_Line.Argument (I);  --  "--rate"
--     Rate   : constant Long_Float := Number (Option, Next_Value (I));
--     --  "sancta team --rate x": Usage_Error "option --rate: "x" is not a number"
package Command_Line_Options is

   Usage_Error : exception;
   --  A bad command line; the message says what is wrong.

   function Next_Value (Index : in out Positive) return String;
   --  The value following the option at Ada.Command_Line.Argument (Index);
   --  Index then designates that value. Usage_Error "option X needs a value"
   --  when the command line ends there.

   function Number (Option, Text : String) return Long_Float;
   --  Text, the value of Option, as a number; Usage_Error
   --  "option OPTION: "TEXT" is not a number" otherwise.

end Command_Line_Options;
