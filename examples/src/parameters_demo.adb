--  A node with parameters, settable from ROS 2 tools (ros2 param / rclada
--  param) and from the command line:
--     parameters_demo [--ros-args -p rate:=20 --params-file FILE]
--  "rate" (integer, 1 .. 100), "name" (string), "gain" (double), "ids"
--  (integer array), "frozen" (read-only boolean). Every change is logged as
--  "parameter <name> = <value>".
with Ada.Strings.Unbounded;
with Example_Support; use Example_Support;
with RCL.Arguments;
with RCL.Logging;
with RCL.Nodes;
with RCL.Parameters;
with RCL.Timers;
with RCL.YAML;

procedure Parameters_Demo is

   use Ada.Strings.Unbounded;
   use RCL;
   use RCL.Parameters;

   function Check (Name : String; New_Value : Value) return String is
   begin
      if Name = "rate" and then New_Value.Int not in 1 .. 100 then
         return "rate must be within 1 .. 100 (got" & New_Value.Int'Image & ")";
      end if;
      return "";
   end Check;

begin
   RCL.Arguments.Load;
   --  A bad --ros-args is reported below, not raised while declaring Node.
   declare
      Node : Nodes.Node := Nodes.Init ("parameters_demo");
      Last : array (1 .. 4) of Unbounded_String;
      Watched : constant array (1 .. 4) of Unbounded_String :=
        [To_Unbounded_String ("rate"), To_Unbounded_String ("name"),
         To_Unbounded_String ("gain"), To_Unbounded_String ("ids")];

      procedure Watch
        (Node    : in out Nodes.Node'Class;
         Timer   : in out Timers.Timer;
         Elapsed : Duration)
      is
         pragma Unreferenced (Timer, Elapsed);
      begin
         for I in Watched'Range loop
            declare
               Now : constant String := Image (Get (Node, To_String (Watched (I))));
            begin
               if Now /= To_String (Last (I)) then
                  Last (I) := To_Unbounded_String (Now);
                  Logging.Info ("parameter " & To_String (Watched (I)) & " = " & Now);
               end if;
            end;
         end loop;
      end Watch;

   begin
      On_Set (Node, Check'Access);
      --  First: command-line overrides are checked too.
      Declare_Parameter (Node, "rate", To_Value (Long_Long_Integer'(10)), "publish rate (Hz)");
      Declare_Parameter (Node, "name", To_Value ("demo"), "a display name");
      Declare_Parameter (Node, "gain", To_Value (Long_Float'(1.5)));
      Declare_Parameter (Node, "ids", Parse ("[1, 2, 3]"));
      Declare_Parameter (Node, "frozen", To_Value (True), Read_Only => True);
      Serve (Node);
      Node.Timer_Add (0.05, Watch'Access);
      Logging.Info ("parameters ready");
      Node.Spin;
   end;
exception
   when E : Parameter_Error | RCL.YAML.Parse_Error | RCL.Arguments.Argument_Error =>
      Fail (E);
end Parameters_Demo;
