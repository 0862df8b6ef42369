--  Component "logger": writes its inputs (any data names, any types) to a
--  CSV or JSON-lines file.
--
--     <component name="logger" file="pose.csv" format="csv" period="0.1">
--       <requires data="pose" as="corrected_pose"/>
--     </component>
--
--  Options: file (required), format (csv | jsonl; default csv), period
--  (seconds; 0, the default, writes one line on each update of an input;
--  otherwise one line per period with the current value of every input).
--  On update: CSV "time,key,value"; JSONL {"time":..,"key":..,"value":..}.
--  Periodic: CSV "time,<data1>,<data2>,..."; JSONL {"time":..,"<data>":..}.
--  Time is seconds since the logger started.
package Sancta.Standard_Components.Logger is
   pragma Elaborate_Body;
end Sancta.Standard_Components.Logger;
